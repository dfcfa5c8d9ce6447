#pragma once
// A fresh, empty temporary folder per test name (emptied on every run, so runs leave one copy behind).
#include <filesystem>
#include <string>

inline std::filesystem::path makeTempDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("motostab_test_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}
