#include <gtest/gtest.h>

#include <complex>
#include <vector>

#include "analysis/sweep.h"
#include "io/result_error.h"
#include "scenario/scenario.h"

namespace motostab::analysis {

using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

SweepResult sweepEnduro() {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml", {"swingarm.compliance=twist"}));
  SweepOptions opt;
  opt.start = 10, opt.stop = 14, opt.step = 1;
  return runSweep(model, opt);
}

// Modal assurance criterion written out here (Allemang 2003, Sound Vib. 37(8):14, eq. 1):
// |a^H b|^2 / (|a|^2 |b|^2), states matched by name.
double calcMacHere(const LinearModel& a, int ka, const LinearModel& b, int kb) {
  std::complex<double> dot = 0;
  double na = 0, nb = 0;
  for (size_t i = 0; i < a.states.size(); ++i) {
    const int j = b.findState(a.states[i].name);
    if (j < 0) continue;
    dot += std::conj(a.eigenvectors(i, ka)) * b.eigenvectors(j, kb);
    na += std::norm(a.eigenvectors(i, ka)), nb += std::norm(b.eigenvectors(j, kb));
  }
  return std::norm(dot) / (na * nb);
}

// The batched cost matrix equals calcMatchCost entry by entry, its MAC equals the one written out
// above, a model matched with itself costs zero on the diagonal and more elsewhere, and the tracked
// branches pair the eigenvalues of consecutive speeds one-to-one.
TEST(Modes, MatchCostMatrixEqualsPairwiseCosts) {
  const SweepResult r = sweepEnduro();
  const LinearModel &a = r.models[1], &b = r.models[2];
  const Eigen::MatrixXd c = calcMatchCosts(a, b);
  ASSERT_EQ(c.rows(), a.eigenvalues.size());
  ASSERT_EQ(c.cols(), b.eigenvalues.size());
  for (int i = 0; i < c.rows(); ++i)
    for (int j = 0; j < c.cols(); ++j) {
      EXPECT_NEAR(c(i, j), calcMatchCost(a, i, b, j), 1e-12) << i << " " << j;
      const double mac = calcMacHere(a, i, b, j);
      EXPECT_NEAR(calcMac(a, i, b, j), mac, 1e-12) << i << " " << j;
      EXPECT_GE(mac, -1e-15);
      EXPECT_LE(mac, 1 + 1e-12);
      EXPECT_NEAR(calcMac(b, j, a, i), mac, 1e-12);  // symmetric
    }
  const Eigen::MatrixXd self = calcMatchCosts(b, b);
  for (int i = 0; i < self.rows(); ++i) {
    EXPECT_NEAR(self(i, i), 0.0, 1e-12) << i;
    for (int j = 0; j < self.cols(); ++j)
      if (std::abs(b.eigenvalues[i] - b.eigenvalues[j]) > 1e-6) {
        EXPECT_GT(self(i, j), 0.0) << i << " " << j;
      }
  }
  // Tracking: every eigenvalue of every speed belongs to exactly one branch.
  ASSERT_EQ(r.branches.size(), static_cast<size_t>(a.eigenvalues.size()));
  for (size_t k = 0; k < r.models.size(); ++k) {
    std::vector<int> used(r.models[k].eigenvalues.size(), 0);
    for (const auto& br : r.branches) {
      ASSERT_GE(br.index[k], 0);
      ++used[br.index[k]];
      EXPECT_EQ(br.eigenvalue[k], r.models[k].eigenvalues[br.index[k]]);
    }
    for (int u : used) EXPECT_EQ(u, 1) << "speed index " << k;
  }
}

// Costs handed in (as sweep workers do) give the same branches as costs computed inside.
TEST(Modes, PrecomputedCostsGiveTheSameBranches) {
  const SweepResult r = sweepEnduro();
  std::vector<Eigen::MatrixXd> costs(r.models.size());
  for (size_t s = 1; s < r.models.size(); s += 2) costs[s] = calcMatchCosts(r.models[s - 1], r.models[s]);
  const auto a = trackModes(r.models, 1), b = trackModes(r.models, 2, costs);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].label, b[i].label);
    EXPECT_EQ(a[i].index, b[i].index);
  }
}

// A non-finite eigenvalue is an error naming the speed index, not a silent mis-assignment: a result
// that could not be computed (ResultError, exit code 3), not a bug.
TEST(Modes, NonFiniteEigenvalueIsNamed) {
  SweepResult r = sweepEnduro();
  r.models[3].eigenvalues[2] = std::complex<double>(std::nan(""), 0);
  try {
    trackModes(r.models, 1);
    FAIL() << "NaN must not be tracked";
  } catch (const io::ResultError& e) {
    EXPECT_NE(std::string(e.what()).find("speed index 3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace motostab::analysis
