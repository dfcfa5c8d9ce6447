#pragma once
// End-to-end helpers: run the motostab binary from a test (fork + exec with arguments, stdout and
// stderr to a log file) and check that the files it writes parse. Used by tests/apps and by the
// command-line tests of other folders.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "nlohmann/json.hpp"
#include "tests/support/temp_dir.h"
#include "tests/support/text_csv.h"

namespace motostab::test {

/// Starts `motostab args...` in `dir` with stdout and stderr going to `log`; returns its pid.
inline pid_t startMotostab(const std::vector<std::string>& args, const std::string& dir, const std::string& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(127);
    FILE* f = std::fopen(log.c_str(), "w");
    if (f) dup2(fileno(f), 1), dup2(fileno(f), 2);
    std::vector<char*> argv{const_cast<char*>(MOTOSTAB_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(MOTOSTAB_BINARY, argv.data());
    _exit(127);
  }
  return pid;
}

/// Waits for `pid`; its exit code, or 128 + signal when killed.
inline int waitForExit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

inline std::string readLog(const std::string& log) {
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Runs `motostab args...` in `dir` to completion; its exit code, with stdout + stderr in `output`.
inline int runMotostab(const std::vector<std::string>& args, const std::string& dir, std::string& output) {
  const std::string log = dir + "/motostab_run.log";
  const int code = waitForExit(startMotostab(args, dir, log));
  output = readLog(log);
  return code;
}

}  // namespace motostab::test

struct CliRun {
  int exitCode = -1;   ///< exit status, or 128 + signal when killed
  std::string output;  ///< stdout and stderr
};

/// Runs `motostab args...` in `dir`, by default the source folder (relative paths as in the README's
/// examples); the log goes to a folder of its own.
inline CliRun runCli(const std::vector<std::string>& args, const std::string& dir = MOTOSTAB_SOURCE_DIR) {
  static int counter = 0;
  // One folder per process and run: ctest -j runs the tests side by side.
  const auto log = makeTempDir("cli_log_" + std::to_string(getpid()) + "_" + std::to_string(++counter)) / "log.txt";
  CliRun r;
  r.exitCode = motostab::test::waitForExit(motostab::test::startMotostab(args, dir, log.string()));
  r.output = motostab::test::readLog(log.string());
  std::filesystem::remove_all(log.parent_path());
  return r;
}

/// Every .json under `dir` parses, every .csv has a header and rows of its width; returns the count.
inline int checkOutputsParse(const std::filesystem::path& dir) {
  int n = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    if (e.path().extension() == ".json") {
      std::ifstream in(e.path());
      EXPECT_FALSE(nlohmann::json::parse(in).is_discarded());  // throws on bad JSON
      ++n;
    } else if (e.path().extension() == ".csv") {
      const TextCsv t = readTextCsv(e.path());  // throws on ragged rows
      if (t.header.empty() || t.rows.empty()) throw std::runtime_error(e.path().string() + ": empty CSV");
      ++n;
    }
  }
  return n;
}

inline nlohmann::json readJson(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

/// Expects exit status 2 (bad input) and `named` (the option, file or key) in the message; runs in `dir`
/// (default: the source folder).
inline void expectInputError(const std::vector<std::string>& args, const std::string& named,
                             const std::string& dir = MOTOSTAB_SOURCE_DIR) {
  const CliRun r = runCli(args, dir);
  std::string cmd;
  for (const auto& a : args) cmd += a + " ";
  EXPECT_EQ(r.exitCode, 2) << cmd << "\n" << r.output;
  EXPECT_NE(r.output.find(named), std::string::npos) << cmd << "\n" << r.output;
}
