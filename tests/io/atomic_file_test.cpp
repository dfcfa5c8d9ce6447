#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <csignal>
#include <vector>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/temp_dir.h"
#include "io/atomic_file.h"

TEST(AtomicFile, WritesWholeContentAndLeavesNoTemporary) {
  const auto dir = makeTempDir("atomic_test");
  std::filesystem::remove_all(dir);
  motostab::io::writeFileAtomically(dir / "a.txt", "hello\n");
  std::ifstream in(dir / "a.txt");
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(), "hello\n");
  int files = 0;
  for (auto& e : std::filesystem::directory_iterator(dir)) (void)e, ++files;
  EXPECT_EQ(files, 1);
}

namespace {

std::string readAll(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> listFolder(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

// A target that exists keeps its old content when the new content cannot be written in full: the
// file-size limit (RLIMIT_FSIZE, which binds root too) makes the write fail half-way.
TEST(AtomicFile, FailedWriteLeavesOldTargetAndNoTemporary) {
  const auto dir = makeTempDir("atomic_test2");
  motostab::io::writeFileAtomically(dir / "b.txt", "old");
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
  void (*savedHandler)(int) = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = saved;
  small.rlim_cur = 64;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  bool threw = false;
  try {
    motostab::io::writeFileAtomically(dir / "b.txt", std::string(4096, 'n'));
  } catch (const std::runtime_error& e) {
    threw = std::string(e.what()).find("b.txt") != std::string::npos;
  }
  setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, savedHandler);
  EXPECT_TRUE(threw);
  EXPECT_EQ(readAll(dir / "b.txt"), "old");
  EXPECT_EQ(listFolder(dir), std::vector<std::string>{"b.txt"});
}

// A folder in the way of the target makes the rename fail: an error, and no temporary left behind.
TEST(AtomicFile, FailedRenameLeavesNoTemporary) {
  const auto dir = makeTempDir("atomic_test3");
  std::filesystem::create_directories(dir / "b.txt" / "x");
  EXPECT_THROW(motostab::io::writeFileAtomically(dir / "b.txt", "new"), std::runtime_error);
  EXPECT_EQ(listFolder(dir), std::vector<std::string>{"b.txt"});
  EXPECT_TRUE(std::filesystem::is_directory(dir / "b.txt" / "x"));
}

// A check of the complete temporary that fails (an import whose scenario does not load) leaves the old
// file and no temporary; one that passes sees the whole content before the rename.
TEST(AtomicFile, FailedCheckLeavesOldTarget) {
  const auto dir = makeTempDir("atomic_check");
  motostab::io::writeFileAtomically(dir / "s.yaml", "old");
  EXPECT_THROW(motostab::io::writeFileAtomically(dir / "s.yaml", "bad",
                                                 [](const std::filesystem::path&) { throw std::runtime_error("no"); }),
               std::runtime_error);
  EXPECT_EQ(readAll(dir / "s.yaml"), "old");
  EXPECT_EQ(listFolder(dir), std::vector<std::string>{"s.yaml"});
  std::string seen;
  motostab::io::writeFileAtomically(dir / "s.yaml", "new", [&](const std::filesystem::path& t) { seen = readAll(t); });
  EXPECT_EQ(seen, "new");
  EXPECT_EQ(readAll(dir / "s.yaml"), "new");
}

// Temporaries of killed writers (their process id no longer runs: 999999999 is above any Linux pid_max)
// are removed by the next write of the same file; a running writer's, another file's, and names outside
// the scheme are kept.
TEST(AtomicFile, TemporariesOfKilledWritersAreRemoved) {
  const auto dir = makeTempDir("atomic_leftovers");
  const std::string alive = ".a.txt.tmp-" + std::to_string(getppid()) + "-5";
  const std::vector<std::string> kept{alive, ".b.txt.tmp-999999999-1", ".a.txt.tmp-999999999-x", ".a.txt.tmp-notes",
                                      "a.txt.tmp-999999999-1"};
  for (const auto& name : kept) std::ofstream(dir / name) << "keep";
  std::ofstream(dir / ".a.txt.tmp-999999999-123") << "half";
  std::ofstream(dir / ".a.txt.tmp-999999998-7") << "half";
  motostab::io::writeFileAtomically(dir / "a.txt", "whole");
  std::vector<std::string> expected = kept;
  expected.push_back("a.txt");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(listFolder(dir), expected);
}
