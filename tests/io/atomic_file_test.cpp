#include <gtest/gtest.h>

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

TEST(AtomicFile, FailureLeavesOldFileIntact) {
  const auto dir = makeTempDir("atomic_test2");
  std::filesystem::remove_all(dir);
  motostab::io::writeFileAtomically(dir / "a.txt", "old");
  // A folder in the way of the target makes the rename fail.
  std::filesystem::create_directories(dir / "b.txt" / "x");
  EXPECT_THROW(motostab::io::writeFileAtomically(dir / "b.txt", "new"), std::runtime_error);
  std::ifstream in(dir / "a.txt");
  std::string s;
  in >> s;
  EXPECT_EQ(s, "old");
}
