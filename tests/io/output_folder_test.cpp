// Whole-run outputs (io/output_folder.h): the target holds the complete old or the complete new
// outputs, never a mix.
#include <gtest/gtest.h>

#include "tests/support/text_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <vector>

#include "tests/support/temp_dir.h"
#include "io/input_error.h"
#include "io/input_file.h"
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

// A folder as an earlier run left it: its outputs and the marker.
void makeEarlierOutputs(const fs::path& folder) {
  fs::create_directories(folder);
  std::ofstream(folder / kOutputMarker) << "written by motostab";
}

// The outputs a run wrote: `names` and the marker.
std::set<std::string> withMarker(std::set<std::string> names) {
  names.insert(kOutputMarker);
  return names;
}

TEST(OutputFolder, CommitReplacesTheOldFolderAsAWhole) {
  const fs::path dir = freshDir("commit");
  const fs::path target = dir / "out";
  makeEarlierOutputs(target);
  fs::create_directories(target / "sub");
  std::ofstream(target / "old.txt") << "old";
  std::ofstream(target / "sub" / "old.csv") << "1";
  {
    OutputFolder out(target);
    EXPECT_NE(out.getPath(), target);
    EXPECT_EQ(out.getPath().parent_path(), target.parent_path());  // a sibling: the rename stays on one file system
    EXPECT_EQ(listNames(out.getPath()), withMarker({}));
    std::ofstream(out.getPath() / "new.txt") << "new";
    EXPECT_EQ(readText(target / "old.txt"), "old");  // untouched before commit
    out.commit();
  }
  EXPECT_EQ(listNames(target), withMarker({"new.txt"}));
  EXPECT_EQ(readText(target / "new.txt"), "new");
  EXPECT_EQ(listNames(dir), std::set<std::string>{"out"});  // no temporary or backup left
}

TEST(OutputFolder, FailedRunLeavesTheOldOutputs) {
  const fs::path dir = freshDir("fail");
  const fs::path target = dir / "out";
  makeEarlierOutputs(target);
  std::ofstream(target / "old.txt") << "old";
  try {
    OutputFolder out(target);
    std::ofstream(out.getPath() / "half.txt") << "partial";
    throw std::runtime_error("computation failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(listNames(target), withMarker({"old.txt"}));
  EXPECT_EQ(listNames(dir), std::set<std::string>{"out"});
}

TEST(OutputFolder, NewTargetAndNestedParents) {
  const fs::path dir = freshDir("new");
  const fs::path target = dir / "a" / "b" / "out";
  OutputFolder out(target);
  std::ofstream(out.getPath() / "x.txt") << "x";
  out.commit();
  EXPECT_EQ(listNames(target), withMarker({"x.txt"}));
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

// A folder name near the file systems' limit of 255 bytes (lengths drawn, seeded): its temporary sibling
// ".NAME.partial-PID" would exceed it (creating it failed, exit 1): the sibling is shortened, the run
// commits, and a killed run's leftover of the same name is cleaned up by the next run.
TEST(OutputFolder, LongNamesGetSiblingsWithinTheLimit) {
  const fs::path dir = freshDir("long");
  std::mt19937 rng(245);
  for (int i = 0; i < 4; ++i) {
    const size_t length = std::uniform_int_distribution<size_t>(230, 255)(rng);
    const std::string name = (i % 2 ? std::string("\xc3\xa9") : std::string()) + std::string(length - 2 * (i % 2), 'o');
    const fs::path target = dir / name;
    fs::path leftover;
    {
      OutputFolder killed(target);  // its temporary, renamed as a dead process's would be
      const std::string t = killed.getPath().filename().string();
      leftover = dir / (t.substr(0, t.rfind('-') + 1) + "999999999");
      fs::rename(killed.getPath(), leftover);
    }
    ASSERT_TRUE(fs::exists(leftover));
    OutputFolder out(target);
    EXPECT_LE(out.getPath().filename().string().size(), 255u) << out.getPath();
    EXPECT_FALSE(fs::exists(leftover)) << "a killed run's folder is left: " << leftover;
    std::ofstream(out.getPath() / "a.txt") << "a";
    out.commit();
    EXPECT_EQ(listNames(target), withMarker({"a.txt"}));
    fs::remove_all(target);
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

// The system's refusal to create the output folder (no permission, a read-only file system) is bad
// input at --out naming the reason (it was an internal error, exit 1). /sys refuses even root.
TEST(OutputFolder, SystemRefusalsAreInputErrorsAtOut) {
  std::vector<fs::path> refused;
  if (fs::is_directory("/sys")) refused.push_back("/sys/motostab_output_test");
  const fs::path dir = freshDir("readonly");
  if (::geteuid() != 0) {  // root writes a mode-555 folder anyway
    fs::create_directories(dir / "ro");
    fs::permissions(dir / "ro", fs::perms::owner_read | fs::perms::owner_exec);
    refused.push_back(dir / "ro" / "out");
  }
  for (const fs::path& target : refused) {
    try {
      OutputFolder out(target);
      ADD_FAILURE() << "no error for " << target;
    } catch (const InputError& e) {
      EXPECT_EQ(e.getLocation().key, "--out") << e.what();
      EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
    }
  }
  if (fs::exists(dir / "ro")) fs::permissions(dir / "ro", fs::perms::owner_all, fs::perm_options::replace);
  fs::remove_all(dir);
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
  makeEarlierOutputs(dir / ".out.backup-999999998");
  std::ofstream(dir / ".out.backup-999999998" / "old.txt") << "old";
  {
    OutputFolder out(target);
    EXPECT_EQ(listNames(target), withMarker({"old.txt"}));  // restored before anything else
    std::ofstream(out.getPath() / "new.txt") << "new";
    out.commit();
  }
  EXPECT_EQ(listNames(dir), std::set<std::string>{"out"});
  EXPECT_EQ(listNames(target), withMarker({"new.txt"}));
}

// A folder motostab did not write (no marker) is the user's: never replaced, whatever it holds; an
// empty folder holds nothing to lose and is taken.
TEST(OutputFolder, AFolderWithoutTheMarkerIsRefused) {
  const fs::path dir = freshDir("foreign");
  const fs::path target = dir / "notes";
  fs::create_directories(target / "sub");
  std::ofstream(target / "notes.txt") << "mine";
  std::ofstream(target / "sub" / ".motostab-output-not") << "x";  // not the marker, and not at the top
  try {
    OutputFolder out(target);
    ADD_FAILURE() << "replaced a folder motostab did not write";
  } catch (const InputError& e) {
    EXPECT_EQ(e.getLocation().key, "--out");
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not written by motostab"), std::string::npos) << e.what();
  }
  EXPECT_EQ(readText(target / "notes.txt"), "mine");
  EXPECT_EQ(listNames(dir), std::set<std::string>{"notes"});
  fs::create_directories(dir / "empty");
  OutputFolder empty(dir / "empty");
  empty.commit();
  EXPECT_EQ(listNames(dir / "empty"), withMarker({}));
}

// The marker lists what motostab wrote: a folder holding anything else (a subfolder of notes, a file
// added inside a written subfolder) is refused naming those entries, at the start and at commit, and
// nothing is lost; without them it is replaced as before. A marker without a list (older motostab)
// still lets its folder be replaced whole.
TEST(OutputFolder, AFolderHoldingEntriesNotWrittenIsRefused) {
  const fs::path dir = freshDir("listed");
  const fs::path target = dir / "A";
  {
    OutputFolder out(target);
    fs::create_directories(out.getPath() / "plots");
    std::ofstream(out.getPath() / "summary.json") << "{}";
    std::ofstream(out.getPath() / "plots" / "x.svg") << "<svg/>";
    out.commit();
  }
  const std::string marker = readText(target / kOutputMarker);
  for (const char* entry : {"\nsummary.json\n", "\nplots\n", "\nplots/x.svg\n"})
    EXPECT_NE(marker.find(entry), std::string::npos) << marker;
  struct Case {
    fs::path file;
    std::string named;
  };
  for (const Case& c : {Case{"sub/notes.txt", "(sub)"}, Case{"plots/mine.txt", "(plots/mine.txt)"}, Case{"notes", "(notes)"}}) {
    fs::create_directories((target / c.file).parent_path());
    std::ofstream(target / c.file) << "mine";
    try {
      OutputFolder out(target);
      ADD_FAILURE() << "replaced a folder holding " << c.file;
    } catch (const InputError& e) {
      EXPECT_EQ(e.getLocation().key, "--out");
      EXPECT_NE(std::string(e.what()).find("did not write " + c.named), std::string::npos) << e.what();
    }
    fs::remove(target / c.file);
    if (c.file.parent_path() == "sub") fs::remove(target / "sub");
    OutputFolder late(target);  // accepted now; the entry added while it computes is refused at commit
    fs::create_directories((target / c.file).parent_path());
    std::ofstream(target / c.file) << "mine";
    EXPECT_THROW(late.commit(), InputError);
    EXPECT_EQ(readText(target / c.file), "mine");
    fs::remove(target / c.file);
    if (c.file.parent_path() == "sub") fs::remove(target / "sub");
  }
  {
    OutputFolder out(target);
    out.commit();
  }
  EXPECT_EQ(listNames(target), withMarker({}));
  std::ofstream(target / kOutputMarker) << "This folder was written by motostab.\n";  // an older marker
  std::ofstream(target / "notes.txt") << "x";
  OutputFolder old(target);
  old.commit();
  EXPECT_EQ(listNames(target), withMarker({}));
}

// A folder put in the target's place while the run computed is checked again at commit.
TEST(OutputFolder, TheCheckIsRepeatedAtCommit) {
  const fs::path dir = freshDir("late");
  const fs::path target = dir / "out";
  OutputFolder out(target);
  fs::create_directories(target);
  std::ofstream(target / "mine.txt") << "mine";
  EXPECT_THROW(out.commit(), InputError);
  EXPECT_EQ(listNames(target), std::set<std::string>{"mine.txt"});
}

// A folder holding a file the run read (readInputFile records it) is refused even when motostab wrote it:
// an input written into an output folder (e.g. an edited extended.yaml) would be lost.
TEST(OutputFolder, AFolderHoldingAnInputIsRefused) {
  const fs::path dir = freshDir("input");
  const fs::path target = dir / "inner";
  makeEarlierOutputs(target);
  fs::create_directories(target / "deep");
  std::ofstream(target / "deep" / "bike.yaml") << "name: bike\n";
  const fs::path sibling = dir / "inner-sweep";  // a prefix of the name is not "inside"
  readInputFile(target / "deep" / "bike.yaml");
  for (const fs::path& bad : {target, dir / "." / "inner"}) {
    try {
      OutputFolder out(bad);
      ADD_FAILURE() << "would replace an input";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("bike.yaml, an input of this run"), std::string::npos) << e.what();
    }
  }
  OutputFolder other(sibling);
  other.commit();
  EXPECT_EQ(readText(target / "deep" / "bike.yaml"), "name: bike\n");
  EXPECT_THROW(checkFileReplaceable(target / "deep" / "bike.yaml", "name"), InputError);  // a single output file too
}

TEST(OutputFolder, FolderNamesAreNamesNotPaths) {
  for (const std::string& bad : std::vector<std::string>{"", ".", "..", "a/b", "../victim", "/tmp/x", "a\nb", std::string(201, 'n')})
    EXPECT_NE(describeBadFolderName(bad), "") << bad;
  for (const std::string& good : std::vector<std::string>{"whipple-benchmark", "Browser + Jason", "..a", "a..b", "x.y", std::string(200, 'n')})
    EXPECT_EQ(describeBadFolderName(good), "") << good;
  // Code points that hide how a name reads (U+0085 next line, U+202E right-to-left override, U+2066
  // isolate, U+2028 line separator) and bytes that are not UTF-8 are refused; other scripts are names.
  for (const std::string& bad : std::vector<std::string>{"a\xc2\x85" "b", "evil\xe2\x80\xaegpj.exe", "x\xe2\x81\xa6y",
                                                         "l\xe2\x80\xa8m", "bad\xff", "cut\xc3", "\x7f"})
    EXPECT_NE(describeBadFolderName(bad), "") << bad;
  for (const std::string& good : std::vector<std::string>{"v\xc3\xa9lo", "\xe8\x87\xaa\xe8\xbb\xa2\xe8\xbb\x8a", "bike \xf0\x9f\x9a\xb2"})
    EXPECT_EQ(describeBadFolderName(good), "") << good;
}

// A single output file (import's scenario) replaces only a file whose first line is motostab's header.
TEST(OutputFolder, SingleOutputFilesReplaceOnlyTheirOwn) {
  const fs::path dir = freshDir("single");
  EXPECT_NO_THROW(checkFileReplaceable(dir / "new.yaml", "# Written by motostab"));
  std::ofstream(dir / "own.yaml") << "# Written by motostab import from x\nname: a\n";
  EXPECT_NO_THROW(checkFileReplaceable(dir / "own.yaml", "# Written by motostab"));
  std::ofstream(dir / "mine.yaml") << "name: mine\n";
  EXPECT_THROW(checkFileReplaceable(dir / "mine.yaml", "# Written by motostab"), InputError);
  fs::create_directories(dir / "folder.yaml");
  EXPECT_THROW(checkFileReplaceable(dir / "folder.yaml", "# Written by motostab"), InputError);
}

}  // namespace
}  // namespace motostab::io
