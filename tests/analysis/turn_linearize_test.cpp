// Linearisation about a steady turn (heading-frame velocities, analysis/linearize.h): a turn at zero
// roll is straight running, and yaw is cyclic in the heading frame. The turn's eigenvalues are checked
// against nonlinear simulation in tests/simulation/turn_simulation_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/linearize.h"
#include "core/portable_random.h"
#include "scenario/scenario.h"

namespace motostab::analysis {

using core::PortableRandom;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

const std::string kScenarios = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/";

// Each eigenvalue of `a` away from zero (|lambda| > 1e-3 1/s) has one in `b` within tol (1 + |lambda|).
double calcWorstEigenvalueMismatch(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) {
  double worst = 0;
  int compared = 0;
  for (int i = 0; i < a.size(); ++i) {
    if (std::abs(a[i]) < 1e-3) continue;
    double best = INFINITY;
    for (int j = 0; j < b.size(); ++j) best = std::min(best, std::abs(a[i] - b[j]) / (1 + std::abs(a[i])));
    worst = std::max(worst, best);
    ++compared;
  }
  EXPECT_GE(compared, 4);
  return worst;
}

// The zero-roll turn (heading frame, yaw removed as cyclic, TurnCondition::Speed) has the eigenvalues
// of straight running (ground frame) at the same speed, for the Whipple bicycle (rolling constraints)
// and the enduro (tyres: the heading frame's -V r term replaces the ground frame's yaw column).
TEST(LinearizeTurn, ZeroRollTurnEqualsUprightRunning) {
  PortableRandom rng(1207);
  for (const std::string scenario : {"whipple-benchmark.yaml", "enduro.yaml"}) {
    const VehicleModel model(loadScenario(kScenarios + scenario));
    const double v = scenario[0] == 'w' ? rng.drawUniform(2, 8) : rng.drawUniform(5, 50);
    const LinearModel upright = linearize(model, calcTrim(model, v));
    TrimOptions turn;
    turn.roll = 0;
    const TrimResult t = calcTrim(model, v, turn);
    ASSERT_TRUE(t.turn);
    const LinearModel inTurn = linearize(model, t);
    EXPECT_TRUE(inTurn.headingFrame);
    EXPECT_LT(inTurn.findState("yaw"), 0);
    const double worst = std::max(calcWorstEigenvalueMismatch(inTurn.eigenvalues, upright.eigenvalues),
                                  calcWorstEigenvalueMismatch(upright.eigenvalues, inTurn.eigenvalues));
    std::printf("%s at %.3f m/s: worst eigenvalue mismatch %.3g\n", scenario.c_str(), v, worst);
    EXPECT_LT(worst, 1e-9) << scenario;
  }
}

// In a turn the heading frame makes yaw cyclic: its column (yaw turned together with the ground-frame
// velocity, d(v_h)'/d psi = -J a_G) vanishes although every ground-frame term in it is of order r V.
TEST(LinearizeTurn, YawColumnVanishesInTheHeadingFrame) {
  for (const std::string scenario : {"whipple-benchmark.yaml", "enduro.yaml"}) {
    const VehicleModel model(loadScenario(kScenarios + scenario));
    TrimOptions turn;
    turn.roll = 0.4;
    const LinearModel lin = linearize(model, calcTrim(model, scenario[0] == 'w' ? 6.0 : 25.0, turn));
    bool found = false;
    for (const auto& [name, column] : lin.removedColumns)
      if (name == "yaw") {
        found = true;
        EXPECT_LT(column.lpNorm<Eigen::Infinity>(), 1e-7 * lin.A.lpNorm<Eigen::Infinity>()) << scenario;
      }
    EXPECT_TRUE(found) << scenario;
  }
}

}  // namespace
}  // namespace motostab::analysis
