#pragma once
// Runs the motostab binary from a test: fork + exec with arguments, output to a log file.
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

}  // namespace motostab::test
