#pragma once
// The whole text of a file in tests ("" if it cannot be read).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

inline std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}
