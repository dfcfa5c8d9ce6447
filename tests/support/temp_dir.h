#pragma once
// A fresh, empty temporary folder per test name and process: runs of one test in two build folders
// (or two ctest jobs) never share it. The folders are removed when the process exits, unless the
// environment sets MOTOSTAB_KEEP_TEST_DIRS (to inspect a failure).
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace motostab::test_support {

inline std::vector<std::filesystem::path>& getTempDirs() {
  static std::vector<std::filesystem::path> dirs;
  return dirs;
}

inline void removeTempDirs() {
  if (std::getenv("MOTOSTAB_KEEP_TEST_DIRS")) return;
  std::error_code ignored;
  for (const auto& d : getTempDirs()) std::filesystem::remove_all(d, ignored);
}

}  // namespace motostab::test_support

inline std::filesystem::path makeTempDir(const std::string& name) {
  static std::mutex mutex;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& dirs = motostab::test_support::getTempDirs();
  if (dirs.empty()) std::atexit(motostab::test_support::removeTempDirs);
  const auto dir = std::filesystem::temp_directory_path() /
                   ("motostab_test_" + name + "_" + std::to_string(getpid()) + "_" + std::to_string(dirs.size()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  dirs.push_back(dir);
  return dir;
}
