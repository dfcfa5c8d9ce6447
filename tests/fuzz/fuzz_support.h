#pragma once
// Helpers of the libFuzzer targets (tests/fuzz/fuzz_*.cpp): a scratch folder per process, inputs
// that hold several files, and the one accepted answer to bad input, an InputError.
//
// Multi-file inputs use the `head` layout: a line "==> NAME <==" starts a file NAME (letters,
// digits, '_', '.', '-'; at most 40 characters; no folders) and the lines up to the next such line
// are its content. Bytes before the first header are ignored.
#include <unistd.h>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "io/input_error.h"

namespace motostab::fuzz {

/// An empty folder private to this process (on tmpfs when /dev/shm exists), emptied on each call.
inline std::filesystem::path resetScratchDir() {
  namespace fs = std::filesystem;
  static const fs::path dir = [] {
    const fs::path base = fs::exists("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    return base / ("motostab_fuzz_" + std::to_string(::getpid()));
  }();
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  return dir;
}

/// Writes `content` to `dir/name` and returns the path.
inline std::filesystem::path writeScratchFile(const std::filesystem::path& dir, const std::string& name,
                                              const std::string& content) {
  const auto path = dir / name;
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

/// True for a file name the multi-file layout accepts (see the header comment).
inline bool isPlainFileName(const std::string& name) {
  if (name.empty() || name.size() > 40 || name == "." || name == "..") return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-')) return false;
  return true;
}

/// Splits a multi-file input into (name, content) pairs; a header with a bad name starts no file
/// and its lines belong to the file before it.
inline std::vector<std::pair<std::string, std::string>> splitFiles(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::pair<std::string, std::string>> files;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    end = end == std::string::npos ? text.size() : end + 1;
    const std::string line = text.substr(pos, end - pos);
    const size_t close = line.find(" <==");
    const std::string name = line.rfind("==> ", 0) == 0 && close != std::string::npos ? line.substr(4, close - 4) : "";
    if (isPlainFileName(name))
      files.emplace_back(name, "");
    else if (!files.empty())
      files.back().second += line;
    pos = end;
  }
  return files;
}

/// Runs `read`: returning or throwing InputError is correct; any other exception is a finding
/// (printed, then abort so libFuzzer keeps the input).
template <class F>
void expectInputErrorOnly(F&& read) {
  try {
    read();
  } catch (const motostab::io::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz finding: exception other than InputError: %s\n", e.what());
    std::abort();
  }
}

}  // namespace motostab::fuzz
