#pragma once
// Runs the motostab command line (MOTOSTAB_CLI, the built binary) and captures exit code and output.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

struct CliRun {
  int exitCode = -1;
  std::string out, err;
};

inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `args` is appended to the binary path as is (quote paths with spaces yourself).
inline CliRun runCli(const std::string& args, const std::filesystem::path& scratch) {
  const auto out = scratch / "cli_stdout.txt", err = scratch / "cli_stderr.txt";
  const std::string cmd = std::string(MOTOSTAB_CLI) + " " + args + " > '" + out.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readText(out);
  r.err = readText(err);
  return r;
}
