// simulate with every model extension present (steer_damper, fork_compliance with
// torsion, rider_lean; enduro tyres): small perturbations follow the linearisation exp(A t) x0 (computed
// independently of the integration path), the extension coordinates are output by name, and a
// steer-torque pulse acts between front frame and rear frame (not on the fork's hub carrier).
#include <gtest/gtest.h>

#include <unsupported/Eigen/MatrixFunctions>

#include <iostream>

#include "analysis/linearize.h"
#include "simulation/simulation.h"
#include "tests/simulation/linear_reference.h"

namespace motostab::simulation {

using analysis::LinearModel;
using scenario::Scenario;
using scenario::loadScenario;

namespace {

const Scenario& getExtendedEnduro() {
  static const Scenario s = loadScenario(
      std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml",
      {"steer_damper={damping_Nms_per_rad: 5}",
       "fork_compliance={stiffness_Nm_per_rad: 40000, damping_Nms_per_rad: 20, "
       "torsion: {stiffness_Nm_per_rad: 60000, damping_Nms_per_rad: 10}}",
       "rider_lean={hinge_height_m: 0.75, mass_kg: 40, com_m: [0.45, 0, 1.05], "
       "inertia_kgm2: {xx: 2.0, yy: 2.1, zz: 0.7, xy: 0, xz: 0, yz: 0}, stiffness_Nm_per_rad: 2000, damping_Nms_per_rad: 60}"});
  return s;
}

TEST(SimulationExtensions, SmallPerturbationFollowsMatrixExponential) {
  for (double v : {10.0, 25.0}) {
    const LinearModel lin = linearizeScenarioAt(getExtendedEnduro(), v);
    const SimulationResult r = runSimulation(getExtendedEnduro(), makeSmallRateKick(v, 1e-10));
    ASSERT_EQ(r.status, SimulationStatus::Completed) << r.message;
    const Eigen::VectorXd x0 = readInitialDeviation(r, lin);
    for (const std::string name : {"roll", "steer", "rider_lean", "fork_bending", "fork_torsion"}) {
      ASSERT_GE(lin.findState(name), 0) << name;
      ASSERT_GE(r.getColumnIndex(name), 0) << name;
      double maxRef = 0;
      const double rel = calcRelativeDeviationFromLinear(r, lin, x0, name, maxRef);
      std::cout << "extended enduro v = " << v << " m/s, " << name << ": max |nonlinear - linear| / max |linear| = " << rel
                << " (max |linear| " << maxRef << ")\n";
      // The fork angles are tiny (1e-7 rad and below): the integrator's absolute floor bounds them.
      EXPECT_LT(rel, name.rfind("fork", 0) == 0 ? 1e-2 : 1e-4) << "v = " << v << ", " << name;
    }
  }
}

// A steer torque pulse acts on the steer coordinate: the steer response's sign follows the torque's
// in the first instants (front frame turns relative to the rear frame), and the run completes.
TEST(SimulationExtensions, SteerTorquePulseActsOnTheSteerAxis) {
  SimulationOptions o;
  o.speed = 20;
  o.duration = 0.3;
  o.outputStep = 0.005;
  o.perturbations = {parsePerturbation("steer-torque:2:0.02:0.05:rect")};
  const SimulationResult r = runSimulation(getExtendedEnduro(), o);
  ASSERT_EQ(r.status, SimulationStatus::Completed) << r.message;
  const int steer = r.getColumnIndex("steer"), torque = r.getColumnIndex("steer_torque");
  ASSERT_GE(steer, 0);
  ASSERT_GE(torque, 0);
  ASSERT_NEAR(r.rows[10][0], 0.05, 1e-12);
  EXPECT_GT(r.rows[10][steer] - r.trimRow[steer], 0);  // 30 ms into a +2 N m pulse: steered left
  EXPECT_NEAR(r.rows[10][torque] - r.trimRow[torque], 2.0, 1e-9);
}

}  // namespace
}  // namespace motostab::simulation
