// Steer-head friction (extensions/steer_head_friction.h, scenario `steer_head_friction`), the worked
// example of a model extension: linearised it is a viscous steer damper T_f/omega_s, checked against
// Meijaard et al. (2007) with that damping added to the steer entry of C (tests/support); the torque
// law at a drawn rate; malformed input.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/portable_random.h"
#include "extension_test_util.h"
#include "extensions/steer_head_friction.h"
#include "tests/support/benchmark_equations.h"

namespace motostab::extensions {

using core::PortableRandom;
using io::formatNumber;
using scenario::Scenario;
using scenario::loadScenario;

namespace {

using namespace motostab::testing;

TEST(SteerHeadFriction, LinearisedItIsTheViscousDamperTorqueOverSmoothing) {
  PortableRandom rng(8128);
  const double tf = rng.drawUniform(0.1, 1.5), ws = rng.drawUniform(0.3, 3.0);
  const Scenario s = loadScenario(kWhipple, {"steer_head_friction={torque_Nm: " + formatNumber(tf) +
                                             ", smoothing_rad_per_s: " + formatNumber(ws) + "}"});
  const Benchmark b = calcMeijaardMatrices(s);
  double worst = 0;
  for (double v : {1.0, 3.0, 5.0, 7.0}) {
    const Eigen::VectorXcd ref = Eigen::EigenSolver<Eigen::Matrix4d>(calcBenchmarkStateMatrix(b, s.gravity, v, 0, tf / ws)).eigenvalues();
    const Eigen::VectorXcd got = calcEigenvaluesAt(s, v);
    worst = std::max(worst, calcSpectrumDistance(ref, got));
    EXPECT_LT(calcSpectrumDistance(ref, got), 1e-7) << "v = " << v << "\nref " << ref.transpose() << "\ngot " << got.transpose();
  }
  std::cout << "T_f " << tf << " N m, omega_s " << ws << " rad/s: worst eigenvalue error against Meijaard with c = T_f/omega_s "
            << worst << "\n";
}

TEST(SteerHeadFriction, TorqueLawAndDefaults) {
  PortableRandom rng(31);
  const double tf = rng.drawUniform(0.1, 2), rate = rng.drawUniform(-2, 2);
  const Scenario s = loadScenario(kWhipple, {"steer_head_friction={torque_Nm: " + formatNumber(tf) + "}"});
  io::YamlMap section = getExtensionSection(s, "steer_head_friction");
  const SteerHeadFrictionParams p = readSteerHeadFriction(section);
  EXPECT_EQ(p.smoothing, 0.1);  // the documented default
  EXPECT_NEAR(calcSteerHeadFrictionTorque(p, rate), -p.torque * std::tanh(rate / 0.1), 1e-14);
  EXPECT_EQ(calcSteerHeadFrictionTorque(p, 0), 0);
  const vehicle::VehicleModel model(s);  // no state of its own
  EXPECT_EQ(model.getNumZ(), 0);
}

TEST(SteerHeadFriction, MalformedInputNamesFileLineColumnAndKey) {
  expectBadInputs(kWhipple, "steer_head_friction_bad",
                  {{"steer_head_friction:\n  torque_Nm: -0.5\n", 3, "steer_head_friction.torque_Nm"},
                   {"steer_head_friction:\n  torque_Nm: 0.5\n  smoothing_rad_per_s: 0\n", 3, "steer_head_friction.smoothing_rad_per_s"},
                   {"steer_head_friction:\n  torque_Nm: 0.5\n  preload: 3\n", 3, "steer_head_friction.preload"},
                   {"steer_head_friction:\n  smoothing_rad_per_s: 1\n", 3, "steer_head_friction"}});
}

}  // namespace
}  // namespace motostab::extensions
