// Steer controller in the time domain (extensions/steer_controller.h): a saturating torque limit holds
// the applied torque at the limit, and the energy budget closes: with rolling constraints, no drag
// and no speed control, the kinetic plus gravitational energy changes by exactly the controller's
// work, the integral of T steer_rate (the steer pin's power), with T recomputed in the test from the
// law and the sampled states.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include <unsupported/Eigen/MatrixFunctions>

#include "io/csv.h"
#include "core/portable_random.h"
#include "analysis/linearize.h"
#include "simulation/simulation.h"
#include "tests/simulation/linear_reference.h"

namespace motostab::simulation {

using analysis::LinearModel;
using core::PortableRandom;
using io::formatNumber;
using scenario::Scenario;
using scenario::loadScenario;

namespace {

const std::string kWhipple = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

TEST(SteerControllerSimulation, SaturatedTorqueAndEnergyBudget) {
  PortableRandom rng(31337);
  const double k = rng.drawUniform(-40, -30);    // N m s/rad, into the fall: stabilises weave at 3 m/s
  const double limit = rng.drawUniform(1.5, 2.5);  // N m: the kick's command k * 0.3 is far above it
  const Scenario s = loadScenario(kWhipple, {"steer_controller={roll_rate_Nms_per_rad: " + formatNumber(k) +
                                             ", torque_limit_Nm: " + formatNumber(limit) + "}"});
  SimulationOptions o;
  o.speed = 3;
  o.duration = 3;
  o.outputStep = 0.0005;
  o.speedControl = SpeedControl::None;
  o.accuracy = 1e-9;
  o.perturbations = {parsePerturbation("roll-rate:0.3")};
  const SimulationResult r = runSimulation(s, o);
  ASSERT_EQ(r.status, SimulationStatus::Completed) << r.message;
  const int cT = r.getColumnIndex("steer_controller_torque"), cRoll = r.getColumnIndex("roll_rate"),
            cSteer = r.getColumnIndex("steer_rate"), cE = r.getColumnIndex("energy");
  int saturated = 0;
  double work = 0, maxT = 0;
  for (size_t i = 0; i < r.rows.size(); ++i) {
    const double law = std::clamp(k * r.rows[i][cRoll], -limit, limit);  // the law, written here
    EXPECT_NEAR(r.rows[i][cT], law, 1e-12) << "t = " << r.rows[i][0];
    saturated += std::abs(law) == limit;
    maxT = std::max(maxT, std::abs(r.rows[i][cT]));
    if (i > 0) {  // trapezoidal rule over the samples
      const double p0 = std::clamp(k * r.rows[i - 1][cRoll], -limit, limit) * r.rows[i - 1][cSteer];
      const double p1 = law * r.rows[i][cSteer];
      work += 0.5 * (p0 + p1) * (r.rows[i][0] - r.rows[i - 1][0]);
    }
  }
  const double dE = r.rows.back()[cE] - r.rows.front()[cE];
  std::cout << "gain " << k << " N m s/rad, limit " << limit << " N m: " << saturated << " of " << r.rows.size()
            << " samples at the limit; energy change " << dE << " J, controller work " << work << " J, difference "
            << dE - work << " J\n";
  EXPECT_EQ(maxT, limit);
  EXPECT_GT(saturated, 50);                      // the limit is reached and held
  EXPECT_GT(std::abs(work), 1e-2);               // the controller does work
  EXPECT_LT(std::abs(dE - work), 1e-5 * std::abs(work));  // measured 3e-7
}

// With every other extension (enduro: relaxation tyres, swingarm; steer damper, fork bending and
// torsion, rider lean) and a delayed, scheduled full-state controller, a small perturbation follows
// exp(A t) x0 of the linearisation, whose states include the delay's z: the force element, the trim
// of z and the linearisation agree in the time domain.
TEST(SteerControllerSimulation, WithEveryExtensionSmallPerturbationFollowsTheLinearModel) {
  PortableRandom rng(8080);
  const std::string controller =
      "steer_controller={roll_angle_Nm_per_rad: " + formatNumber(rng.drawUniform(-60, -20)) +
      ", roll_rate_Nms_per_rad: " + formatNumber(rng.drawUniform(-20, -5)) + ", steer_rate_Nms_per_rad: " +
      formatNumber(rng.drawUniform(-3, 0)) + ", delay_s: " + formatNumber(rng.drawUniform(0.02, 0.06)) +
      ", torque_limit_Nm: 50, schedule: {table: [[5, 1.5], [30, 0.5]]}}";
  const Scenario s = loadScenario(
      std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml",
      {controller, "steer_damper={damping_Nms_per_rad: 5}",
       "fork_compliance={stiffness_Nm_per_rad: 40000, damping_Nms_per_rad: 20, "
       "torsion: {stiffness_Nm_per_rad: 60000, damping_Nms_per_rad: 10}}",
       "rider_lean={hinge_height_m: 0.75, mass_kg: 40, com_m: [0.45, 0, 1.05], "
       "inertia_kgm2: {xx: 2.0, yy: 2.1, zz: 0.7, xy: 0, xz: 0, yz: 0}, stiffness_Nm_per_rad: 2000, damping_Nms_per_rad: 60}"});
  const double v = 15;
  const LinearModel lin = linearizeScenarioAt(s, v);
  ASSERT_GE(lin.findState("steer_controller_delay"), 0);
  const SimulationResult r = runSimulation(s, makeSmallRateKick(v, 1e-10));
  ASSERT_EQ(r.status, SimulationStatus::Completed) << r.message;
  const Eigen::VectorXd x0 = readInitialDeviation(r, lin);
  for (const std::string name : {"roll", "steer", "steer_controller_delay"}) {
    double maxRef = 0;
    const double rel = calcRelativeDeviationFromLinear(r, lin, x0, name, maxRef);
    std::cout << controller << " on the extended enduro at " << v << " m/s, " << name
              << ": max |nonlinear - linear| / max |linear| = " << rel << "\n";
    EXPECT_LT(rel, 1e-4) << name;
  }
}

}  // namespace
}  // namespace motostab::simulation
