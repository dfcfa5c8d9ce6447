// Grouped column evaluation of A in sweeps (Curtis, Powell & Reid 1974): the grouping from a known
// pattern, and sweeps with and without grouping agreeing on every eigenvalue, for a laterally
// symmetric motorcycle (many groups) and one with a tilted compliance axis (coupled, fewer groups).
// The reference is the column-by-column linearisation, which the Whipple benchmark tests validate.
#include <gtest/gtest.h>

#include <iostream>

#include "analysis/sweep.h"

namespace motostab::analysis {

using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

LinearModel makePatternModel(const Eigen::MatrixXd& A, const std::vector<Slot>& slots) {
  LinearModel m;
  m.A = A;
  for (size_t i = 0; i < slots.size(); ++i) m.states.push_back({"s" + std::to_string(i), {slots[i], static_cast<int>(i)}});
  return m;
}

// Two decoupled 2x2 blocks (states 0, 2 and 1, 3): each column of one block pairs with one of the other.
TEST(ColumnGrouping, DecoupledBlocksPairUp) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(4, 4);
  A(0, 0) = 1, A(0, 2) = 2, A(2, 0) = 3, A(2, 2) = 4;  // block a
  A(1, 1) = 5, A(1, 3) = 6, A(3, 1) = 7, A(3, 3) = 8;  // block b
  const LinearModel m = makePatternModel(A, {Slot::Q, Slot::Q, Slot::U, Slot::U});
  const ColumnGrouping g = calcColumnGrouping({&m});
  ASSERT_EQ(g.groups.size(), 2u);
  for (const auto& grp : g.groups) {
    ASSERT_EQ(grp.size(), 2u);
    EXPECT_NE(grp[0] % 2, grp[1] % 2) << "a group must take one column of each block";
  }
  // A tiny coupling below the tolerance keeps the pattern; one above it joins the blocks.
  Eigen::MatrixXd B = A;
  B(0, 1) = 1e-12;
  const LinearModel weak = makePatternModel(B, {Slot::Q, Slot::Q, Slot::U, Slot::U});
  EXPECT_EQ(calcColumnGrouping({&weak}).groups.size(), 2u);
  B = Eigen::MatrixXd::Constant(4, 4, 1.0);
  const LinearModel dense = makePatternModel(B, {Slot::Q, Slot::Q, Slot::U, Slot::U});
  EXPECT_TRUE(calcColumnGrouping({&dense}).groups.empty());
  EXPECT_TRUE(calcColumnGrouping({&m, &dense}).groups.empty()) << "the pattern is the union of the samples";
}

// Largest distance from an eigenvalue of `a` to the nearest of `b`, relative to max(1, |lambda|).
double calcEigenvalueDistance(const LinearModel& a, const LinearModel& b) {
  double worst = 0;
  for (int i = 0; i < a.eigenvalues.size(); ++i) {
    double best = 1e300;
    for (int j = 0; j < b.eigenvalues.size(); ++j) best = std::min(best, std::abs(a.eigenvalues[i] - b.eigenvalues[j]));
    worst = std::max(worst, best / std::max(1.0, std::abs(a.eigenvalues[i])));
  }
  return worst;
}

void expectGroupedSweepMatches(const std::vector<std::string>& sets, double start, bool expectGroups) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml", sets));
  SweepOptions opt;
  opt.start = start, opt.stop = 40, opt.step = 1;
  const SweepResult grouped = runSweep(model, opt);
  opt.groupColumns = false;
  const SweepResult single = runSweep(model, opt);
  ASSERT_EQ(grouped.models.size(), single.models.size());
  double worst = 0;
  for (size_t k = 0; k < grouped.models.size(); ++k)
    worst = std::max(worst, calcEigenvalueDistance(grouped.models[k], single.models[k]));
  const ColumnGrouping g = calcColumnGrouping({&single.models[1], &single.models.back()});
  size_t saved = 0;
  for (const auto& grp : g.groups) saved += grp.size() - 1;
  std::cout << sets.back() << ": " << g.groups.size() << " groups save " << saved << " of " << g.states.size()
            << " column evaluations; worst relative eigenvalue difference " << worst << "\n";
  // Both are second-order differences (step 3e-6); grouping adds cross third-derivative terms of the
  // same order (1.3e-9 against the fourth-order linearisation, column by column 1.7e-10).
  EXPECT_LT(worst, 5e-9);
  if (expectGroups) {
    EXPECT_GE(saved, 4u);
  }
  ASSERT_EQ(grouped.criticalSpeeds.size(), single.criticalSpeeds.size());
  for (size_t c = 0; c < grouped.criticalSpeeds.size(); ++c)
    EXPECT_NEAR(grouped.criticalSpeeds[c].speed, single.criticalSpeeds[c].speed, 1e-6);
}

TEST(ColumnGrouping, SymmetricMotorcycleSweepMatchesColumnByColumn) {
  expectGroupedSweepMatches({"swingarm.compliance=twist"}, 0, true);
}

TEST(ColumnGrouping, TiltedAxisSweepMatchesColumnByColumn) {
  expectGroupedSweepMatches({"swingarm.compliance=torsion",
                             "swingarm.torsion={point_m: [0.56, 0, 0.014], direction: [1, 0.2, 0], "
                             "stiffness_Nm_per_rad: 55200, damping_Nms_per_rad: 0.49}"},
                            1, false);  // asymmetric: no upright equilibrium at standstill
}

// The rows of removed coordinates (the Whipple bicycle's yaw, a dependent rate under the rolling
// constraints, from which diagnosis predicts a yaw-rate gyro; the cyclic coordinates' rates) agree
// with the column-by-column ones, with grouped columns (Whipple) and mirrored ones (enduro).
void expectRemovedRowsMatch(const std::string& scenario, double start, double stop) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/" + scenario));
  SweepOptions opt;
  opt.start = start, opt.stop = stop, opt.step = (stop - start) / 10;
  const SweepResult grouped = runSweep(model, opt);
  opt.groupColumns = false;
  const SweepResult single = runSweep(model, opt);
  ASSERT_EQ(grouped.models.size(), single.models.size());
  EXPECT_FALSE(calcColumnGrouping({&single.models[0], &single.models[1]}).groups.empty()) << "no column is grouped";
  for (size_t k = 0; k < grouped.models.size(); ++k) {
    const LinearModel &a = grouped.models[k], &b = single.models[k];
    ASSERT_EQ(a.removedRows.size(), b.removedRows.size());
    ASSERT_FALSE(b.removedRows.empty());
    for (size_t r = 0; r < b.removedRows.size(); ++r) {
      ASSERT_EQ(a.removedRows[r].first, b.removedRows[r].first);
      const Eigen::RowVectorXd &x = a.removedRows[r].second, &y = b.removedRows[r].second;
      EXPECT_LT((x - y).norm(), 1e-7 * std::max(1.0, y.norm())) << scenario << " row " << b.removedRows[r].first
                                                                << " at " << grouped.speeds[k] << " m/s";
    }
  }
}

TEST(ColumnGrouping, RemovedRowsMatchColumnByColumn) {
  expectRemovedRowsMatch("whipple-benchmark.yaml", 1, 8);
  expectRemovedRowsMatch("enduro.yaml", 5, 40);
}

}  // namespace
}  // namespace motostab::analysis
