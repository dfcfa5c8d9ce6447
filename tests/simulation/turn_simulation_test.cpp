// Simulation from a steady turn (SimulationOptions::trim.roll) against the linearisation about the
// turn: the nonlinear model, integrated in ground-frame coordinates, checks the heading-frame linear
// model (analysis/linearize.h) independently of its chain rule.
#include <gtest/gtest.h>

#include <iostream>

#include "analysis/linearize.h"
#include "simulation/simulation.h"
#include "tests/simulation/linear_reference.h"

namespace motostab::simulation {

using analysis::LinearModel;
using analysis::TrimOptions;
using analysis::calcTrim;
using analysis::linearize;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

// Small roll- and steer-rate kicks from turns of the Whipple bicycle (rolling constraints) and of the
// enduro (relaxation tyres): roll and steer follow exp(A t) x0 of the turn's linear model over 2 s.
// A still-steady run (no kick) stays on the trim, which checks that the trim is a steady turn.
TEST(TurnSimulation, SmallPerturbationFollowsTheTurnsLinearModel) {
  struct Case {
    std::string scenario;
    double speed, roll, accuracy, tolerance;
  };
  for (const Case& c : {Case{"whipple-benchmark.yaml", 5.5, 0.3, 1e-11, 2e-4}, Case{"enduro.yaml", 25.0, 0.6, 1e-9, 5e-4}}) {
    const Scenario scenario = loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/" + c.scenario);
    const VehicleModel model(scenario);
    TrimOptions turn;
    turn.roll = c.roll;
    const LinearModel lin = linearize(model, calcTrim(model, c.speed, turn));
    SimulationOptions o = makeSmallRateKick(c.speed, c.accuracy);
    o.trim = turn;
    const SimulationResult r = runSimulation(scenario, o);
    ASSERT_EQ(r.status, SimulationStatus::Completed) << r.message;
    const Eigen::VectorXd x0 = readInitialDeviation(r, lin);
    ASSERT_NEAR(x0[lin.findState("roll_rate")], 1e-4, 1e-12);
    for (const std::string name : {"roll", "steer"}) {
      double maxRef = 0;
      const double rel = calcRelativeDeviationFromLinear(r, lin, x0, name, maxRef);
      std::cout << c.scenario << " at " << c.speed << " m/s, roll " << c.roll << " rad, " << name
                << ": max |nonlinear - linear| / max |linear| = " << rel << " (max |linear| " << maxRef << ")\n";
      EXPECT_LT(rel, c.tolerance) << c.scenario << ", " << name;
    }
  }
}

}  // namespace
}  // namespace motostab::simulation
