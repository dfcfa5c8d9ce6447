// The rider's arms on the handlebar (extensions/rider_arms.h, scenario `rider_arms`): the grip masses
// keep the totals and add J_a about the steer axis (computed here), the linear model against
// Meijaard's equations with k_a and c_a in the steer entries, and malformed input.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/portable_random.h"
#include "extension_test_util.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "tests/support/benchmark_equations.h"
#include "scenario/whole_vehicle.h"
#include "extensions/rider_arms.h"
#include "plugins/plugin_registry.h"

namespace motostab::extensions {

using core::PortableRandom;
using scenario::BodySpec;
using scenario::Scenario;
using scenario::loadScenario;

namespace {

using namespace motostab::testing;

std::string arms(double J, double k, double c) {
  return "rider_arms={inertia_kgm2: " + io::formatNumber(J) + ", stiffness_Nm_per_rad: " + io::formatNumber(k) +
         ", damping_Nms_per_rad: " + io::formatNumber(c) + "}";
}

// Moment of inertia of `b` about the line through p along unit n (parallel-axis theorem).
double calcAxisInertia(const BodySpec& b, const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
  const auto& I = b.inertia;
  Eigen::Matrix3d M;
  M << I.xx, I.xy, I.xz, I.xy, I.yy, I.yz, I.xz, I.yz, I.zz;
  const Eigen::Vector3d r = Eigen::Vector3d(b.com[0], b.com[1], b.com[2]) - p;
  return n.dot(M * n) + b.mass * (r - n * n.dot(r)).squaredNorm();
}

TEST(RiderArms, GripMassesKeepTheTotalsAndAddTheInertiaAboutTheSteerAxis) {
  PortableRandom rng(20261127);
  for (const std::string& file : {kEnduro, std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/supersport.yaml"}) {
    const double J = rng.drawUniform(0.05, 0.6), d = rng.drawUniform(0.2, 0.4);
    const Scenario plain = loadScenario(file);
    const Scenario s = loadScenario(file, {arms(J, 50, 5), "rider_arms.grip_half_width_m=" + io::formatNumber(d)});
    ASSERT_NE(scenario::findExtension(s, "rider_arms"), nullptr);
    const BodySpec a = scenario::calcVehicleTotal(plain), b = calcModelTotal(s);
    EXPECT_NEAR(b.mass, a.mass, 1e-9);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(b.com[i], a.com[i], 1e-9);
    EXPECT_NEAR(b.inertia.xx, a.inertia.xx, 1e-9);
    EXPECT_NEAR(b.inertia.zz, a.inertia.zz, 1e-9);
    EXPECT_NEAR(b.inertia.xz, a.inertia.xz, 1e-9);
    const double lambda = plain.geometry.steerAxisTilt;
    const Eigen::Vector3d p(plain.geometry.wheelbase + plain.geometry.trail, 0, 0), n(-std::sin(lambda), 0, std::cos(lambda));
    const BodySpec front = getModelBody(s, "front_frame");
    EXPECT_NEAR(calcAxisInertia(front, p, n) - calcAxisInertia(plain.frontFrame, p, n), J, 1e-9 * (1 + J)) << file;
    EXPECT_NEAR(front.mass - plain.frontFrame.mass, J / (d * d), 1e-9) << file;
  }
}

// The benchmark bicycle's rear frame (85 kg with its rider) gives up the grips; Meijaard's matrices
// of the loaded bodies (grips in the front frame) plus k and c in the steer entries.
TEST(RiderArms, BenchmarkBicycleMatchesMeijaardWithStiffnessAndDamping) {
  PortableRandom rng(777);
  const double J = rng.drawUniform(0.05, 0.3), k = rng.drawUniform(5, 100), c = rng.drawUniform(0.5, 10);
  const Scenario s = loadScenario(kWhipple, {arms(J, k, c)});
  Scenario loaded = s;  // the bodies as the model carries them: the grips in the front frame
  loaded.rearFrame = getModelBody(s, "rear_frame");
  loaded.frontFrame = getModelBody(s, "front_frame");
  const Benchmark b = calcMeijaardMatrices(loaded);
  for (int v = 0; v <= 10; v += 2) {
    const Eigen::VectorXcd ref = Eigen::EigenSolver<Eigen::Matrix4d>(calcBenchmarkStateMatrix(b, s.gravity, v, k, c)).eigenvalues();
    const Eigen::VectorXcd got = calcEigenvaluesAt(s, v);
    EXPECT_LT(calcSpectrumDistance(ref, got), 1e-8) << "v = " << v << "\nref " << ref.transpose() << "\ngot " << got.transpose();
  }
  io::YamlMap section = getExtensionSection(s, "rider_arms");
  EXPECT_DOUBLE_EQ(calcRiderArmsTorque(readRiderArms(section, plugins::makeVehicleLayout(s)), 0.1, -0.2), -k * 0.1 + c * 0.2);
}

TEST(RiderArms, BadInputIsAnInputError) {
  EXPECT_THROW(loadAndBuild(kWhipple, {"rider_arms={inertia_kgm2: 0, stiffness_Nm_per_rad: 1, damping_Nms_per_rad: 1}"}), io::InputError);
  EXPECT_THROW(loadAndBuild(kWhipple, {"rider_arms={inertia_kgm2: 0.2, stiffness_Nm_per_rad: -1, damping_Nms_per_rad: 1}"}), io::InputError);
  EXPECT_THROW(loadAndBuild(kWhipple, {"rider_arms={inertia_kgm2: 0.2, stiffness_Nm_per_rad: 1, damping_Nms_per_rad: 1, hands: 2}"}), io::InputError);
  // Grips heavier than the rear frame can give up (1000 kg m^2 at 0.25 m: 16 t).
  EXPECT_THROW(loadAndBuild(kWhipple, {arms(1000, 50, 5)}), io::InputError);
}

}  // namespace
}  // namespace motostab::extensions
