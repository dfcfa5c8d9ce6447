// Whole-run outputs: a sweep killed while it writes leaves the output folder with the
// complete old outputs or the complete new ones, and the next run cleans up after it.
#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include "io/output_folder.h"
#include "tests/support/temp_dir.h"
#include "tests/apps/cli_support.h"

namespace motostab::cli {
namespace {
namespace fs = std::filesystem;

const std::string kWhipple = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

std::set<std::string> listNames(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename() != motostab::io::kOutputMarker) out.insert(e.path().filename().string());
  return out;
}

void writeOldOutputs(const fs::path& target) {
  fs::remove_all(target);
  fs::create_directories(target);
  std::ofstream(target / "eigenvalues.csv") << "old\n";
  std::ofstream(target / "old_marker.txt") << "old\n";
  std::ofstream(target / motostab::io::kOutputMarker) << "motostab\n";  // an earlier run's outputs
}

// The first file in a temporary output folder of `pid`, polled every 0.2 ms; false if it exits first.
bool waitForFirstOutputFile(const fs::path& dir, pid_t pid) {
  const fs::path partial = dir / (".out.partial-" + std::to_string(pid));
  for (int i = 0; i < 300000; ++i) {
    std::error_code ec;
    if (fs::exists(partial, ec) && !fs::is_empty(partial, ec)) return true;
    if (waitpid(pid, nullptr, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return false;
}

TEST(WholeRunOutputs, KilledSweepLeavesCompleteOldOrNewOutputs) {
  const fs::path dir = makeTempDir("killed_run");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path target = dir / "out";
  const std::vector<std::string> args{"sweep", kWhipple, "--speeds", "0:10:0.5", "--out", "out"};
  const std::string log = (dir / "log.txt").string();
  // The complete new outputs, from an uninterrupted run (a serial sweep is bit-reproducible).
  ASSERT_EQ(test::waitForExit(test::startMotostab(args, dir.string(), log)), 0) << test::readLog(log);
  const std::set<std::string> newNames = listNames(target);
  const std::string newEigenvalues = test::readLog((target / "eigenvalues.csv").string());
  ASSERT_GT(newNames.size(), 2u);

  int killedMidWrite = 0;
  for (int trial = 0; trial < 4; ++trial) {
    writeOldOutputs(target);
    const pid_t pid = test::startMotostab(args, dir.string(), log);
    const bool writing = waitForFirstOutputFile(dir, pid);
    if (writing) kill(pid, SIGKILL);
    const int code = test::waitForExit(pid);
    killedMidWrite += writing && code == 128 + SIGKILL;
    const std::set<std::string> names = listNames(target);
    if (names.count("old_marker.txt")) {
      EXPECT_EQ(names, (std::set<std::string>{"eigenvalues.csv", "old_marker.txt"})) << trial;
      EXPECT_EQ(test::readLog((target / "eigenvalues.csv").string()), "old\n") << trial;
    } else {
      EXPECT_EQ(names, newNames) << trial;
      EXPECT_EQ(test::readLog((target / "eigenvalues.csv").string()), newEigenvalues) << trial;
    }
  }
  EXPECT_GE(killedMidWrite, 1) << "no run was killed while writing: the test proved nothing";

  // The next run replaces the old outputs and removes what the killed runs left.
  writeOldOutputs(target);
  ASSERT_EQ(test::waitForExit(test::startMotostab(args, dir.string(), log)), 0) << test::readLog(log);
  EXPECT_EQ(listNames(target), newNames);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // orphaned gnuplot children of killed runs
  for (const auto& name : listNames(dir)) EXPECT_TRUE(name == "out" || name == "log.txt") << name;
}

TEST(WholeRunOutputs, FailedRunKeepsOldOutputs) {
  const fs::path dir = makeTempDir("failed_run");
  fs::remove_all(dir);
  fs::create_directories(dir);
  writeOldOutputs(dir / "out");
  // No hands-free turn between 1 and 1.5 m/s at 20 deg (the Whipple bicycle's are above 2 m/s): a
  // computation without a result (exit 3) after the output folder exists.
  const std::string log = (dir / "log.txt").string();
  const int code = test::waitForExit(test::startMotostab(
      {"trim", kWhipple, "--hands-free", "--roll-deg", "20", "--speeds", "1:1.5:0.25", "--out", "out"}, dir.string(), log));
  ASSERT_EQ(code, 3) << test::readLog(log);
  EXPECT_EQ(listNames(dir / "out"), (std::set<std::string>{"eigenvalues.csv", "old_marker.txt"}));
  for (const auto& name : listNames(dir)) EXPECT_TRUE(name == "out" || name == "log.txt") << name;
}

}  // namespace
}  // namespace motostab::cli
