// linear_models.mat read back by an independent reader: SciPy's loadmat (python3-scipy, through
// tests/output/read_linear_models.py) checks the variables and that the eigenvalues of each A(:, :, k)
// (numpy) are those of eigenvalues.csv, for a sweep of the enduro (relaxing tyres and a twisting
// swingarm: 20 states) over a random speed grid and for one linearisation at a random speed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "analysis/modes.h"
#include "core/portable_random.h"
#include "output/linear_models_mat.h"
#include "output/sweep_output.h"
#include "tests/support/analysis_chain.h"
#include "tests/support/temp_dir.h"

namespace motostab::output {

using namespace motostab::testing;
using core::PortableRandom;

namespace {

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

// Runs the reader; its exit status (0: every check held).
int readBack(const std::filesystem::path& dir, const std::string& kind, const std::string& aCsv = "") {
  const std::string cmd = std::string(MOTOSTAB_SCIPY_PYTHON) + " " + MOTOSTAB_SOURCE_DIR + "/tests/output/read_linear_models.py " +
                          (dir / "linear_models.mat").string() + " " + (dir / "eigenvalues.csv").string() + " " + kind + " " +
                          aCsv + " > " + (dir / "reader.log").string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream in(dir / "reader.log");
  std::cout << std::string(std::istreambuf_iterator<char>(in), {});
  return status;
}

}  // namespace

TEST(LinearModelsMat, SweepReadBackBySciPy) {
  PortableRandom rng(2024);
  const VehicleModel model(loadScenario(kEnduro, {"swingarm.compliance=twist"}));
  SweepOptions opt;
  opt.start = rng.drawUniform(2, 10), opt.step = rng.drawUniform(2, 4), opt.stop = opt.start + 3 * opt.step;
  opt.linearize.computeB = true;
  const SweepResult sweep = runSweep(model, opt);
  const auto dir = makeTempDir("mat_sweep");
  writeSweepData(dir, "enduro", sweep);
  writeLinearModelsMat(dir / "linear_models.mat", sweep.models);
  EXPECT_EQ(readBack(dir, "sweep"), 0);
}

TEST(LinearModelsMat, LinearisationReadBackBySciPy) {
  PortableRandom rng(77);
  const VehicleModel model(loadScenario(kEnduro));
  const LinearModel lm = linearize(model, calcTrim(model, rng.drawUniform(5, 35)));
  const auto dir = makeTempDir("mat_linearize");
  writeLinearModel(dir, lm, analysis::calcModeContents(lm));  // labels: the model's own (lm.labels)
  writeLinearModelsMat(dir / "linear_models.mat", {lm});
  EXPECT_EQ(readBack(dir, "linearize", (dir / "A.csv").string()), 0);
}

TEST(LinearModelsMat, RefusesModelsItCannotStack) {
  const VehicleModel model(loadScenario(kEnduro));
  const LinearModel a = linearize(model, calcTrim(model, 10));
  LinearModel noB = a;
  noB.B.resize(0, 0);
  LinearModel renamed = a;
  renamed.states[0].name = "other";
  const auto file = makeTempDir("mat_refused") / "linear_models.mat";
  EXPECT_THROW(writeLinearModelsMat(file, {a, noB}), std::logic_error);
  EXPECT_THROW(writeLinearModelsMat(file, {a, renamed}), std::logic_error);
  EXPECT_THROW(writeLinearModelsMat(file, {}), std::logic_error);
  EXPECT_FALSE(std::filesystem::exists(file));
}

// A .mat file that cannot be written where the user asked (its folder is a file) is an OutputError
// naming that file, not matio's temporary; the file in the way is left as it was.
TEST(LinearModelsMat, UnwritableFileIsAnOutputErrorNamingIt) {
  const VehicleModel model(loadScenario(kEnduro));
  const LinearModel lm = linearize(model, calcTrim(model, 10));
  const auto taken = makeTempDir("mat_unwritable") / "taken";
  std::ofstream(taken) << "a user's file\n";
  const auto file = taken / "linear_models.mat";
  try {
    writeLinearModelsMat(file, {lm});
    ADD_FAILURE() << "no error";
  } catch (const io::OutputError& e) {
    EXPECT_EQ(e.getLocation().file, file.string());
    EXPECT_NE(e.getReason().find("matio cannot create"), std::string::npos) << e.getReason();
  }
  std::ifstream in(taken);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "a user's file\n");
}

}  // namespace motostab::output
