#pragma once
// Runs the motostab executable (MOTOSTAB_CLI) as a user would and checks the files it writes parse.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "nlohmann/json.hpp"
#include "tests/support/temp_dir.h"
#include "tests/support/text_csv.h"

struct CliRun {
  int exitCode = -1;  ///< the exit status, or 128 + signal number when killed
  std::string out, err;
};

inline std::string readWholeFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs `motostab ARGS` (ARGS already shell-quoted where needed) in the source folder.
inline CliRun runCli(const std::string& args) {
  static int counter = 0;
  const auto dir = makeTempDir("cli_io_" + std::to_string(++counter));
  const std::string cmd = "cd '" MOTOSTAB_SOURCE_DIR "' && '" MOTOSTAB_CLI "' " + args + " >'" + (dir / "out").string() +
                          "' 2>'" + (dir / "err").string() + "'";
  const int status = std::system(cmd.c_str());
  CliRun r;
  if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.exitCode = 128 + WTERMSIG(status);
  r.out = readWholeFile(dir / "out");
  r.err = readWholeFile(dir / "err");
  return r;
}

/// Every .json under `dir` parses, every .csv has a header and rows of its width; returns the count.
inline int checkOutputsParse(const std::filesystem::path& dir) {
  int n = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    if (e.path().extension() == ".json") {
      std::ifstream in(e.path());
      nlohmann::json::parse(in);  // throws on bad JSON
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
inline void expectInputError(const std::string& args, const std::string& named) {
  const CliRun r = runCli(args);
  EXPECT_EQ(r.exitCode, 2) << args << "\nstdout: " << r.out << "\nstderr: " << r.err;
  EXPECT_NE(r.err.find(named), std::string::npos) << args << "\nstderr: " << r.err;
}
