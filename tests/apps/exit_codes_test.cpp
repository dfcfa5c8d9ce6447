// One exit-code scheme for every command (docs/commands.md, "Exit codes"): 2 for bad input, naming it;
// 3 for valid input whose computation gives no result (a trim that does not converge, no hands-free
// turn, every sample failed, no mode, a plate that only translates), saying what was tried; never 1.
// Each command has one of each here, where it has a computation that can fail (check, import and
// identify virtual-rig compute nothing that can: they have exit 2 only). A failed run writes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <random>
#include <sstream>

#include "tests/apps/cli_support.h"
#include "tests/support/temp_dir.h"

namespace motostab::cli {
namespace {

namespace fs = std::filesystem;
const std::string kScenarios = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/";
const std::string kWhipple = kScenarios + "whipple-benchmark.yaml";
const std::string kExamples = std::string(MOTOSTAB_SOURCE_DIR) + "/examples/identification/";

// Runs `args` (with --out OUT) in a fresh folder; expects `code`, `needle` in the message and no OUT.
void expectExit(const std::vector<std::string>& args, int code, const std::string& needle, const fs::path& dir) {
  std::vector<std::string> full = args;
  full.insert(full.end(), {"--out", "out"});
  const CliRun r = runCli(full, dir.string());
  std::string cmd;
  for (const auto& a : full) cmd += a + " ";
  EXPECT_EQ(r.exitCode, code) << cmd << "\n" << r.output;
  EXPECT_NE(r.output.find(needle), std::string::npos) << cmd << "\n" << r.output << "(expected " << needle << ")";
  if (code == 3) EXPECT_NE(r.output.find("motostab: no result: "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.json")) << cmd;
}

// A steady turn at 85 deg of roll at 1 m/s has no trim (the roll continuation stalls near 11 deg): the
// trim failure of every command that trims.
const std::vector<std::string> kNoTrim{"--roll-deg", "85"};

TEST(ExitCodes, Sweep) {
  const fs::path dir = makeTempDir("exit_sweep");
  expectExit({"sweep", kWhipple, "--speeds", "1:2:0"}, 2, "--speeds", dir);
  expectExit({"sweep", kWhipple, "--speeds", "1:2:1", "--roll-deg", "85"}, 3, "trim failed at speed 1 m/s, roll 85 deg", dir);
}

// A speed x roll map whose every roll fails to trim (the roll continuation stalls near 11 deg at 1 m/s).
TEST(ExitCodes, SweepMap) {
  const fs::path dir = makeTempDir("exit_sweep_map");
  expectExit({"sweep", kWhipple, "--speeds", "1:2:1", "--roll-deg", "80:85:0"}, 2, "--roll-deg", dir);
  expectExit({"sweep", kWhipple, "--speeds", "1:2:1", "--roll-deg", "80:85:5"}, 3,
             "no roll angle of the map could be trimmed", dir);
}

// The Magic Formula supersport has no straight-running trim at 150 m/s: nothing to compare.
TEST(ExitCodes, Compare) {
  const fs::path dir = makeTempDir("exit_compare");
  const std::string mf = kScenarios + "supersport-mf.yaml";
  expectExit({"compare", mf}, 2, "scenarios", dir);
  expectExit({"compare", mf, mf, "--speeds", "150:150:1"}, 3, "trim failed at speed 150 m/s", dir);
}

TEST(ExitCodes, Linearize) {
  const fs::path dir = makeTempDir("exit_linearize");
  expectExit({"linearize", kWhipple, "--speed", "-1"}, 2, "--speed", dir);
  expectExit({"linearize", kWhipple, "--speed", "1", "--roll-deg", "85"}, 3, "trim failed", dir);
}

TEST(ExitCodes, Trim) {
  const fs::path dir = makeTempDir("exit_trim");
  expectExit({"trim", kWhipple, "--speed", "4", "--roll-deg", "89"}, 2, "--roll-deg", dir);
  expectExit({"trim", kWhipple, "--speed", "1", "--roll-deg", "85"}, 3, "trim failed", dir);
  // Valid, but no hands-free turn between 1 and 2 m/s at 3 deg: once an input error, now a result error.
  expectExit({"trim", kWhipple, "--hands-free", "--roll-deg", "3", "--speeds", "1:2:0.5"}, 3,
             "no hands-free turn at roll 3 deg", dir);
}

TEST(ExitCodes, Study) {
  const fs::path dir = makeTempDir("exit_study");
  const std::string enduro = kScenarios + "enduro.yaml";
  expectExit({"study", enduro, "--stiffness-scale", "0"}, 2, "--stiffness-scale", dir);
  expectExit({"study", enduro, "--speeds", "1:2:1", "--shape-speeds", "1", "--roll-deg", "85", "--compare", "rigid"}, 3,
             "trim failed", dir);
}

TEST(ExitCodes, Simulate) {
  const fs::path dir = makeTempDir("exit_simulate");
  expectExit({"simulate", kWhipple, "--speed", "5", "--duration", "inf"}, 2, "--duration", dir);
  expectExit({"simulate", kWhipple, "--speed", "1", "--roll-deg", "85", "--duration", "1"}, 3, "trim failed", dir);
}

// Every sample's sweep fails (the Magic Formula supersport has no straight-running trim at 150 m/s):
// once "0 succeeded" and exit 0.
TEST(ExitCodes, Uncertainty) {
  const fs::path dir = makeTempDir("exit_uncertainty");
  expectExit({"uncertainty", kScenarios + "kooijman-silvercity.yaml", "--samples", "1000000000"}, 2, "--samples", dir);
  expectExit({"uncertainty", kScenarios + "supersport-mf.yaml", "--speeds", "150:150:1", "--samples", "3", "--set",
              "uncertainty={total.mass_kg: 2}"},
             3, "every one of the 3 samples failed", dir);
  // Every draw of a crown radius with sigma 1e6 m is refused: named at the uncertainty entry with its
  // sigma and the value drawn (it was blamed on a "--set rear_wheel.crown_radius_m=..." nobody gave).
  std::ifstream in(kWhipple);
  std::stringstream text;
  text << in.rdbuf() << "uncertainty:\n  rear_wheel.crown_radius_m: 1e6\n";
  std::ofstream(dir / "wide.yaml") << text.str();
  const CliRun r = runCli({"uncertainty", (dir / "wide.yaml").string(), "--samples", "3", "--speeds", "4:5:1", "--out",
                           (dir / "u").string()});
  EXPECT_EQ(r.exitCode, 3) << r.output;
  EXPECT_NE(r.output.find("wide.yaml:35:3: uncertainty.rear_wheel.crown_radius_m: a value drawn with sigma 1e+06"),
            std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("--set"), std::string::npos) << r.output;
}

// A measured run at 150 m/s on the Magic Formula supersport: the model has no trim there.
TEST(ExitCodes, Diagnose) {
  const fs::path dir = makeTempDir("exit_diagnose");
  std::ofstream(dir / "e.csv") << "speed_mps,mode,real,imag\n4,weave,0.4,3\n-1,weave,0.3,4\n";
  std::ofstream(dir / "m.yaml") << "eigenvalues:\n  - file: e.csv\n";
  expectExit({"diagnose", kWhipple, (dir / "m.yaml").string()}, 2, "e.csv:3: speed_mps", dir);
  std::ofstream(dir / "far.csv") << "speed_mps,mode,real,imag\n150,weave,0.4,3\n";
  std::ofstream(dir / "far.yaml") << "eigenvalues:\n  - file: far.csv\n";
  expectExit({"diagnose", kScenarios + "supersport-mf.yaml", (dir / "far.yaml").string(), "--set",
              "speeds_mps={start: 140, stop: 150, step: 10}", "--no-robustness"},
             3, "trim failed", dir);
}

// A static test whose sensors all move alike: the plate translates without turning, so it has no twist
// axis (valid readings, no result).
TEST(ExitCodes, IdentifyStatic) {
  const fs::path dir = makeTempDir("exit_static");
  fs::copy_file(kExamples + "static.yaml", dir / "static.yaml");
  std::ofstream(dir / "static.csv") << "force_N,L1_m,L2_m,L3_m\n0,0.005,0.006,0.007\n250,0.0052,0.0062,0.0072\n"
                                       "500,0.0054,0.0064,0.0074\n250,0.0052,0.0062,0.0072\n0,0.005,0.006,0.007\n";
  expectExit({"identify", "static", kExamples + "frf.yaml"}, 2, "frf.yaml", dir);
  expectExit({"identify", "static", (dir / "static.yaml").string()}, 3, "the plate only translates", dir);
}

// Hammer hits whose accelerometers saw only noise (drawn at random, seeded): no mode.
void writeNoiseHits(const fs::path& dir) {
  for (const char* f : {"frf.yaml", "static.yaml", "static.csv"}) fs::copy_file(kExamples + f, dir / f);
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> noise(-1, 1);
  for (const char* hit : {"hit1.csv", "hit2.csv", "hit3.csv"}) {
    std::ifstream in(kExamples + hit);
    std::ofstream out(dir / hit);
    std::string line;
    std::getline(in, line);
    out << line << "\n";
    while (std::getline(in, line)) {
      std::stringstream cells(line);
      std::string t, force;
      std::getline(cells, t, ',');
      std::getline(cells, force, ',');
      out << t << "," << force << "," << noise(rng) << "," << noise(rng) << "," << noise(rng) << "\n";
    }
  }
}

TEST(ExitCodes, IdentifyFrfAndSwingarm) {
  const fs::path dir = makeTempDir("exit_frf");
  writeNoiseHits(dir);
  expectExit({"identify", "frf", (dir / "hit1.csv").string()}, 2, "hit1.csv", dir);
  expectExit({"identify", "swingarm", (dir / "static.yaml").string(), (dir / "static.yaml").string()}, 2, "static.yaml", dir);
  const CliRun frf = runCli({"identify", "frf", (dir / "frf.yaml").string(), "--out", "frf_out"}, dir.string());
  EXPECT_EQ(frf.exitCode, 3) << frf.output;
  EXPECT_NE(frf.output.find("no mode identified"), std::string::npos) << frf.output;
  expectExit({"identify", "swingarm", (dir / "static.yaml").string(), (dir / "frf.yaml").string()}, 3, "no mode identified", dir);
}

TEST(ExitCodes, IdentifyResponse) {
  const fs::path dir = makeTempDir("exit_response");
  std::ostringstream csv;
  csv << "time_s,roll_rate\n";
  for (int i = 0; i < 200; ++i) csv << 0.01 * i << "," << 0.5 << "\n";
  std::ofstream(dir / "flat.csv") << csv.str();
  expectExit({"identify", "response", (dir / "flat.csv").string(), "--signal", "steer_rate"}, 2, "steer_rate", dir);
  expectExit({"identify", "response", (dir / "flat.csv").string(), "--signal", "roll_rate"}, 2,
             "flat.csv: roll_rate: signal 0 is constant in the window", dir);
}

// check, import, tyre and identify cog|inertia|virtual-rig: bad input is exit 2 (they have no computation
// that fails on valid input, or, for tyre, one the tyre reader refuses at load).
TEST(ExitCodes, CommandsWithoutAResultFailure) {
  const fs::path dir = makeTempDir("exit_plain");
  EXPECT_EQ(runCli({"check", kWhipple, "--set", "name=../x"}, dir.string()).exitCode, 2);
  std::ofstream(dir / "bike.txt") << "w = 1.02+/-0.01\nw = 1.03\n";
  const CliRun imp = runCli({"import", "bike.txt", "--format", "bicycleparameters", "--out", "b.yaml"}, dir.string());
  EXPECT_EQ(imp.exitCode, 2) << imp.output;
  EXPECT_NE(imp.output.find("bike.txt:2: w: given twice (first on line 1)"), std::string::npos) << imp.output;
  EXPECT_FALSE(fs::exists(dir / "b.yaml"));
  for (const char* noFile : {"", ".", "sub/"}) {  // "" was reported as a bad --name
    const CliRun none = runCli({"import", "bike.txt", "--format", "bicycleparameters", "--out", noFile}, dir.string());
    EXPECT_EQ(none.exitCode, 2) << none.output;
    EXPECT_NE(none.output.find("--out: '" + std::string(noFile) + "' names no file"), std::string::npos) << none.output;
  }
  // Output that cannot be written where the user asked (its folder is a file): exit 2 naming the path,
  // never an internal error, and the file in the way untouched.
  std::ofstream(dir / "taken") << "mine\n";
  const std::string benchmark = std::string(MOTOSTAB_TEST_DATA_DIR) +
                                "/measured-data/BicycleParameters/data/bicycles/Benchmark/Parameters/BenchmarkBenchmark.txt";
  const CliRun blocked = runCli({"import", benchmark, "--format", "bicycleparameters", "--out", "taken/b.yaml"}, dir.string());
  EXPECT_EQ(blocked.exitCode, 2) << blocked.output;
  EXPECT_NE(blocked.output.find("cannot write output: taken/b.yaml"), std::string::npos) << blocked.output;
  EXPECT_EQ(blocked.output.find("internal error"), std::string::npos) << blocked.output;
  std::ifstream taken(dir / "taken");
  std::string kept;
  std::getline(taken, kept);
  EXPECT_EQ(kept, "mine");
  const std::string tir = std::string(MOTOSTAB_TEST_DATA_DIR) + "/reference/MF61-sample-tir/sample_MF61_ExternData.tir";
  expectExit({"tyre", tir, "--fz", "4000", "--slip-deg", "-1:", "--camber-deg", "0"}, 2, "--slip-deg", dir);
  expectExit({"identify", "cog", kExamples + "static.yaml"}, 2, "static.yaml", dir);
  expectExit({"identify", "inertia", kExamples + "cog.yaml"}, 2, "cog.yaml", dir);
  expectExit({"identify", "virtual-rig", "--noise-factor", "-1"}, 2, "--noise-factor", dir);
}

// A misspelt model-extension section is bad input for every command that reads a scenario, named at
// its file, line and column with the extensions known (the commands read the sections right after
// loading, before any work).
TEST(ExitCodes, MisspeltExtensionSectionIsBadInput) {
  const fs::path dir = makeTempDir("exit_misspelt_section");
  std::ifstream in(kWhipple);
  std::stringstream text;
  text << in.rdbuf();
  const int line = static_cast<int>(std::count(std::istreambuf_iterator<char>(text), {}, '\n')) + 1;
  const fs::path file = dir / "misspelt.yaml";
  std::ofstream(file) << text.str() << "steer_dampr: {damping_Nms_per_rad: 1}\n";
  const std::string where = file.string() + ":" + std::to_string(line) + ":";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"sweep", file.string(), "--speeds", "1:2:1"},
        std::vector<std::string>{"linearize", file.string(), "--speed", "3"},
        std::vector<std::string>{"simulate", file.string(), "--speed", "4", "--duration", "0.1", "--perturb", "steer-torque:1:0.1:0.05"},
        std::vector<std::string>{"uncertainty", file.string(), "--samples", "2"}}) {
    expectExit(args, 2, where, dir);
    expectExit(args, 2, "unknown section 'steer_dampr'", dir);
  }
}

TEST(ExitCodes, VersionAndHelpExit0) {
  const CliRun v = runCli({"--version"});
  EXPECT_EQ(v.exitCode, 0);
  EXPECT_NE(v.output.find("motostab 0."), std::string::npos) << v.output;
  EXPECT_NE(v.output.find("plugin API "), std::string::npos) << v.output;
}

}  // namespace
}  // namespace motostab::cli
