// Steady turns on tyres (relaxation_linear: camber thrust, slip, crown radius, load transfer): thin,
// stiff tyres tend to rolling without slip, and the bundled motorcycles trim across roll and speed.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "analysis/linearize.h"
#include "analysis/trim.h"
#include "scenario/scenario.h"

namespace motostab::analysis {

using scenario::loadScenario;
using vehicle::CoordinateIndices;
using vehicle::Input;
using vehicle::VehicleModel;

namespace {

const std::string kScenarios = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/";

// Knife-edge tyres on the benchmark bicycle whose slip, deflection and moment stiffnesses scale with
// `stiffness`: cornering k_alpha = 15 s /rad, longitudinal 20 s, radial 1e5 s N/m, no camber thrust,
// no moments, no lag. Slips and deflection, hence every difference from rolling without slip, go as 1/s.
std::string makeStiffTyres(double s) {
  std::ostringstream tyre;
  tyre << "{cornering_stiffness_per_rad: " << 15 * s << ", camber_stiffness_per_rad: 0, self_aligning_stiffness_m_per_rad: 0, "
       << "twisting_stiffness_m_per_rad: 0, relaxation_length_m: 0, radial_stiffness_N_per_m: " << 1e5 * s
       << ", radial_damping_Ns_per_m: 100, longitudinal_stiffness: " << 20 * s << "}";
  return "contact={model: relaxation_linear, front: " + tyre.str() + ", rear: " + tyre.str() + "}";
}

TEST(MotorcycleTurn, ThinStiffTyresTendToRollingWithoutSlip) {
  TrimOptions opt;
  opt.roll = 0.3;
  opt.tolerance = 1e-8;  // radial stiffness up to 1e9 N/m: force round-off alone is about 1e-10 m/s^2 per 1e-16 m
  const double v = 5.0;
  const VehicleModel noSlip(loadScenario(kScenarios + "whipple-benchmark.yaml"));
  const TrimResult ref = calcTrim(noSlip, v, opt);
  const CoordinateIndices& ix = noSlip.getIndices();
  const double steer0 = ref.state.getQ()[ix.steer], torque0 = noSlip.getInput(ref.state, Input::SteerTorque);
  const double yawRate0 = ref.state.getU()[ix.yaw];
  double lastError = NAN;
  for (double s : {1e1, 1e2, 1e3}) {
    const VehicleModel tyres(loadScenario(kScenarios + "whipple-benchmark.yaml", {makeStiffTyres(s)}));
    const TrimResult t = calcTrim(tyres, v, opt);
    const double error = std::max({std::abs(t.state.getQ()[ix.steer] - steer0) / std::abs(steer0),
                                   std::abs(tyres.getInput(t.state, Input::SteerTorque) - torque0) / std::abs(torque0),
                                   std::abs(t.state.getU()[ix.yaw] - yawRate0) / std::abs(yawRate0)});
    std::printf("tyre stiffness x%g: largest relative difference from rolling without slip %.3g\n", s, error);
    if (!std::isnan(lastError)) {
      EXPECT_NEAR(error / lastError, 0.1, 0.03) << "stiffness x" << s;
    }
    lastError = error;
  }
  EXPECT_LT(lastError, 1e-3);
}

// Both motorcycles trim from 5 to 45 deg of roll at 10 to 60 m/s, and the turn is what the tyres
// make of it: a right lean turns right, and the wide tyres' contact moving round the crown calls for
// more lean than the point-mass turn tan(roll) = a / g (lateral acceleration below g tan(roll)).
TEST(MotorcycleTurn, EnduroAndSupersportTrimAcrossRollAndSpeed) {
  for (const std::string scenario : {"enduro.yaml", "supersport.yaml"}) {
    const VehicleModel model(loadScenario(kScenarios + scenario));
    for (double rollDeg : {5.0, 25.0, 45.0}) {
      TrimOptions opt;
      opt.roll = rollDeg * M_PI / 180;
      TrimResult t;
      for (double v : {10.0, 35.0, 60.0}) {
        if (v == 10.0) t = calcTrim(model, v, opt);
        else updTrim(model, v, opt, t);
        EXPECT_LT(t.residualNorm, 1e-10) << scenario << " " << rollDeg << " deg " << v << " m/s";
        const TurnFigures f = calcTurnFigures(model, t.state);
        EXPECT_NEAR(f.speed, v, 1e-9);
        EXPECT_LT(f.yawRate, 0);
        const double pointMass = model.getScenario().gravity * std::tan(opt.roll);
        EXPECT_GT(-f.lateralAcceleration, 0.6 * pointMass) << scenario << " " << rollDeg << " deg " << v << " m/s";
        EXPECT_LT(-f.lateralAcceleration, pointMass) << scenario << " " << rollDeg << " deg " << v << " m/s";
      }
    }
  }
}

// Every model extension at once (steer damper, fork bending and torsion, leaning rider, swingarm twist
// compliance, rear suspension): the turn trims with no extension-specific code, and the zero-roll turn
// keeps the eigenvalues of straight running to 1e-9.
TEST(MotorcycleTurn, TurnsWorkWithEveryModelExtension) {
  const VehicleModel model(loadScenario(
      kScenarios + "enduro.yaml",
      {"steer_damper={damping_Nms_per_rad: 5}",
       "fork_compliance={stiffness_Nm_per_rad: 40000, damping_Nms_per_rad: 20, "
       "torsion: {stiffness_Nm_per_rad: 60000, damping_Nms_per_rad: 10}}",
       "rider_lean={hinge_height_m: 0.75, mass_kg: 40, com_m: [0.45, 0, 1.05], "
       "inertia_kgm2: {xx: 2.0, yy: 2.1, zz: 0.7, xy: 0, xz: 0, yz: 0}, stiffness_Nm_per_rad: 2000, damping_Nms_per_rad: 60}",
       "swingarm.compliance=twist", "swingarm.suspension={wheel_rate_N_per_m: 30000, damping_Ns_per_m: 1500}"}));
  TrimOptions opt;
  opt.roll = 35 * M_PI / 180;
  const TrimResult t = calcTrim(model, 30, opt);
  EXPECT_LT(t.residualNorm, 1e-10);
  EXPECT_LT(calcTurnFigures(model, t.state).yawRate, 0);
  opt.roll = 0;
  const LinearModel inTurn = linearize(model, calcTrim(model, 30, opt));
  const LinearModel upright = linearize(model, calcTrim(model, 30));
  int compared = 0;
  for (int i = 0; i < inTurn.eigenvalues.size(); ++i) {
    if (std::abs(inTurn.eigenvalues[i]) < 1e-3) continue;
    double best = INFINITY;
    for (int j = 0; j < upright.eigenvalues.size(); ++j)
      best = std::min(best, std::abs(inTurn.eigenvalues[i] - upright.eigenvalues[j]) / (1 + std::abs(inTurn.eigenvalues[i])));
    EXPECT_LT(best, 1e-9) << inTurn.eigenvalues[i];
    ++compared;
  }
  EXPECT_GT(compared, 20);
}

}  // namespace
}  // namespace motostab::analysis
