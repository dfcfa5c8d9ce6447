// Every input error exits with code 2 and names what was wrong: CLI11's own parse and
// validation errors, non-finite or out-of-range numbers, bad --set overrides, bad scenario files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

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
  expectInputError({"sweep", kWhipple, "--speeds", "0:1e9:1e-9"}, "at most 1e6 speeds");
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

}  // namespace
}  // namespace motostab::cli
