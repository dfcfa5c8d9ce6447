// Steering damper (extensions/steer_damper.h, scenario `steer_damper`): against an independent linear
// model, the zero-damping limit, the linearised Coulomb friction, --set and malformed input.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/portable_random.h"
#include "extension_test_util.h"
#include "tests/support/benchmark_equations.h"
#include "extensions/steer_damper.h"

namespace motostab::extensions {

using analysis::SweepResult;
using core::PortableRandom;
using scenario::Scenario;
using scenario::loadScenario;


namespace {

using namespace motostab::testing;

// All eigenvalues at 0..10 m/s within 1e-8 (relative to max(1, |lambda|)); the model's one extra
// eigenvalue (forward speed) is zero.
void expectMatchesBenchmark(const Scenario& s, double c) {
  const Benchmark b = calcMeijaardMatrices(s);
  double worst = 0;
  for (int v = 0; v <= 10; ++v) {
    const Eigen::VectorXcd ref = Eigen::EigenSolver<Eigen::Matrix4d>(calcBenchmarkStateMatrix(b, s.gravity, v, 0, c)).eigenvalues();
    const Eigen::VectorXcd got = calcEigenvaluesAt(s, v);
    ASSERT_EQ(got.size(), 5);
    worst = std::max(worst, calcSpectrumDistance(ref, got));
    EXPECT_LT(calcSpectrumDistance(ref, got), 1e-8) << "v = " << v << "\nref " << ref.transpose() << "\ngot " << got.transpose();
    EXPECT_LT(calcSpectrumDistance(got, (Eigen::VectorXcd(5) << ref, cd(0)).finished()), 1e-8) << "v = " << v;
  }
  std::cout << "c = " << c << " N m s/rad: worst eigenvalue error against Meijaard M, C1, K0, K2 over 0-10 m/s: " << worst << "\n";
}

TEST(SteerDamper, BenchmarkBicycleMatchesMeijaardWithDampingInC) {
  Scenario s = loadScenario(kWhipple, {"steer_damper={damping_Nms_per_rad: 0.5}"});
  ASSERT_NE(scenario::findExtension(s, "steer_damper"), nullptr);
  expectMatchesBenchmark(s, 0.5);
}

// A randomly drawn bicycle (seeded): frame masses, rear-frame CoM and the damping vary.
TEST(SteerDamper, RandomBicycleMatchesMeijaard) {
  PortableRandom rng(20260410);
  Scenario s = loadScenario(kWhipple);
  s.rearFrame.mass *= rng.drawUniform(0.7, 1.3);
  s.rearFrame.com[0] *= rng.drawUniform(0.8, 1.2);
  s.rearFrame.com[2] *= rng.drawUniform(0.9, 1.1);
  s.frontFrame.mass *= rng.drawUniform(0.7, 1.3);
  s.geometry.trail *= rng.drawUniform(0.7, 1.3);
  const double c = rng.drawUniform(0.1, 2.0);
  setExtension(s, "steer_damper", "{damping_Nms_per_rad: " + io::formatNumber(c) + "}");
  expectMatchesBenchmark(s, c);
}

TEST(SteerDamper, ZeroDampingReproducesTheUndampedModel) {
  expectWhippleSpectrumKept(loadScenario(kWhipple, {"steer_damper={damping_Nms_per_rad: 0}"}));

  expectEnduroWeaveAndWobbleKept({"steer_damper={damping_Nms_per_rad: 0}"});
}

// Damping raises wobble damping on the enduro (Cossalter 2006 sec. 8.5; Sharp & Limebeer 2001).
TEST(SteerDamper, DampingStabilisesWobble) {
  const SweepResult a = runScenarioSweep(loadScenario(kEnduro), 20, 30, 10);
  const SweepResult b = runScenarioSweep(loadScenario(kEnduro, {"steer_damper={damping_Nms_per_rad: 10}"}), 20, 30, 10);
  for (size_t k : {0, 1}) EXPECT_LT(findLabelled(b, "wobble", k).real(), findLabelled(a, "wobble", k).real() - 0.5);
}

// Linearised, the smoothed friction f tanh(delta'/omega_s) is a viscous damper f/omega_s.
TEST(SteerDamper, LinearisedCoulombFrictionIsViscous) {
  PortableRandom rng(77);
  const double f = rng.drawUniform(0.05, 0.5), ws = rng.drawUniform(0.5, 5.0), c = rng.drawUniform(0.0, 1.0);
  const Scenario dry = loadScenario(kWhipple, {"steer_damper={damping_Nms_per_rad: " + std::to_string(c) +
                                                   ", coulomb_Nm: " + std::to_string(f) +
                                                   ", coulomb_smoothing_rad_per_s: " + std::to_string(ws) + "}"});
  io::YamlMap section = getExtensionSection(dry, "steer_damper");
  const SteerDamperParams p = readSteerDamper(section);
  ASSERT_NEAR(p.coulomb, f, 1e-6);
  Scenario viscous = loadScenario(kWhipple);
  setExtension(viscous, "steer_damper", "{damping_Nms_per_rad: " + io::formatNumber(p.damping + p.coulomb / p.coulombSmoothing) + "}");
  for (double v : {3.0, 6.0}) EXPECT_LT(calcSpectrumDistance(calcEigenvaluesAt(viscous, v), calcEigenvaluesAt(dry, v)), 1e-7);
  // The torque law itself, at a rate drawn at random.
  const double rate = rng.drawUniform(-3, 3);
  EXPECT_NEAR(calcSteerDamperTorque(p, rate), -p.damping * rate - p.coulomb * std::tanh(rate / p.coulombSmoothing), 1e-14);
}

TEST(SteerDamper, SetCreatesAndEditsTheSection) {
  const Scenario s = loadScenario(kWhipple, {"steer_damper={damping_Nms_per_rad: 0.4}", "steer_damper.coulomb_Nm=0.3"});
  io::YamlMap section = getExtensionSection(s, "steer_damper");
  const SteerDamperParams p = readSteerDamper(section);
  EXPECT_DOUBLE_EQ(p.damping, 0.4);
  EXPECT_DOUBLE_EQ(p.coulomb, 0.3);
  EXPECT_EQ(scenario::findExtension(loadScenario(kWhipple), "steer_damper"), nullptr);
}

TEST(SteerDamper, MalformedInputNamesFileLineColumnAndKey) {
  expectBadInputs(kWhipple, "steer_damper_bad",
                  {
                      {"steer_damper:\n  damping_Nms_per_rad: -0.5\n", 3, "steer_damper.damping_Nms_per_rad"},
                      {"steer_damper:\n  damping_Nms_per_rad: .nan\n", 3, "steer_damper.damping_Nms_per_rad"},
                      {"steer_damper:\n  damping_Nms_per_rad: [1]\n", 3, "steer_damper.damping_Nms_per_rad"},
                      {"steer_damper:\n  damping_Nms_per_rad: soft\n", 3, "steer_damper.damping_Nms_per_rad"},
                      {"steer_damper:\n  damping_Nms_per_rad: 1\n  damping: 0.5\n", 3, "steer_damper.damping"},
                      {"steer_damper:\n  coulomb_Nm: 1\n", 3, "steer_damper"},  // missing damping: at the map
                      {"steer_damper:\n  damping_Nms_per_rad: 1\n  coulomb_Nm: -1\n", 3, "steer_damper.coulomb_Nm"},
                      {"steer_damper:\n  damping_Nms_per_rad: 1\n  coulomb_smoothing_rad_per_s: 0\n", 3,
                       "steer_damper.coulomb_smoothing_rad_per_s"},
                      {"steer_damper: 0.5\n", 1, "steer_damper"},
                  });
}

}  // namespace
}  // namespace motostab::extensions
