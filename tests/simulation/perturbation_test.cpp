// Perturbation syntax: accepted forms and clear errors naming the spec.
#include <gtest/gtest.h>

#include "io/input_error.h"
#include "simulation/perturbation.h"
#include "simulation/simulation.h"

namespace motostab::simulation {

using io::InputError;

namespace {

TEST(SimulationPerturbation, ParsesEveryKind) {
  auto p = parsePerturbation("steer-torque:2.5:0.1:0.2");
  EXPECT_EQ(p.kind, PerturbationKind::SteerTorque);
  EXPECT_DOUBLE_EQ(p.amplitude, 2.5);
  EXPECT_DOUBLE_EQ(p.start, 0.1);
  EXPECT_DOUBLE_EQ(p.duration, 0.2);
  EXPECT_EQ(p.shape, PulseShape::Rectangular);
  EXPECT_DOUBLE_EQ(p.calcPulseValue(0.15), 2.5);

  p = parsePerturbation("steer-torque:-3:1:0.5:halfsine");
  EXPECT_EQ(p.shape, PulseShape::HalfSine);
  EXPECT_NEAR(p.calcPulseValue(1.25), -3.0, 1e-15);  // peak at mid-pulse
  EXPECT_NEAR(p.calcPulseValue(1.125), -3.0 * std::sqrt(0.5), 1e-14);

  p = parsePerturbation("lateral-force:front_frame:100:0.5:0.05");
  EXPECT_EQ(p.kind, PerturbationKind::LateralForce);
  EXPECT_EQ(p.body, "front_frame");
  EXPECT_DOUBLE_EQ(p.amplitude, 100);

  p = parsePerturbation("roll-rate:0.3");
  EXPECT_EQ(p.kind, PerturbationKind::RollRate);
  EXPECT_DOUBLE_EQ(p.amplitude, 0.3);
  p = parsePerturbation("steer-rate:-1e-3");
  EXPECT_EQ(p.kind, PerturbationKind::SteerRate);
  EXPECT_DOUBLE_EQ(p.amplitude, -1e-3);

  p = parsePerturbation("road-step:front_wheel:0.02:1");
  EXPECT_EQ(p.kind, PerturbationKind::RoadStep);
  EXPECT_EQ(p.body, "front_wheel");
  EXPECT_DOUBLE_EQ(p.amplitude, 0.02);
  EXPECT_DOUBLE_EQ(p.start, 1);
}

TEST(SimulationPerturbation, MalformedSpecsAreErrorsNamingTheSpec) {
  const std::vector<std::string> bad{
      "",                                    // empty
      "steer-torque",                        // no fields
      "steer-torque:1:0",                    // missing duration
      "steer-torque:abc:0:0.1",              // not a number
      "steer-torque:1:0:0.1:triangle",       // unknown shape
      "steer-torque:1:0:0",                  // zero duration
      "steer-torque:1:-1:0.1",               // negative start
      "steer-torque:1:0:0.1:halfsine:x",     // too many fields
      "lateral-force:handlebar:10:0:0.1",    // unknown body
      "lateral-force:rear_frame:10:0",       // missing duration
      "roll-rate",                           // missing value
      "roll-rate:0.1:2",                     // extra field
      "steer-rate:nan",                      // not finite
      "roll-rate:",                          // empty value
      "yaw-kick:1",                          // unknown kind
      "road-step:middle_wheel:0.01:1",       // unknown wheel
  };
  for (const auto& spec : bad) {
    try {
      parsePerturbation(spec);
      ADD_FAILURE() << "accepted '" << spec << "'";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("'" + spec + "'"), std::string::npos) << what;
      EXPECT_NE(what.find("--perturb"), std::string::npos) << what;
      EXPECT_NE(what.find("steer-torque:AMPLITUDE_Nm:START_s:DURATION_s"), std::string::npos) << what;
    }
  }
}

TEST(SimulationPerturbation, OptionNamesAreChecked) {
  EXPECT_EQ(parseIntegratorKind("rungekuttamerson"), IntegratorKind::RungeKuttaMerson);
  EXPECT_EQ(parseIntegratorKind("Auto"), IntegratorKind::Auto);
  EXPECT_EQ(parseIntegratorKind("ROS34PW2"), IntegratorKind::Rosenbrock);
  EXPECT_EQ(parseIntegratorKind("CPodes"), IntegratorKind::CPodes);
  EXPECT_EQ(parseIntegratorKind("rk3"), IntegratorKind::RungeKutta3);
  EXPECT_EQ(parseIntegratorKind("Verlet"), IntegratorKind::Verlet);
  EXPECT_THROW(parseIntegratorKind("euler"), InputError);
  EXPECT_EQ(parseSpeedControl("none"), SpeedControl::None);
  EXPECT_EQ(parseSpeedControl("PI"), SpeedControl::PI);
  EXPECT_THROW(parseSpeedControl("pid"), InputError);
}

}  // namespace
}  // namespace motostab::simulation
