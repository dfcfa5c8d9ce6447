// motostab diagnose on bad measurement files: exit 2, the message names file and line, and the
// output folder is neither created nor changed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "io/csv.h"
#include "tests/apps/cli_support.h"

namespace motostab::cli {
namespace {

namespace fs = std::filesystem;
const std::string kWhipple = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

// Writes `yaml` as DIR/m.yaml, diagnoses the Whipple bicycle against it into DIR/out, expects exit 2
// and returns the output.
std::string runDiagnoseExpectingExit2(const fs::path& dir, const std::string& yaml) {
  std::ofstream(dir / "m.yaml") << yaml;
  const std::string log = (dir / "log.txt").string();
  const int code = test::waitForExit(test::startMotostab(
      {"diagnose", kWhipple, (dir / "m.yaml").string(), "--out", (dir / "out").string()}, dir.string(), log));
  const std::string out = test::readLog(log);
  EXPECT_EQ(code, 2) << out;
  return out;
}

TEST(DiagnoseCli, BadMeasurementsExit2AndLeaveTheFolderAlone) {
  const fs::path dir = fs::temp_directory_path() / ("motostab_diagnose_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "e.csv") << "speed_mps,mode,real,imag\n4,weave,0.4,3\n5,weave,nan,4\n";
  // Speed range with min > max on line 3; a 40-sample trace (0.01 s apart) with NaN on line 12.
  std::ofstream(dir / "r.csv") << "speed_mps,mode,real,imag,speed_min_mps,speed_max_mps\n4,weave,0.4,3,3.9,4.1\n"
                                  "5,weave,0.3,4,5.2,4.8\n";
  std::string trace = "t_s,lean_V\n", nanTrace = trace;
  for (int i = 0; i < 40; ++i) {
    trace += std::to_string(0.01 * i) + "," + std::to_string(std::sin(0.3 * i)) + "\n";
    nanTrace += std::to_string(0.01 * i) + "," + (i == 10 ? std::string("nan") : std::to_string(std::sin(0.3 * i))) + "\n";
  }
  std::ofstream(dir / "trace.csv") << trace;
  std::ofstream(dir / "nan.csv") << nanTrace;
  const std::string run = "responses:\n  - file: FILE\n    speed_mps: 5\n    time_column: t_s\n    window_s: WINDOW\n"
                          "    signals:\n      - {column: lean_V, quantity: roll_rate, scale: free}\n";
  auto makeRun = [&](const std::string& file, const std::string& window) {
    std::string y = run;
    y.replace(y.find("FILE"), 4, file);
    y.replace(y.find("WINDOW"), 6, window);
    return y;
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"eigenvalues:\n  - file: r.csv\n", "r.csv:3"},                    // speed range min > max
      {makeRun("nan.csv", "[0, 0.39]"), "nan.csv:12"},                    // trace with NaN
      {makeRun("trace.csv", "[0, 2.5]"), "m.yaml:5"},                     // run shorter than its window
      {"eigenvalues:\n  - file: e.csv\n", "e.csv:3"},                     // NaN cell
      {"eigenvalues:\n  - file: missing.csv\n", "m.yaml:2:5"},           // missing file
      {"eigenvalues:\n  - {file: e.csv, colour: red}\n", "m.yaml:2"},    // unknown key
  };
  for (const auto& [yaml, needle] : cases) {
    const std::string out = runDiagnoseExpectingExit2(dir, yaml);
    EXPECT_NE(out.find(needle), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
  fs::remove_all(dir);
}

// An existing output folder keeps exactly its old contents when the run fails, both before the
// outputs are prepared (bad measurements) and after (an unknown candidate, found inside the run).
TEST(DiagnoseCli, FailedRunLeavesExistingFolderWhole) {
  const fs::path dir = fs::temp_directory_path() / ("motostab_diagnose_keep_" + std::to_string(::getpid()));
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / ".motostab-output") << "";  // an earlier run's outputs
  std::ofstream(dir / "out" / "old.txt") << "old outputs\n";
  std::ofstream(dir / "e.csv") << "speed_mps,mode,real,imag\n4,weave,0.4,3\n5,weave,0.3,4\n";
  std::ofstream(dir / "good.yaml") << "eigenvalues:\n  - file: e.csv\n";
  std::ofstream(dir / "bad.yaml") << "eigenvalues:\n  - {file: e.csv, colour: red}\n";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"bad.yaml"}, "bad.yaml:2"},
      {{"good.yaml", "--candidates", "no_such_candidate"}, "no_such_candidate"},
  };
  for (const auto& [args, needle] : cases) {
    std::vector<std::string> argv = {"diagnose", kWhipple, (dir / args[0]).string(), "--out", (dir / "out").string()};
    argv.insert(argv.end(), args.begin() + 1, args.end());
    const std::string log = (dir / "log.txt").string();
    const int code = test::waitForExit(test::startMotostab(argv, dir.string(), log));
    const std::string out = test::readLog(log);
    EXPECT_EQ(code, 2) << out;
    EXPECT_NE(out.find(needle), std::string::npos) << out;
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir / "out")) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{".motostab-output", "old.txt"}));
    std::ifstream in(dir / "out" / "old.txt");
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "old outputs");
    for (const auto& e : fs::directory_iterator(dir))  // no temporary folder left behind
      EXPECT_EQ(e.path().filename().string().find(".out."), std::string::npos) << e.path();
  }
  fs::remove_all(dir);
}

// Measured-data options are checked where they are read and blamed on that file: a controller's negative
// delay was reported against the scenario and "a --set" nobody gave, a run's speed of 1e6 m/s as a
// --candidates problem (and 5e4 started a 500,000-speed reference sweep), a noise level of 1e300 gave
// "RMS -nan, BIC -nan". The values are drawn at random (seeded) from the refused ranges.
TEST(DiagnoseCli, MeasuredOptionsAreBlamedOnTheMeasurementFile) {
  const fs::path dir = fs::temp_directory_path() / ("motostab_diagnose_blame_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::mt19937 rng(29);
  auto draw = [&](double lo, double hi) { return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng)); };
  std::string trace = "t_s,roll_rate\n";
  for (int i = 0; i < 40; ++i) trace += std::to_string(0.01 * i) + "," + std::to_string(0.5 * std::exp(-0.1 * i) * std::sin(0.7 * i)) + "\n";
  std::ofstream(dir / "trace.csv") << trace;
  std::ofstream(dir / "e.csv") << "speed_mps,mode,real,imag\n4,weave,0.4,3\n";
  const std::string run = "responses:\n  - file: trace.csv\n    time_column: t_s\n    signals:\n      - {column: roll_rate, quantity: roll_rate}\n";
  const std::string delay = std::to_string(-draw(1e-3, 1e3)), speed = std::to_string(draw(151, 1e7));
  const std::string noise = std::to_string(draw(1e101, 1e300)), csvSpeed = std::to_string(draw(151, 1e7));
  std::ofstream(dir / "big.csv") << "speed_mps,mode,real,imag\n" << csvSpeed << ",weave,0.4,3\n";
  std::ofstream(dir / "cd.csv") << "speed_mps,mode,real,imag,steer_controller.delay_s\n4,weave,0.4,3," << delay << "\n";
  const std::string tinyDelay = io::formatNumber(draw(1e-300, 9.9e-5));  // below the floor kMinSteerDelay
  std::ofstream(dir / "tiny.csv") << "speed_mps,mode,real,imag,steer_controller.delay_s\n4,weave,0.4,3," << tinyDelay << "\n";
  std::ofstream(dir / "dup.csv") << "speed_mps,mode,real,imag,real\n4,weave,0.4,3,0.5\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"eigenvalues:\n  - file: e.csv\n    controller: {roll_rate_Nms_per_rad: -3, delay_s: " + delay + "}\n",
       "m.yaml:3:45: eigenvalues[0].controller.delay_s: must not be negative"},
      {"eigenvalues:\n  - file: cd.csv\n", "cd.csv:2: steer_controller.delay_s: must not be negative"},
      {"eigenvalues:\n  - file: e.csv\n    controller: {delay_s: " + tinyDelay + "}\n",
       "m.yaml:3:18: eigenvalues[0].controller.delay_s: must be 0 (off) or at least 0.0001 s"},
      {"eigenvalues:\n  - file: tiny.csv\n", "tiny.csv:2: steer_controller.delay_s: must be 0 (off) or at least 0.0001 s"},
      {run + "    speed_mps: " + speed + "\n", "m.yaml:6:5: responses[0].speed_mps: a measured speed must lie between 0 and 150"},
      {"eigenvalues:\n  - file: big.csv\n", "big.csv:2: speed_mps: a measured speed"},
      {run + "    speed_mps: 4\n    noise_std: {roll_rate: " + noise + "}\n", "m.yaml:7:17: responses[0].noise_std.roll_rate"},
      {"eigenvalues:\n  - file: dup.csv\n", "dup.csv:1:5: real: column 'real' is given twice"},
  };
  for (const auto& [yaml, needle] : cases) {
    const std::string out = runDiagnoseExpectingExit2(dir, yaml);
    EXPECT_NE(out.find(needle), std::string::npos) << out << "(expected " << needle << ")";
    EXPECT_EQ(out.find("--set"), std::string::npos) << out;
    EXPECT_EQ(out.find("--candidates"), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace motostab::cli
