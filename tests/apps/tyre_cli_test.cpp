// `motostab tyre` end to end on the MF 6.1 sample file, its input errors (exit 2), and a nonlinear
// simulation of the Magic Formula supersport at a large roll perturbation.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/apps/cli_support.h"

namespace {

const std::string kSampleTir = "tests/data/reference/MF61-sample-tir/sample_MF61_ExternData.tir";

TEST(CliTyre, WritesForcesAndPlots) {
  const auto dir = makeTempDir("cli_tyre");
  const CliRun r = runCli({"tyre", kSampleTir, "--fz", "4000", "--slip-deg", "-10:10:0.5", "--camber-deg", "2", "--slip-ratio",
                           "0.01", "--out", (dir / "out").string()});
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("cornering stiffness"), std::string::npos) << r.output;
  const TextCsv t = readTextCsv(dir / "out" / "forces.csv");
  const std::vector<std::string> pinned{"fz_N", "slip_angle_rad", "camber_rad", "slip_ratio", "fx_N",
                                        "fy_N", "mz_Nm",          "mx_Nm",      "my_Nm"};
  ASSERT_EQ(t.header, pinned);
  ASSERT_EQ(t.rows.size(), 41u);
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const double slip = std::stod(t.rows[i][1]);
    EXPECT_NEAR(slip, (-10 + 0.5 * i) * M_PI / 180, 1e-15);
    EXPECT_EQ(std::stod(t.rows[i][0]), 4000);
    EXPECT_NEAR(std::stod(t.rows[i][2]), 2 * M_PI / 180, 1e-16);
    EXPECT_EQ(std::stod(t.rows[i][3]), 0.01);
  }
  // ISO signs: a wheel sliding left (alpha > 0) is pushed right, and the force saturates near the
  // friction limit mu Fz (PDY1 = 0.8785 at the nominal load 4000 N: 3514 N; the vertical shifts and
  // the camber add a few per cent).
  const double fyLeft = std::stod(t.rows.front()[5]), fyRight = std::stod(t.rows.back()[5]);
  EXPECT_GT(fyLeft, 1000);
  EXPECT_LT(fyRight, -1000);
  EXPECT_LT(std::abs(fyRight), 1.05 * 0.8785 * 4000);  // within a few per cent: shifts and camber add a little
  // 17 significant digits: the slip column round-trips the double the command computed.
  EXPECT_GE(t.rows[1][1].size(), 17u) << t.rows[1][1];
  for (const char* f : {"fy_vs_slip.png", "fy_vs_slip.svg", "fy_vs_slip.gp", "mz_vs_slip.png", "mz_vs_slip.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
}

TEST(CliTyre, BadInputExitsWithTwo) {
  const auto dir = makeTempDir("cli_tyre_errors");
  const std::string out = (dir / "out").string();
  // A broken file: unknown FITTYP, named with its line.
  std::ifstream in(std::string(MOTOSTAB_SOURCE_DIR) + "/" + kSampleTir);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  s.replace(s.find("FITTYP                   = 61"), 29, "FITTYP                   = 52");
  const auto broken = dir / "broken.tir";
  std::ofstream(broken) << s;
  expectInputError({"tyre", broken.string(), "--fz", "3000", "--slip-deg", "0:5:1", "--camber-deg", "0", "--out", out},
                   "broken.tir:18: FITTYP");
  expectInputError({"tyre", kSampleTir, "--fz", "3000", "--slip-deg", "5:-5:1", "--camber-deg", "0", "--out", out}, "--slip-deg");
  expectInputError({"tyre", kSampleTir, "--fz", "nan", "--slip-deg", "0:5:1", "--camber-deg", "0", "--out", out}, "--fz");
  expectInputError({"tyre", kSampleTir, "--fz", "3000", "--slip-deg", "0:5:1", "--out", out}, "--camber-deg");
  EXPECT_FALSE(std::filesystem::exists(out)) << "no output folder after an input error";
}

TEST(CliTyre, MagicFormulaSupersportSimulatesALargeLean) {
  // A lateral force pulse on the rear frame (3 kN for 0.6 s) leans the motorcycle about 18 degrees at
  // 30 m/s: the tyres run at large camber and nonzero slip; the run completes with finite tyre forces
  // and the lean decays. Slowly: on these tyres the capsize mode at 30 m/s is nearly neutral (real
  // part -0.08 1/s in the sweep), so the motorcycle is not upright after 3 s.
  const auto dir = makeTempDir("cli_tyre_simulate");
  const CliRun r = runCli({"simulate", "scenarios/supersport-mf.yaml", "--speed", "30", "--perturb",
                           "lateral-force:rear_frame:3000:0.1:0.6", "--duration", "3", "--out", (dir / "sim").string()});
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const TextCsv t = readTextCsv(dir / "sim" / "timeseries.csv");
  const int roll = t.find("roll"), camber = t.find("front_tyre_camber_rad"), fy = t.find("front_tyre_Fy_N"),
            mx = t.find("rear_tyre_Mx_Nm");
  ASSERT_GE(roll, 0);
  ASSERT_GE(camber, 0);
  ASSERT_GE(fy, 0);
  ASSERT_GE(mx, 0);
  double maxCamber = 0, maxFy = 0;
  for (const auto& row : t.rows) {
    const double c = std::stod(row[camber]), f = std::stod(row[fy]);
    ASSERT_TRUE(std::isfinite(c) && std::isfinite(f));
    maxCamber = std::max(maxCamber, std::abs(c));
    maxFy = std::max(maxFy, std::abs(f));
  }
  EXPECT_GT(maxCamber, 0.3) << "the pulse should lean the motorcycle by more than 17 degrees";
  EXPECT_GT(maxFy, 500);
  EXPECT_LT(std::abs(std::stod(t.rows.back()[camber])), 0.8 * maxCamber) << "the lean decays";
}

TEST(CliTyre, UncertaintySamplesAScalingFactor) {
  // A scaling factor given in the scenario is a number like any other: uncertainty samples it and
  // reports the wobble speed's sensitivity to it (the front cornering stiffness moves wobble).
  const auto dir = makeTempDir("cli_tyre_uncertainty");
  const CliRun r = runCli({"uncertainty", "scenarios/supersport-mf.yaml", "--set", "contact.front.scaling={LKY: 1}", "--set",
                           "uncertainty={contact.front.scaling.LKY: 0.1}", "--samples", "8", "--speeds", "30:50:5", "--threads",
                           "1", "--out", (dir / "unc").string()});
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const TextCsv t = readTextCsv(dir / "unc" / "sensitivity.csv");
  const int mode = t.find("mode"), parameter = t.find("parameter"), derivative = t.find("derivative");
  bool found = false;
  for (const auto& row : t.rows) {
    if (row[mode] != "wobble") continue;
    found = true;
    EXPECT_EQ(row[parameter], "contact.front.scaling.LKY");
    EXPECT_GT(std::abs(std::stod(row[derivative])), 1.0) << "m/s per unit of LKY";
  }
  EXPECT_TRUE(found);
}

}  // namespace
