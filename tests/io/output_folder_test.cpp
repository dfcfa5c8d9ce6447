// Whole-run outputs (io/output_folder.h): the target holds the complete old or the complete new
// outputs, never a mix.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "tests/support/temp_dir.h"
#include "io/input_error.h"
#include "io/output_folder.h"

namespace motostab::io {
namespace {
namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
  const fs::path d = makeTempDir("output_folder_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::set<std::string> listNames(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.insert(e.path().filename().string());
  return out;
}

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(OutputFolder, CommitReplacesTheOldFolderAsAWhole) {
  const fs::path dir = freshDir("commit");
  const fs::path target = dir / "out";
  fs::create_directories(target / "sub");
  std::ofstream(target / "old.txt") << "old";
  std::ofstream(target / "sub" / "old.csv") << "1";
  {
    OutputFolder out(target);
    EXPECT_NE(out.getPath(), target);
    EXPECT_EQ(out.getPath().parent_path(), target.parent_path());  // a sibling: the rename stays on one file system
    EXPECT_TRUE(listNames(out.getPath()).empty());
    std::ofstream(out.getPath() / "new.txt") << "new";
    EXPECT_EQ(readText(target / "old.txt"), "old");  // untouched before commit
    out.commit();
  }
  EXPECT_EQ(listNames(target), std::set<std::string>{"new.txt"});
  EXPECT_EQ(readText(target / "new.txt"), "new");
  EXPECT_EQ(listNames(dir), std::set<std::string>{"out"});  // no temporary or backup left
}

TEST(OutputFolder, FailedRunLeavesTheOldOutputs) {
  const fs::path dir = freshDir("fail");
  const fs::path target = dir / "out";
  fs::create_directories(target);
  std::ofstream(target / "old.txt") << "old";
  try {
    OutputFolder out(target);
    std::ofstream(out.getPath() / "half.txt") << "partial";
    throw std::runtime_error("computation failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(listNames(target), std::set<std::string>{"old.txt"});
  EXPECT_EQ(listNames(dir), std::set<std::string>{"out"});
}

TEST(OutputFolder, NewTargetAndNestedParents) {
  const fs::path dir = freshDir("new");
  const fs::path target = dir / "a" / "b" / "out";
  OutputFolder out(target);
  std::ofstream(out.getPath() / "x.txt") << "x";
  out.commit();
  EXPECT_EQ(listNames(target), std::set<std::string>{"x.txt"});
}

TEST(OutputFolder, TargetThatIsAFileIsAnInputError) {
  const fs::path dir = freshDir("file");
  std::ofstream(dir / "out") << "not a folder";
  EXPECT_THROW(OutputFolder out(dir / "out"), InputError);
}

// Names the file system rejects (a 300-character component; a parent that is a file) are input
// errors naming --out, not file-system exceptions (found by fuzz_measured_data for data files).
TEST(OutputFolder, NamesTheFileSystemRejectsAreInputErrors) {
  const fs::path dir = freshDir("rejected");
  for (const fs::path& bad : {dir / std::string(300, 'x'), dir / std::string(300, 'y') / "out"}) {
    try {
      OutputFolder out(bad);
      ADD_FAILURE() << "no error for " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.getLocation().key, "--out") << e.what();
    }
  }
  std::ofstream(dir / "file") << "x";
  EXPECT_THROW(OutputFolder out(dir / "file" / "out"), InputError);
  EXPECT_EQ(listNames(dir), std::set<std::string>{"file"});
}

// "--out ." (or "..", "x/..", or any folder that holds the working folder) would have the run replace
// the folder it works in: refused at once, before any computing, and nothing is created.
TEST(OutputFolder, TheWorkingFolderOrOneHoldingItIsRefused) {
  const fs::path dir = freshDir("here");
  fs::create_directories(dir / "work");
  const fs::path saved = fs::current_path();
  fs::current_path(dir / "work");
  for (const fs::path& bad : {fs::path("."), fs::path(".."), fs::path("x/.."), fs::path("./"), dir, dir / "work"}) {
    try {
      OutputFolder out(bad);
      ADD_FAILURE() << "no error for " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.getLocation().key, "--out") << e.what();
    }
  }
  fs::current_path(saved);
  EXPECT_EQ(listNames(dir), std::set<std::string>{"work"});
  EXPECT_TRUE(fs::is_empty(dir / "work"));
}

TEST(OutputFolder, LeftoversOfKilledRunsAreCleanedUp) {
  const fs::path dir = freshDir("stale");
  const fs::path target = dir / "out";
  // A run killed mid-write (pid 999999999 is above any Linux pid_max, so never alive) ...
  fs::create_directories(dir / ".out.partial-999999999");
  std::ofstream(dir / ".out.partial-999999999" / "half.txt") << "partial";
  // ... and one killed between the fallback's two renames: only its backup holds the outputs.
  fs::create_directories(dir / ".out.backup-999999998");
  std::ofstream(dir / ".out.backup-999999998" / "old.txt") << "old";
  {
    OutputFolder out(target);
    EXPECT_EQ(listNames(target), std::set<std::string>{"old.txt"});  // restored before anything else
    std::ofstream(out.getPath() / "new.txt") << "new";
    out.commit();
  }
  EXPECT_EQ(listNames(dir), std::set<std::string>{"out"});
  EXPECT_EQ(listNames(target), std::set<std::string>{"new.txt"});
}

}  // namespace
}  // namespace motostab::io
