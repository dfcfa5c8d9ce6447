// `motostab tyre` end to end on the MF 6.1 sample file and on the tyres of bundled scenarios, its input
// errors (exit 2), tyre parameters without a meaningful result refused with their location (exit 2), and
// a nonlinear simulation of the Magic Formula supersport at a large roll perturbation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "tests/apps/cli_support.h"

namespace {

const std::string kSampleTir = "tests/data/reference/MF61-sample-tir/sample_MF61_ExternData.tir";

TEST(CliTyre, WritesForcesAndPlots) {
  const auto dir = makeTempDir("cli_tyre");
  const CliRun r = runCli({"tyre", kSampleTir, "--fz", "4000", "--slip-deg", "-10:10:0.5", "--camber-deg", "2", "--slip-ratio",
                           "0.01", "--out", (dir / "out").string()});
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("cornering stiffness"), std::string::npos) << r.output;
  // The sample has no LONGITUDINAL_STIFFNESS: no longitudinal relaxation length (it printed "nan m").
  EXPECT_NE(r.output.find("longitudinal relaxation length = not given"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
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
                   "broken.tir:18:28: FITTYP");
  expectInputError({"tyre", kSampleTir, "--fz", "3000", "--slip-deg", "5:-5:1", "--camber-deg", "0", "--out", out}, "--slip-deg");
  expectInputError({"tyre", kSampleTir, "--fz", "nan", "--slip-deg", "0:5:1", "--camber-deg", "0", "--out", out}, "--fz");
  expectInputError({"tyre", kSampleTir, "--fz", "3000", "--slip-deg", "0:5:1", "--out", out}, "--camber-deg");
  EXPECT_FALSE(std::filesystem::exists(out)) << "no output folder after an input error";
}

// The Fy column of forces.csv at slip angle row i.
double fyAt(const TextCsv& t, size_t i) { return std::stod(t.rows.at(i)[5]); }

// The front tyre of scenarios/supersport-mf.yaml (Evangelou 2004, Tables 9.1-9.3) in pure side slip at
// zero camber, written out from Sharp, Evangelou & Limebeer (2004) sec. 4 with the default reading
// (paper_axes z_down, slip_variable angle: a = alpha_ISO, Fy_ISO = -Fy): Fy = -Dy sin(Cy atan(By a -
// Ey (By a - atan(By a)))), Dy = PDY1 Fz, Ey = PEY1, By = K_ya/(Cy Dy).
double supersportFrontPureFy(double Fz, double alpha) {
  const double FNOMIN = 1100, PCY1 = 0.83266, PDY1 = 1.3, PEY1 = -1.2556, PKY1 = 22.841, PKY2 = 2.1578, PKY3 = 2.5058;
  const double Kya = PKY1 * FNOMIN * std::sin(PKY2 * std::atan(Fz / (PKY3 * FNOMIN)));
  const double Dy = PDY1 * Fz, By = Kya / (PCY1 * Dy), x = By * alpha;
  return -Dy * std::sin(PCY1 * std::atan(x - PEY1 * (x - std::atan(x))));
}

TEST(CliTyre, DrawsAScenariosMotorcycleTyre) {
  const auto dir = makeTempDir("cli_tyre_scenario");
  const CliRun r = runCli({"tyre", "scenarios/supersport-mf.yaml", "--wheel", "front", "--fz", "1500", "--slip-deg", "-12:12:1.5",
                           "--camber-deg", "0", "--out", (dir / "front").string()});
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("motorcycle Magic Formula (paper_axes z_down, slip_variable angle)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("m at 20 m/s"), std::string::npos) << "the speed-dependent relaxation length at three speeds\n" << r.output;
  const TextCsv t = readTextCsv(dir / "front" / "forces.csv");
  ASSERT_EQ(t.header, (std::vector<std::string>{"fz_N", "slip_angle_rad", "camber_rad", "slip_ratio", "fx_N", "fy_N", "mz_Nm", "mx_Nm", "my_Nm"}));
  ASSERT_EQ(t.rows.size(), 17u);
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const double alpha = std::stod(t.rows[i][1]);
    EXPECT_NEAR(alpha, (-12 + 1.5 * i) * M_PI / 180, 1e-15);
    EXPECT_NEAR(fyAt(t, i), supersportFrontPureFy(1500, alpha), 1e-9 * 1500) << i;
    // Small slips: the aligning moment turns the wheel towards its velocity (Mz > 0 for alpha > 0).
    if (std::abs(alpha) > 0 && std::abs(alpha) < 0.05) {
      EXPECT_GT(std::stod(t.rows[i][6]) * alpha, 0) << i;
    }
  }
  for (const char* f : {"fy_vs_slip.png", "fy_vs_slip.svg", "mz_vs_slip.png", "mz_vs_slip.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir / "front" / f)) << f;
}

// The combined-slip cut's side (RBY3 = -0.059) follows paper_axes, a scenario key that --set changes:
// at slip ratio 0.1 the side force is cut more at -5 degrees than at +5 degrees with z_down (the public
// implementations' reading), and the other way round with z_up.
TEST(CliTyre, PaperAxesMoveTheCombinedSlipCut) {
  const auto dir = makeTempDir("cli_tyre_axes");
  std::vector<std::string> args{"tyre", "scenarios/supersport-mf.yaml", "--wheel", "front", "--fz", "1500",
                                "--slip-deg", "-5:5:10", "--camber-deg", "0", "--slip-ratio", "0.1"};
  auto run = [&](const std::string& out, const std::vector<std::string>& extra) {
    std::vector<std::string> a = args;
    a.insert(a.end(), extra.begin(), extra.end());
    a.insert(a.end(), {"--out", (dir / out).string()});
    const CliRun r = runCli(a);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return readTextCsv(dir / out / "forces.csv");
  };
  const TextCsv down = run("down", {});
  const TextCsv up = run("up", {"--set", "contact.front.paper_axes=z_up"});
  ASSERT_EQ(down.rows.size(), 2u);
  ASSERT_EQ(up.rows.size(), 2u);
  EXPECT_GT(fyAt(down, 0), 0);
  EXPECT_LT(fyAt(down, 1), 0);
  EXPECT_LT(std::abs(fyAt(down, 0)) + 100, std::abs(fyAt(down, 1))) << fyAt(down, 0) << " " << fyAt(down, 1);
  EXPECT_NEAR(fyAt(up, 0), -fyAt(down, 1), 1e-6);
  EXPECT_NEAR(fyAt(up, 1), -fyAt(down, 0), 1e-6);
}

// relaxation_linear's linear laws: Fy = Fz (k_alpha a + k_phi phi) with a = -tan(alpha_ISO), phi =
// -gamma_ISO; the supersport's rear tyre (seed Table 6: 10.1, 1.52, -0.47, 0.054 per unit load) and the
// bicycle preset's front (15, 0.9, -0.24, 0.012; docs/scenario-format.md).
TEST(CliTyre, DrawsAScenariosLinearTyre) {
  const auto dir = makeTempDir("cli_tyre_linear");
  struct Case {
    std::string scenario, wheel;
    double ka, kphi, kmz, kmt;
  };
  for (const auto& c : {Case{"scenarios/supersport.yaml", "rear", 10.1, 1.52, -0.47, 0.054},
                        Case{"scenarios/whipple-benchmark-tyres.yaml", "front", 15, 0.9, -0.24, 0.012}}) {
    const auto out = dir / c.wheel;
    const CliRun r = runCli({"tyre", c.scenario, "--wheel", c.wheel, "--fz", "800", "--slip-deg", "-6:6:2", "--camber-deg", "-20",
                             "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("relaxation_linear tyre"), std::string::npos) << r.output;
    const TextCsv t = readTextCsv(out / "forces.csv");
    ASSERT_EQ(t.rows.size(), 7u);
    for (size_t i = 0; i < t.rows.size(); ++i) {
      const double a = -std::tan(std::stod(t.rows[i][1])), phi = 20 * M_PI / 180;
      EXPECT_NEAR(fyAt(t, i), 800 * (c.ka * a + c.kphi * phi), 1e-9) << c.scenario << " " << i;
      EXPECT_NEAR(std::stod(t.rows[i][6]), 800 * (c.kmz * a + c.kmt * phi), 1e-9) << c.scenario << " " << i;
    }
  }
}

TEST(CliTyre, ScenarioTyreInputErrorsExitWithTwo) {
  const auto dir = makeTempDir("cli_tyre_scenario_errors");
  const std::string out = (dir / "out").string();
  const std::vector<std::string> common{"--fz", "1000", "--slip-deg", "0:5:1", "--camber-deg", "0", "--out", out};
  auto with = [&](std::vector<std::string> head) {
    head.insert(head.end(), common.begin(), common.end());
    return head;
  };
  expectInputError(with({"tyre", "scenarios/whipple-benchmark.yaml", "--wheel", "front"}), "contact.model");  // rolling_no_slip
  expectInputError(with({"tyre", "scenarios/supersport-mf.yaml", "--wheel", "middle"}), "--wheel");
  expectInputError(with({"tyre", "scenarios/supersport-mf.yaml"}), "--wheel");
  expectInputError(with({"tyre", kSampleTir, "--wheel", "front"}), "--wheel");
  expectInputError(with({"tyre", kSampleTir, "--set", "name=x"}), "--set");
  expectInputError(with({"tyre", "scenarios/supersport-mf.yaml", "--wheel", "front", "--set", "contact.front.paper_axes=sideways"}),
                   "contact.front.paper_axes");
  expectInputError(with({"tyre", "scenarios/supersport.yaml", "--wheel", "front", "--set", "contact.front.paper_axes=z_up"}),
                   "contact.front.paper_axes");
  EXPECT_FALSE(std::filesystem::exists(out)) << "no output folder after an input error";
}

// A copy of `source` (relative to the source folder) in `dir` with the first occurrence of `from`
// replaced by `to`, and the line (1-based) where it was.
std::pair<std::filesystem::path, int> writeEdited(const std::filesystem::path& dir, const std::string& source,
                                                  const std::string& from, const std::string& to) {
  std::ifstream in(std::string(MOTOSTAB_SOURCE_DIR) + "/" + source);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  const int line = 1 + static_cast<int>(std::count(s.begin(), s.begin() + static_cast<long>(at), '\n'));
  s.replace(at, from.size(), to);
  const auto path = dir / (std::filesystem::path(source).stem().string() + "-edited" + std::filesystem::path(source).extension().string());
  std::ofstream(path) << s;
  return {path, line};
}

// Physical tyre parameters that cannot give a meaningful result are refused where they are read, with
// file:line:column and key (exit 2), through every route: a .tir file, a scenario's inline coefficients
// or relaxation_linear keys, a scaling factor given with --set; a law that is not finite in its range is
// refused naming its coefficient set; a path that is not a regular file is refused.
TEST(CliTyre, MeaninglessTyreParametersAreRefused) {
  const auto dir = makeTempDir("cli_tyre_meaningless");
  const std::string out = (dir / "out").string();
  const std::vector<std::string> common{"--fz", "1000", "--slip-deg", "0:5:1", "--camber-deg", "0", "--out", out};
  auto tyre = [&](std::vector<std::string> head) {
    head.insert(head.begin(), "tyre");
    head.insert(head.end(), common.begin(), common.end());
    return head;
  };
  // .tir: a negative relaxation scale (gave unstable "relaxation" roots of +117 1/s) and a zero shape
  // factor (gave a flat side force with a printed cornering stiffness of -53353 N/rad).
  const auto [lsgal, lsgalLine] = writeEdited(dir, kSampleTir, "LSGAL                    = 1", "LSGAL                    = -1");
  expectInputError(tyre({lsgal.string()}), "sample_MF61_ExternData-edited.tir:" + std::to_string(lsgalLine) + ":28: LSGAL");
  const auto [pcy1, pcy1Line] = writeEdited(dir, kSampleTir, "PCY1                     =  1.337", "PCY1                     =  0");
  expectInputError(tyre({pcy1.string()}), "sample_MF61_ExternData-edited.tir:" + std::to_string(pcy1Line) + ":29: PCY1");
  if (std::filesystem::exists("/dev/zero")) expectInputError(tyre({"/dev/zero"}), "/dev/zero: not a regular file");
  // A magnitude above 1e12 (QDZ1 = 1e200 gave an aligning moment of 1e201 N m with exit 0).
  const auto [qdz1, qdz1Line] = writeEdited(dir, kSampleTir, "QDZ1                     =  0.09068", "QDZ1                     =  1e200");
  expectInputError(tyre({qdz1.string()}), "sample_MF61_ExternData-edited.tir:" + std::to_string(qdz1Line) + ":29: QDZ1");
  // A scenario's inline relaxation coefficient, the same refused by sweep, and a relaxation_linear camber
  // stiffness of the wrong sign.
  const auto [relax, relaxLine] = writeEdited(dir, "scenarios/supersport-mf.yaml", "RELAX_C1: 8.633e-6", "RELAX_C1: -8.633e-6");
  const std::string relaxAt = "supersport-mf-edited.yaml:" + std::to_string(relaxLine) + ":7: contact.front.coefficients.RELAX_C1";
  expectInputError(tyre({relax.string(), "--wheel", "front"}), relaxAt);
  expectInputError({"sweep", relax.string(), "--speeds", "10:20:5", "--out", out + "-sweep"}, relaxAt);
  const auto [camber, camberLine] =
      writeEdited(dir, "scenarios/supersport.yaml", "camber_stiffness_per_rad: 1.52", "camber_stiffness_per_rad: -1.52");
  expectInputError({"check", camber.string()}, "supersport-edited.yaml:" + std::to_string(camberLine));
  expectInputError({"check", camber.string()}, "contact.rear.camber_stiffness_per_rad");
  // A scaling factor from --set, and a law whose side force overflows above 1.7 FNOMIN (PDY2 = 1000).
  expectInputError(tyre({"scenarios/supersport-mf.yaml", "--wheel", "rear", "--set", "contact.rear.scaling={LKY: -1}"}),
                   "contact.rear.scaling.LKY");
  const CliRun inf = runCli(tyre({"scenarios/supersport-mf.yaml", "--wheel", "front", "--set", "contact.front.coefficients.PDY2=1000"}));
  EXPECT_EQ(inf.exitCode, 2) << inf.output;
  EXPECT_NE(inf.output.find("contact.front.coefficients: these coefficients cannot be used: a force or moment is not finite"),
            std::string::npos)
      << inf.output;
  EXPECT_FALSE(std::filesystem::exists(out)) << "no output folder after an input error";
}

// The bundled tyres not drawn by the tests above load and draw finite forces at large camber and slip:
// the supersport-mf rear in both readings, the enduro's and the bicycle preset's rear tyres.
TEST(CliTyre, BundledTyresLoad) {
  const auto dir = makeTempDir("cli_tyre_bundled");
  const std::vector<std::vector<std::string>> cases = {
      {"scenarios/supersport-mf.yaml", "--wheel", "rear"},
      {"scenarios/supersport-mf.yaml", "--wheel", "rear", "--set", "contact.rear.paper_axes=z_up", "--set",
       "contact.rear.slip_variable=tangent"},
      {"scenarios/enduro.yaml", "--wheel", "rear"},
      {"scenarios/whipple-benchmark-tyres.yaml", "--wheel", "rear"}};
  int n = 0;
  for (auto args : cases) {
    args.insert(args.begin(), "tyre");
    const std::string out = (dir / std::to_string(++n)).string();
    args.insert(args.end(), {"--fz", "1200", "--slip-deg", "-20:20:5", "--camber-deg", "45", "--slip-ratio", "-0.2", "--out", out});
    const CliRun r = runCli(args);
    EXPECT_EQ(r.exitCode, 0) << args[1] << "\n" << r.output;
    if (r.exitCode != 0) continue;
    const TextCsv t = readTextCsv(std::filesystem::path(out) / "forces.csv");
    for (const auto& row : t.rows)
      for (const auto& v : row) EXPECT_TRUE(std::isfinite(std::stod(v))) << args[1];
  }
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


// A .tir coefficient the equations do not use (the sample's PTX1, a longitudinal relaxation length) is
// warned once by the command, named at the key that gives the file, not once per model built (the
// sweep builds one model per worker, the trims and linearisations more).
TEST(CliTyre, UnusedTirCoefficientsAreWarnedOnce) {
  const auto dir = makeTempDir("cli_tyre_unused");
  const std::string tir = std::string(MOTOSTAB_SOURCE_DIR) + "/" + kSampleTir;
  std::ifstream in(tir);
  std::string line;
  int ptx1 = 0;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.rfind("PTX1 ", 0) == 0) ptx1 = n;
  ASSERT_GT(ptx1, 0);
  const std::string contact = "contact={model: magic_formula, front: {tir: " + tir + ", radial_stiffness_N_per_m: 100000}," +
                              " rear: {tir: " + tir + ", radial_stiffness_N_per_m: 120000}}";
  const CliRun r = runCli({"sweep", "scenarios/enduro.yaml", "--set", contact, "--speeds", "10:12:1", "--threads", "2", "--out",
                           (dir / "out").string()});
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string named = "PTX1 (line " + std::to_string(ptx1) + ")";
  size_t count = 0;
  for (size_t at = r.output.find(named); at != std::string::npos; at = r.output.find(named, at + 1)) ++count;
  EXPECT_EQ(count, 1u) << r.output;
  EXPECT_NE(r.output.find("motostab: warning: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(".tir: " + tir + ": "), std::string::npos) << r.output;  // at contact.front.tir or .rear.tir
}

}  // namespace
