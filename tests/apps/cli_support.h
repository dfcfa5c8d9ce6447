#pragma once
// End-to-end helpers: run motostab in the source folder (run_motostab.h) and check that the files it
// writes parse.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "nlohmann/json.hpp"
#include "tests/apps/run_motostab.h"
#include "tests/support/temp_dir.h"
#include "tests/support/text_csv.h"

struct CliRun {
  int exitCode = -1;   ///< exit status, or 128 + signal when killed
  std::string output;  ///< stdout and stderr
};

/// Runs `motostab args...` in the source folder (relative paths as in the README's examples).
inline CliRun runCli(const std::vector<std::string>& args) {
  static int counter = 0;
  // One folder per process and run: ctest -j runs the tests side by side.
  const auto log = makeTempDir("cli_log_" + std::to_string(getpid()) + "_" + std::to_string(++counter)) / "log.txt";
  CliRun r;
  r.exitCode = motostab::test::waitForExit(motostab::test::startMotostab(args, MOTOSTAB_SOURCE_DIR, log.string()));
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

/// Expects exit status 2 (bad input) and `named` (the option, file or key) in the message.
inline void expectInputError(const std::vector<std::string>& args, const std::string& named) {
  const CliRun r = runCli(args);
  std::string cmd;
  for (const auto& a : args) cmd += a + " ";
  EXPECT_EQ(r.exitCode, 2) << cmd << "\n" << r.output;
  EXPECT_NE(r.output.find(named), std::string::npos) << cmd << "\n" << r.output;
}
