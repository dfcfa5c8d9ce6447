// The whole-vehicle route end to end: `check` prints the vehicle in Table 6's form with the derived rear
// frame; plausibility warnings go to stderr and scenario.json, and `--strict` makes them exit 2 at
// file:line:col; bad totals exit 2 at `total`; `compare` sweeps several scenarios (critical speeds
// against the published benchmark values and against separate sweeps); `sweep` and `linearize`
// write linear_models.mat that SciPy's loadmat reads back with the eigenvalues of eigenvalues.csv.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "tests/apps/cli_support.h"

namespace {

namespace fs = std::filesystem;

const std::string kSource = MOTOSTAB_SOURCE_DIR;

// supersport.yaml with `from` replaced by `to`, written into `dir`; `line` is the line of `to`.
fs::path writeVariant(const fs::path& dir, const std::string& from, const std::string& to, int& line) {
  std::ifstream in(kSource + "/scenarios/supersport.yaml");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const size_t pos = text.find(from);
  EXPECT_NE(pos, std::string::npos);
  text.replace(pos, from.size(), to);
  line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
  const fs::path p = dir / "variant.yaml";
  std::ofstream(p) << text;
  return p;
}

int runReader(const fs::path& dir, const std::string& kind, const std::string& extra = "") {
  const std::string cmd = std::string(MOTOSTAB_SCIPY_PYTHON) + " " + kSource + "/tests/output/read_linear_models.py " +
                          (dir / "linear_models.mat").string() + " " + (dir / "eigenvalues.csv").string() + " " + kind +
                          " " + extra;
  return std::system(cmd.c_str());
}

}  // namespace

// Seed Table 6 (supersport): 166.2 + 77.5 kg, CoG 0.698 / 0.672 m, roll 26.7, pitch 51.0, yaw 28.1, product 3.2.
TEST(WholeVehicleCli, CheckShowsTable6AndTheDerivedRearFrame) {
  const CliRun r = runCli({"check", "scenarios/supersport.yaml"});
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* s : {"total mass               243.7000 kg", "x 0.6980 m from the rear contact, height 0.6720 m",
                        "26.7000, 51.0000, 28.1000 kg m^2", "xz 3.2000 kg m^2", "rear_frame is derived", "fork offset"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
}

TEST(WholeVehicleCli, WarningsGoToStderrAndScenarioJsonAndStrictRefuses) {
  const auto dir = makeTempDir("cli_warnings");
  int line = 0;
  const fs::path file = writeVariant(dir, "steer_axis_tilt_deg: 23.7", "steer_axis_tilt_deg: 0.436", line);
  const std::string where = "variant.yaml:" + std::to_string(line) + ":3: geometry.steer_axis_tilt_deg";
  CliRun r = runCli({"check", file.string()});
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("motostab: warning: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(where), std::string::npos) << r.output;
  expectInputError({"check", file.string(), "--strict"}, where);
  expectInputError({"sweep", file.string(), "--speeds", "5:6:1", "--strict", "--out", (dir / "strict").string()}, where);
  EXPECT_FALSE(fs::exists(dir / "strict"));
  r = runCli({"linearize", file.string(), "--speed", "10", "--out", (dir / "lin").string()});
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const nlohmann::json j = readJson(dir / "lin" / "scenario.json");
  ASSERT_EQ(j.at("warnings").size(), 1u);
  EXPECT_EQ(j.at("warnings")[0].at("check"), "steer_axis_tilt");
  EXPECT_EQ(j.at("warnings")[0].at("line"), line);
  EXPECT_TRUE(j.at("rear_frame").at("derived_from_total").get<bool>());
  EXPECT_NEAR(j.at("vehicle").at("inertia_about_cog_kgm2").at("yaw_zz").get<double>(), 28.1, 1e-9);
}

TEST(WholeVehicleCli, BadTotalsExitTwoAtTheirKey) {
  const auto dir = makeTempDir("cli_bad_total");
  int line = 0;
  fs::path file = writeVariant(dir, "{xx: 26.7, yy: 51.0, zz: 28.1,", "{xx: 26.7, yy: 36.0, zz: 10.0,", line);
  expectInputError({"check", file.string()}, "variant.yaml:" + std::to_string(line - 3) + ":1: total: the rear frame left");
  file = writeVariant(dir, "com_m: [0.698, 0, 0.672]", "com_m: [1.698, 0, 0.672]", line);
  expectInputError({"sweep", file.string(), "--out", (dir / "o").string()},
                   "variant.yaml:" + std::to_string(line) + ":3: total.com_m: the centre of mass must lie between");
  file = writeVariant(dir, "total:  ", "totals:  ", line);  // neither rear_frame nor total
  expectInputError({"check", file.string()}, "missing key 'rear_frame' (or 'total'");
}

TEST(WholeVehicleCli, CompareSweepsEachScenarioAsSweepDoes) {
  const auto dir = makeTempDir("cli_compare");
  const std::string out = (dir / "cmp").string();
  const CliRun r = runCli({"compare", "scenarios/whipple-benchmark.yaml", "scenarios/kooijman-silvercity.yaml", "--speeds",
                           "0:10:0.5", "--out", out});
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("differences against whipple-benchmark"), std::string::npos) << r.output;
  const nlohmann::json j = readJson(fs::path(out) / "summary.json");
  // Meijaard et al. (2007): weave 4.292382 m/s, capsize 6.024262 m/s.
  const nlohmann::json& ref = j.at("scenarios")[0].at("summary");
  EXPECT_NEAR(ref.at("weave_speed_mps").get<double>(), 4.29238253634111, 1e-6);
  EXPECT_NEAR(ref.at("capsize_speed_mps").get<double>(), 6.02426201538837, 1e-6);
  // The second scenario as `sweep` writes it, and each difference its speed minus the first's.
  ASSERT_EQ(runCli({"sweep", "scenarios/kooijman-silvercity.yaml", "--speeds", "0:10:0.5", "--out", (dir / "k").string()}).exitCode, 0);
  const nlohmann::json alone = readJson(dir / "k" / "summary.json");
  EXPECT_EQ(j.at("scenarios")[1].at("summary").at("critical_speeds"), alone.at("critical_speeds"));
  int rows = 0;
  for (const auto& c : j.at("critical_speeds")) {
    if (c.at("speeds_mps")[0].is_null() || c.at("speeds_mps")[1].is_null()) continue;
    EXPECT_DOUBLE_EQ(c.at("differences_mps")[1].get<double>(),
                     c.at("speeds_mps")[1].get<double>() - c.at("speeds_mps")[0].get<double>());
    ++rows;
  }
  EXPECT_GE(rows, 2);  // weave and capsize of both bicycles
  for (const char* f : {"critical_speeds.csv", "root_locus.png", "real_part_vs_speed.svg", "real_part_vs_speed.gp",
                        "kooijman-silvercity/eigenvalues.csv", "whipple-benchmark/scenario.json"})
    EXPECT_TRUE(fs::exists(fs::path(out) / f)) << f;
  EXPECT_GT(checkOutputsParse(out), 6);
  expectInputError({"compare", "scenarios/whipple-benchmark.yaml", "--out", (dir / "one").string()}, "two or more");
}

TEST(WholeVehicleCli, SweepAndLinearizeWriteMatFilesSciPyReads) {
  const auto dir = makeTempDir("cli_mat");
  ASSERT_EQ(runCli({"sweep", "scenarios/whipple-benchmark.yaml", "--speeds", "1:9:2", "--out", (dir / "s").string()}).exitCode, 0);
  EXPECT_EQ(runReader(dir / "s", "sweep"), 0);
  ASSERT_EQ(runCli({"linearize", "scenarios/enduro.yaml", "--speed", "17", "--out", (dir / "l").string()}).exitCode, 0);
  EXPECT_EQ(runReader(dir / "l", "linearize", (dir / "l" / "A.csv").string()), 0);
}
