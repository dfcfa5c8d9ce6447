// Trim convergence with stiff tyres, crossings refined between grid speeds whose middle trims need the
// bracketing grid trims, and failed map points named with their residual (analysis/trim.h, sweep.h,
// turn_map.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "analysis/linearize.h"
#include "analysis/sweep.h"
#include "analysis/trim.h"
#include "analysis/turn_map.h"
#include "scenario/scenario.h"
#include "tests/support/contact_outputs.h"

namespace motostab::analysis {

using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

std::string scenarioPath(const std::string& name) { return std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/" + name + ".yaml"; }

// Sharp's (1971) machine at 4 m/s in a steady turn at a roll drawn in [15, 35] deg: its radial tyres (1e7
// N/m) put the residual's round-off floor above the absolute tolerance. The trim must converge, and be
// a steady turn of the vehicle checked here from the nonlinear model alone: every acceleration is the
// turn's centripetal one (xddot = -r ydot, yddot = r xdot, the rest zero) to 1e-8 of g / wheelbase (the
// scale of the gravity and tyre terms it balances, per rad or per m), both tyres carry load (an
// equilibrium with a wheel in the air has a zero residual too), and the rear contact point's path radius
// is within 25 % of the point-mass turn's V^2 / (g tan(roll)) (the mass centre, half a wheelbase ahead,
// runs on a wider circle: 6 % at 15 deg, 16 % at 35 deg).
TEST(TrimConvergence, SharpTurnAtFourMetresPerSecondIsASteadyTurn) {
  const VehicleModel model(loadScenario(scenarioPath("sharp1971")));
  std::mt19937 rng(1971);
  const double rollDeg = std::uniform_real_distribution<double>(15, 35)(rng);
  TrimOptions opt;
  opt.roll = rollDeg * M_PI / 180;
  const double v = 4;
  const TrimResult trim = calcTrim(model, v, opt);

  const SimTK::State& s = trim.state;
  model.getSystem().realize(s, SimTK::Stage::Acceleration);
  const auto& ix = model.getIndices();
  const SimTK::Vector& u = s.getU();
  const SimTK::Vector udot = s.getUDot();
  const double g = model.getScenario().gravity, L = model.getScenario().geometry.wheelbase;
  double worst = 0;
  for (int i = 0; i < s.getNU(); ++i) {
    double expected = 0;
    if (i == ix.x) expected = -u[ix.yaw] * u[ix.y];
    if (i == ix.y) expected = u[ix.yaw] * u[ix.x];
    worst = std::max(worst, std::abs(udot[i] - expected));
  }
  for (int i = 0; i < s.getNZ(); ++i) worst = std::max(worst, std::abs(s.getZDot()[i]));
  EXPECT_LT(worst, 1e-8 * g / L) << "roll " << rollDeg << " deg";

  EXPECT_GT(test::findContactOutput(model, s, "front_tyre_Fz_N"), 0);
  EXPECT_GT(test::findContactOutput(model, s, "rear_tyre_Fz_N"), 0);
  const double radius = calcTurnFigures(model, s).pathRadius;
  const double pointMass = v * v / (g * std::tan(opt.roll));
  EXPECT_NEAR(radius, pointMass, 0.25 * pointMass) << "roll " << rollDeg << " deg";
}

// The supersport-mf's weave stabilises between 4 and 6 m/s at 35 deg of roll; the predictor of the 4 m/s
// grid trim does not reach the speeds between, so the crossing is refined from the bracketing trims. It
// must be refined, and at the reported speed the root nearest the axis, from a cold trim and a
// linearisation done here, must have a real part within what the speed tolerance allows (its slope,
// measured here over +/-1e-4 m/s, times the tolerance, plus the trim's own noise), changing sign across it.
TEST(TrimConvergence, CrossingNeedingTheBracketingTrimsIsRefined) {
  const VehicleModel model(loadScenario(scenarioPath("supersport-mf")));
  SweepOptions opt;
  opt.trim.roll = 35 * M_PI / 180;
  opt.keepFailedSpeeds = true;
  const SweepResult sweep = runSweep(model, std::vector<double>{4, 6}, opt);
  ASSERT_TRUE(sweep.failures.empty());
  const CriticalSpeed* weave = nullptr;
  for (const auto& c : sweep.criticalSpeeds)
    if (c.mode == ModeLabel::Weave && c.speed > 4 && c.speed < 6) weave = &c;
  ASSERT_NE(weave, nullptr);
  EXPECT_TRUE(weave->refined);
  EXPECT_TRUE(weave->stabilising);

  // The real part of the eigenvalue nearest the weave's frequency at speed w, from a cold trim.
  auto weaveRealPart = [&](double w) {
    TrimResult t = calcTrim(model, w, opt.trim);
    const LinearModel lin = linearizeInPlace(model, t, opt.linearize);
    const double omega = 2 * M_PI * weave->frequency;
    Eigen::Index best = 0;
    for (Eigen::Index k = 1; k < lin.eigenvalues.size(); ++k)
      if (std::abs(std::abs(lin.eigenvalues[k].imag()) - omega) < std::abs(std::abs(lin.eigenvalues[best].imag()) - omega))
        best = k;
    return lin.eigenvalues[best].real();
  };
  const double h = 1e-4, below = weaveRealPart(weave->speed - h), above = weaveRealPart(weave->speed + h);
  EXPECT_GT(below, 0);
  EXPECT_LT(above, 0);
  const double slope = std::abs(above - below) / (2 * h);
  EXPECT_LT(std::abs(weaveRealPart(weave->speed)), slope * (opt.criticalSpeedTolerance + 1e-7));
}

// A map whose low-speed tight turns do not trim (the Whipple bicycle at 1 m/s and 20 or 30 deg): each
// failed point, and each roll none of whose speeds trimmed, is named with a finite residual, and no
// message says "nan" or "after 0 iterations".
TEST(TrimConvergence, FailedMapPointsNameAFiniteResidual) {
  const VehicleModel model(loadScenario(scenarioPath("whipple-benchmark")));
  TurnMapOptions opt;
  opt.sweep.start = 1, opt.sweep.stop = 2, opt.sweep.step = 1;
  opt.rolls = {0.0, 10 * M_PI / 180, 20 * M_PI / 180, 30 * M_PI / 180};
  const TurnMapResult map = runTurnMap(model, opt);
  size_t failed = 0;
  for (const auto& s : map.sweeps)
    for (const auto& f : s.failures) {
      ++failed;
      EXPECT_TRUE(std::isfinite(f.residual)) << f.message;
      EXPECT_GT(f.residual, 0) << f.message;
      EXPECT_EQ(f.message.find("nan"), std::string::npos) << f.message;
      EXPECT_EQ(f.message.find("after 0 iterations"), std::string::npos) << f.message;
    }
  for (const auto& r : map.failedRolls) {
    ++failed;
    EXPECT_EQ(r.message.find("nan"), std::string::npos) << r.message;
    EXPECT_EQ(r.message.find("after 0 iterations"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("residual norm"), std::string::npos) << r.message;
  }
  EXPECT_GT(failed, 0u);
  // A map none of whose points trim: the error carries the first failure's finite residual.
  TurnMapOptions none = opt;
  none.sweep.start = 1, none.sweep.stop = 1, none.sweep.step = 1;
  none.rolls = {30 * M_PI / 180};
  try {
    runTurnMap(model, none);
    ADD_FAILURE() << "the map trimmed";
  } catch (const TrimError& e) {
    EXPECT_TRUE(std::isfinite(e.residual)) << e.what();
    EXPECT_EQ(std::string(e.what()).find("nan"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace motostab::analysis
