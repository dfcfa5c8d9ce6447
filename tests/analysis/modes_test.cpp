#include <gtest/gtest.h>

#include "analysis/sweep.h"
#include "scenario/scenario.h"

namespace motostab {
namespace {

SweepResult sweepEnduro() {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml", {"swingarm.compliance=twist"}));
  SweepOptions opt;
  opt.start = 10, opt.stop = 14, opt.step = 1;
  return runSweep(model, opt);
}

// The MAC of the batched cost matrix (real products) against calcMac's direct complex sum.
TEST(Modes, MatchCostMatrixEqualsPairwiseCosts) {
  const SweepResult r = sweepEnduro();
  const LinearModel &a = r.models[1], &b = r.models[2];
  const Eigen::MatrixXd c = calcMatchCosts(a, b);
  ASSERT_EQ(c.rows(), a.eigenvalues.size());
  for (int i = 0; i < c.rows(); ++i)
    for (int j = 0; j < c.cols(); ++j) EXPECT_NEAR(c(i, j), calcMatchCost(a, i, b, j), 1e-12) << i << " " << j;
  EXPECT_LT(c.diagonal().minCoeff(), 1.0);  // something matches
}

// Costs handed in (as sweep workers do) give the same branches as costs computed inside.
TEST(Modes, PrecomputedCostsGiveTheSameBranches) {
  const SweepResult r = sweepEnduro();
  std::vector<Eigen::MatrixXd> costs(r.models.size());
  for (size_t s = 1; s < r.models.size(); s += 2) costs[s] = calcMatchCosts(r.models[s - 1], r.models[s]);
  const auto a = trackModes(r.models, 1.4, 1), b = trackModes(r.models, 1.4, 2, costs);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].label, b[i].label);
    EXPECT_EQ(a[i].index, b[i].index);
  }
}

// A non-finite eigenvalue is an error naming the speed index, not a silent mis-assignment.
TEST(Modes, NonFiniteEigenvalueIsNamed) {
  SweepResult r = sweepEnduro();
  r.models[3].eigenvalues[2] = std::complex<double>(std::nan(""), 0);
  try {
    trackModes(r.models, 1.4, 1);
    FAIL() << "NaN must not be tracked";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("speed index 3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace motostab
