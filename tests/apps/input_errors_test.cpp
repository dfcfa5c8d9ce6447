// Every input error exits with code 2 and names what was wrong: CLI11's own parse and
// validation errors, non-finite or out-of-range numbers, bad --set overrides, bad scenario files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "tests/support/temp_dir.h"
#include "tests/apps/cli_support.h"

namespace motostab::cli {
namespace {

const std::string kWhipple = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

// The runs' folder: relative --out paths of a run that wrongly succeeded land there.
const std::string& getRunDir() {
  static const std::string dir = makeTempDir("cli_errors_runs").string();
  return dir;
}

// Exit code 2 with `needle` in the message.
void expectInputError(const std::vector<std::string>& args, const std::string& needle) {
  ::expectInputError(args, needle, getRunDir());
}

TEST(CliInput, SpeedsMustBeFinite) {
  expectInputError({"sweep", kWhipple, "--speeds", "nan:10:0.1"}, "--speeds");  // once a segfault
  expectInputError({"sweep", kWhipple, "--speeds", "0:inf:0.1"}, "--speeds");
  expectInputError({"sweep", kWhipple, "--speeds", "0:10:0"}, "--speeds");
  expectInputError({"sweep", kWhipple, "--speeds", "5:1:0.1"}, "--speeds");
  expectInputError({"sweep", kWhipple, "--speeds", "0:1e9:1e-9"}, "speeds above 150 m/s");
  expectInputError({"sweep", kWhipple, "--speeds", "1e11:1e11:1"}, "speeds above 150 m/s");  // accepted, exit 0
  expectInputError({"sweep", kWhipple, "--speeds", "0:100:0.01"}, "gives 10001 speeds; at most 10000");
  expectInputError({"linearize", kWhipple, "--speed", "151"}, "--speed");
  expectInputError({"study", kWhipple, "--speeds", "0:10"}, "--speeds");
}

TEST(CliInput, ThreadsBetween1And256) {
  expectInputError({"sweep", kWhipple, "--threads", "0"}, "--threads");
  expectInputError({"sweep", kWhipple, "--threads", "257"}, "--threads");
  expectInputError({"sweep", kWhipple, "--threads", "two"}, "--threads");
  expectInputError({"study", kWhipple, "--threads", "0"}, "--threads");
}

TEST(CliInput, NumbersMustBeFiniteAndInRange) {
  expectInputError({"linearize", kWhipple, "--speed", "nan", "--out", "x"}, "--speed");
  expectInputError({"linearize", kWhipple, "--speed", "-1", "--out", "x"}, "--speed");
  expectInputError({"simulate", kWhipple, "--speed", "5", "--duration", "inf"}, "--duration");
  expectInputError({"simulate", kWhipple, "--speed", "5", "--duration", "1", "--accuracy", "0"}, "--accuracy");
  expectInputError({"simulate", kWhipple, "--speed", "5", "--duration", "1", "--output-step", "-0.1"}, "--output-step");
  expectInputError({"simulate", kWhipple, "--speed", "5", "--duration", "1", "--perturb", "roll-rate:nan"}, "--perturb");
  expectInputError({"study", kWhipple, "--stiffness-scale", "0"}, "--stiffness-scale");
  expectInputError({"study", kWhipple, "--shape-speeds", "10,nan"}, "--shape-speeds");
  expectInputError({"study", std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml", "--speeds", "4:20:4",
                    "--shape-speeds", "30"},
                   "--shape-speeds");  // outside the swept speeds
  expectInputError({"identify", "virtual-rig", "--out", "x", "--noise-factor", "inf"}, "--noise-factor");
}

TEST(CliInput, ParseErrorsExit2NotCli11Codes) {
  expectInputError({"sweep", kWhipple, "--no-such-option"}, "--no-such-option");
  expectInputError({"sweep"}, "scenario");                           // missing positional
  expectInputError({"sweep", "/nonexistent/scenario.yaml"}, "scenario");  // ExistingFile check
  expectInputError({"no-such-command"}, "subcommand");
  expectInputError({"linearize", kWhipple, "--out", "x"}, "--speed");  // required option
  EXPECT_EQ(runCli({"--help"}, getRunDir()).exitCode, 0);
}

TEST(CliInput, BadSetNamesTheOverride) {
  expectInputError({"check", kWhipple, "--set", "geometry.trail_m=abc"}, "--set geometry.trail_m=abc");
  expectInputError({"check", kWhipple, "--set", "geometry.trail_m=.nan"}, "--set geometry.trail_m=.nan");
  expectInputError({"check", kWhipple, "--set", "geometry.trail_m=[1,"}, "geometry.trail_m=[1,");
  expectInputError({"check", kWhipple, "--set", "geometry.trail_m.x=1"}, "--set");
  expectInputError({"check", kWhipple, "--set", "noequals"}, "KEY.PATH=VALUE");
  // Read by the contact plugin while the model is built, not by the scenario loader.
  const std::string enduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";
  expectInputError({"check", enduro, "--set", "contact.front.relaxation_length_m=-1"},
                   "contact.front.relaxation_length_m: must not be negative (got -1.000000) (value from --set "
                   "contact.front.relaxation_length_m=-1)");
  expectInputError({"check", kWhipple, "--set", "geometry={wheelbase_m: 1, wheelbase_m: 2}"}, "duplicate key");
}

// A mistyped key of a declared section: the error says which declared key was meant, or lists them.
TEST(CliInput, UnknownKeyNamesTheDeclaredOnes) {
  const std::string enduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";
  expectInputError({"check", kWhipple, "--set", "geometry.trial_m=0.08"}, "unknown key (value from --set geometry.trial_m=0.08) (did you mean `trail_m`?)");
  expectInputError({"check", enduro, "--set", "swingarm.bending.stifness_Nm_per_rad=1"}, "(did you mean `stiffness_Nm_per_rad`?)");
  // A contact model's keys depend on the model the file selects: no guess there.
  const auto contact = runCli({"check", enduro, "--set", "contact.front.cornering_stifness_per_rad=1"}, getRunDir());
  EXPECT_EQ(contact.exitCode, 2);
  EXPECT_EQ(contact.output.find("did you mean"), std::string::npos) << contact.output;
  expectInputError({"check", kWhipple, "--set", "speeds_mps={start: 0, stop: 5, step: 1, extra: 2}"},
                   "(`speeds_mps` declares: start, stop, step)");
  // A bad value of a declared key is no unknown key: no list of keys.
  const auto value = runCli({"check", kWhipple, "--set", "speeds_mps={start: 0, stop: 5, step: abc}"}, getRunDir());
  EXPECT_EQ(value.exitCode, 2);
  EXPECT_NE(value.output.find("speeds_mps.step"), std::string::npos) << value.output;
  EXPECT_EQ(value.output.find("declares"), std::string::npos) << value.output;
}

TEST(CliInput, BadScenarioFiles) {
  const auto dir = makeTempDir("cli_errors");
  std::filesystem::create_directories(dir);
  const auto dup = (dir / "dup.yaml").string();
  std::ofstream(dup) << "name: a\ngravity_mps2: 9.81\nname: b\n";
  expectInputError({"check", dup}, "dup.yaml:3:1: name: duplicate key (first given on line 1)");
  const auto syntax = (dir / "syntax.yaml").string();
  std::ofstream(syntax) << "name: [a\n";
  expectInputError({"sweep", syntax}, "syntax.yaml:");
}

// A bad steer_controller section (an unknown key, NaN, a negative delay, a table not sorted by speed)
// exits 2 naming file:line:col and the key, for check and for a command that builds models.
TEST(CliInput, BadSteerControllerNamesFileLineColumn) {
  const auto dir = std::filesystem::temp_directory_path() / ("motostab_cli_controller_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::ifstream in(kWhipple);
  const std::string base((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const int lines = static_cast<int>(std::count(base.begin(), base.end(), '\n'));
  const std::string line = std::to_string(lines + 2);
  const std::pair<std::string, std::string> cases[] = {
      {"steer_controller:\n  roll_rate_gain: -6\n", ":" + line + ":3: steer_controller.roll_rate_gain"},
      {"steer_controller:\n  roll_rate_Nms_per_rad: .nan\n", ":" + line + ":3: steer_controller.roll_rate_Nms_per_rad"},
      {"steer_controller:\n  delay_s: -0.02\n", ":" + line + ":3: steer_controller.delay_s"},
      {"steer_controller:\n  schedule: {table: [[2, 1], [1, 0]]}\n", ":" + line + ":30: steer_controller.schedule.table[1]"}};
  int i = 0;
  for (const auto& [text, needle] : cases) {
    const std::string file = (dir / ("bad" + std::to_string(i++) + ".yaml")).string();
    std::ofstream(file) << base << (base.back() == '\n' ? "" : "\n") << text;
    expectInputError({"check", file}, file + needle);
    expectInputError({"sweep", file, "--out", (dir / "out").string()}, file + needle);
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  std::filesystem::remove_all(dir);
}

// A relaxation_linear tyre given both a relaxation length and a lateral carcass stiffness exits 2 naming
// file:line:col of the stiffness key, for check and for a command that builds models.
TEST(CliInput, TyreWithLengthAndCarcassNamesFileLineColumn) {
  const auto dir = makeTempDir("cli_carcass");
  std::ifstream in(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/supersport.yaml");
  std::string text, line, needle;
  for (int n = 1; std::getline(in, line); ++n) {
    const size_t at = line.find("relaxation_length_m: 0.122");  // the rear tyre
    if (at != std::string::npos) {
      line.insert(at, "lateral_carcass_stiffness_N_per_m: 1.1e5, ");
      needle = ":" + std::to_string(n) + ":" + std::to_string(at + 1) + ": contact.rear.lateral_carcass_stiffness_N_per_m";
    }
    text += line + "\n";
  }
  ASSERT_FALSE(needle.empty());
  const std::string file = (dir / "both.yaml").string();
  std::ofstream(file) << text;
  expectInputError({"check", file}, file + needle);
  expectInputError({"sweep", file, "--speeds", "10:10:1", "--out", (dir / "out").string()}, file + needle);
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The benchmark scenario with its `name:` line replaced.
std::string withName(const std::string& name) {
  std::string text = readFile(kWhipple);
  const size_t at = text.find("\nname: ") + 1;
  text.replace(at, text.find('\n', at) - at, "name: " + name);
  return text;
}

// `sweep inner/bike.yaml --out inner` once replaced the folder holding the scenario and the user's notes:
// a folder that holds an input of the run is refused, whether or not motostab wrote it, and so is any
// folder motostab did not write.
TEST(CliOutputSafety, AFolderHoldingTheScenarioIsNeverReplaced) {
  namespace fs = std::filesystem;
  const fs::path dir = makeTempDir("cli_inner");
  fs::create_directories(dir / "inner");
  std::ofstream(dir / "inner" / "bike.yaml") << readFile(kWhipple);
  std::ofstream(dir / "inner" / "notes.txt") << "my notes\n";
  for (const bool marked : {false, true}) {
    if (marked) std::ofstream(dir / "inner" / ".motostab-output") << "";
    const CliRun r = runCli({"sweep", "inner/bike.yaml", "--out", "inner", "--speeds", "4:5:1"}, dir.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("'inner' holds "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("bike.yaml, an input of this run"), std::string::npos) << r.output;
    EXPECT_EQ(readFile(dir / "inner" / "notes.txt"), "my notes\n");
    EXPECT_EQ(readFile(dir / "inner" / "bike.yaml"), readFile(kWhipple));
  }
  // A folder of the user's that holds no input is refused too; an empty one is used.
  fs::create_directories(dir / "mine");
  std::ofstream(dir / "mine" / "x.txt") << "x";
  const CliRun r = runCli({"sweep", kWhipple, "--out", "mine", "--speeds", "4:5:1"}, dir.string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("not written by motostab"), std::string::npos) << r.output;
  EXPECT_EQ(readFile(dir / "mine" / "x.txt"), "x");
  fs::create_directories(dir / "empty");
  EXPECT_EQ(runCli({"sweep", kWhipple, "--out", "empty", "--speeds", "4:5:1"}, dir.string()).exitCode, 0);
  EXPECT_TRUE(fs::exists(dir / "empty" / "eigenvalues.csv"));
  // A second run replaces what the first wrote.
  EXPECT_EQ(runCli({"sweep", kWhipple, "--out", "empty", "--speeds", "4:6:1"}, dir.string()).exitCode, 0);
}

// A scenario `name` that is a path ("../victim", an absolute path, "a/b", "..") once made a plain
// `motostab sweep s.yaml` replace a sibling folder: an input error at the name's line.
TEST(CliOutputSafety, AScenarioNameIsNotAPath) {
  namespace fs = std::filesystem;
  const fs::path dir = makeTempDir("cli_name");
  fs::create_directories(dir / "work");
  fs::create_directories(dir / "victim");
  std::ofstream(dir / "victim" / "precious.txt") << "keep\n";
  const int nameLine = 5;  // the benchmark scenario's name line
  for (const std::string& name : std::vector<std::string>{"\"../victim\"", "\"" + (dir / "victim").string() + "\"", "a/b", "\"..\"", "\".\""}) {
    std::ofstream(dir / "work" / "s.yaml") << withName(name);
    const CliRun r = runCli({"sweep", "s.yaml", "--speeds", "4:5:1"}, (dir / "work").string());
    EXPECT_EQ(r.exitCode, 2) << name << "\n" << r.output;
    EXPECT_NE(r.output.find("s.yaml:" + std::to_string(nameLine) + ":1: name"), std::string::npos) << r.output;
    EXPECT_EQ(readFile(dir / "victim" / "precious.txt"), "keep\n");
  }
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator(dir / "work")) (void)e, ++entries;
  EXPECT_EQ(entries, 1u);  // s.yaml only: nothing was written
  expectInputError({"check", kWhipple, "--set", "name=../victim"}, "--set name=../victim");
  // A name with a right-to-left override (U+202E) or a C1 control (U+0085) becomes no folder.
  for (const std::string& name : {std::string("\"rev\\u202Egpj\""), std::string("\"next\\x85line\"")}) {
    std::ofstream(dir / "work" / "s.yaml") << withName(name);
    const CliRun r = runCli({"check", "s.yaml"}, (dir / "work").string());
    EXPECT_EQ(r.exitCode, 2) << name << "\n" << r.output;
    EXPECT_NE(r.output.find("s.yaml:" + std::to_string(nameLine) + ":1: name"), std::string::npos) << r.output;
  }
}

// A user's files added to a folder motostab wrote (`sweep --out A; mkdir A/sub`) were deleted by the next
// run into A: the marker lists what motostab wrote, and a folder holding anything else is refused
// naming it. The system's refusals (a name over 255 bytes) are exit 2 at --out; a 245-character name,
// whose temporary sibling would exceed 255 bytes, works.
TEST(CliOutputSafety, UserFilesInAnOutputFolderAreKept) {
  namespace fs = std::filesystem;
  const fs::path dir = makeTempDir("cli_user_files");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<std::string> sweep{"sweep", kWhipple, "--speeds", "4:5:1", "--out"};
  auto run = [&](const std::string& out) {
    std::vector<std::string> args = sweep;
    args.push_back(out);
    return runCli(args, dir.string());
  };
  ASSERT_EQ(run("A").exitCode, 0);
  fs::create_directories(dir / "A" / "sub");
  std::ofstream(dir / "A" / "sub" / "notes.txt") << "x\n";
  const CliRun refused = run("A");
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  EXPECT_NE(refused.output.find("--out: 'A' holds entries motostab did not write (sub)"), std::string::npos) << refused.output;
  EXPECT_EQ(readFile(dir / "A" / "sub" / "notes.txt"), "x\n");
  fs::remove_all(dir / "A" / "sub");
  EXPECT_EQ(run("A").exitCode, 0);
  const CliRun longName = run(std::string(245, 'o'));
  EXPECT_EQ(longName.exitCode, 0) << longName.output;
  EXPECT_TRUE(fs::exists(dir / std::string(245, 'o') / "eigenvalues.csv"));
  const CliRun tooLong = run(std::string(256, 'o'));
  EXPECT_EQ(tooLong.exitCode, 2) << tooLong.output;
  EXPECT_NE(tooLong.output.find("--out"), std::string::npos) << tooLong.output;
  fs::remove_all(dir);
}

// YAML aliases nested ten wide and seven deep ("billion laughs", 1.5 KB) once took 30 s and 6.5 GB: now
// an error at the first alias that would expand aliases, in a scenario, a --set value and measured data.
TEST(CliBoundedInputs, AliasBombsAreRefusedAtOnce) {
  namespace fs = std::filesystem;
  const fs::path dir = makeTempDir("cli_bomb");
  std::string bomb = "bomb0: &b0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int l = 1; l <= 7; ++l) {
    bomb += "bomb" + std::to_string(l) + ": &b" + std::to_string(l) + " [";
    for (int k = 0; k < 10; ++k) bomb += (k ? ", *b" : "*b") + std::to_string(l - 1);
    bomb += "]\n";
  }
  std::ofstream(dir / "s.yaml") << bomb << readFile(kWhipple);
  expectInputError({"sweep", (dir / "s.yaml").string()}, "s.yaml:3:");
  expectInputError({"check", kWhipple, "--set", "description={a: &a [1, 1], b: &b [*a, *a], c: [*b, *b]}"},
                   "expanded at most once");
  std::ofstream(dir / "m.yaml") << bomb << "eigenvalues: []\n";
  expectInputError({"diagnose", kWhipple, (dir / "m.yaml").string(), "--out", (dir / "o").string()}, "m.yaml:3:");
  std::ofstream(dir / "two.yaml") << readFile(kWhipple) << "---\nname: second\n";
  expectInputError({"check", (dir / "two.yaml").string()}, "second YAML document");
  EXPECT_FALSE(fs::exists(dir / "o"));
}

// Files must be regular files; counts are bounded (the bounds are in docs/commands.md).
TEST(CliBoundedInputs, CountsAndFilesAreBounded) {
  expectInputError({"check", "/dev/zero"}, "is a device");
  expectInputError({"uncertainty", std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/kooijman-silvercity.yaml", "--samples",
                    "1000000000"},
                   "--samples");
  expectInputError({"sweep", kWhipple, "--roll-deg", "5:"}, "a bound or step is missing");
  expectInputError({"sweep", kWhipple, "--roll-deg", ":10:1"}, "--roll-deg");
  expectInputError({"sweep", kWhipple, "--speeds", "1:5:"}, "--speeds");
  expectInputError({"sweep", kWhipple, "--roll-deg", "0:20:0.01"}, "at most 1000 angles");
  // Speeds x roll angles of a map: 991 x 201 points (1e8 were accepted and filled the memory; 30 kB each).
  expectInputError({"sweep", kWhipple, "--speeds", "1:100:0.1", "--roll-deg", "0:20:0.1"}, "points; at most 10000 (");
  // Output samples of a simulation (duration / output step overflowed to an empty run with exit 0).
  expectInputError({"simulate", kWhipple, "--speed", "5", "--duration", "300000", "--output-step", "1e-4"},
                   "output samples; at most 1e5");
}

// A sweep over one speed (`--speeds 5:5:1`) is a valid request: its plots are drawn over a range around it.
TEST(CliValidRequests, OneSpeedSweepWithItsPlots) {
  namespace fs = std::filesystem;
  const fs::path dir = makeTempDir("cli_one_speed");
  const CliRun r = runCli({"sweep", kWhipple, "--speeds", "5:5:1", "--out", "one"}, dir.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* f : {"real_part_vs_speed.png", "real_part_vs_speed.svg", "root_locus.png", "eigenvalues.csv"})
    EXPECT_TRUE(fs::exists(dir / "one" / f)) << f;
}

}  // namespace
}  // namespace motostab::cli
