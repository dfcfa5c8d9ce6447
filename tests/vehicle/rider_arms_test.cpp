// The rider's arms on the handlebar (vehicle/rider_arms.h, scenario `rider_arms`): the grip masses
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
#include "vehicle/rider_arms.h"

namespace motostab::vehicle {

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
    ASSERT_TRUE(s.hasRiderArms);
    const BodySpec a = scenario::calcVehicleTotal(plain), b = scenario::calcVehicleTotal(s);
    EXPECT_NEAR(b.mass, a.mass, 1e-9);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(b.com[i], a.com[i], 1e-9);
    EXPECT_NEAR(b.inertia.xx, a.inertia.xx, 1e-9);
    EXPECT_NEAR(b.inertia.zz, a.inertia.zz, 1e-9);
    EXPECT_NEAR(b.inertia.xz, a.inertia.xz, 1e-9);
    const double lambda = plain.geometry.steerAxisTilt;
    const Eigen::Vector3d p(plain.geometry.wheelbase + plain.geometry.trail, 0, 0), n(-std::sin(lambda), 0, std::cos(lambda));
    EXPECT_NEAR(calcAxisInertia(s.frontFrame, p, n) - calcAxisInertia(plain.frontFrame, p, n), J, 1e-9 * (1 + J)) << file;
    EXPECT_NEAR(s.frontFrame.mass - plain.frontFrame.mass, J / (d * d), 1e-9) << file;
  }
}

// Eigenvalues of M q'' + (v C1 + diag(0, c)) q' + (g K0 + v^2 K2 + diag(0, k)) q = 0.
Eigen::VectorXcd calcArmsEigenvalues(const Benchmark& b, double g, double v, double k, double c) {
  const Eigen::Matrix2d C = v * b.C1 + Eigen::Vector2d(0, c).asDiagonal().toDenseMatrix();
  const Eigen::Matrix2d K = g * b.K0 + v * v * b.K2 + Eigen::Vector2d(0, k).asDiagonal().toDenseMatrix();
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  A.topRightCorner<2, 2>().setIdentity();
  A.bottomLeftCorner<2, 2>() = -b.M.inverse() * K;
  A.bottomRightCorner<2, 2>() = -b.M.inverse() * C;
  return Eigen::EigenSolver<Eigen::Matrix4d>(A).eigenvalues();
}

// The benchmark bicycle's rear frame (85 kg with its rider) gives up the grips; Meijaard's matrices
// of the loaded bodies (grips in the front frame) plus k and c in the steer entries.
TEST(RiderArms, BenchmarkBicycleMatchesMeijaardWithStiffnessAndDamping) {
  PortableRandom rng(777);
  const double J = rng.drawUniform(0.05, 0.3), k = rng.drawUniform(5, 100), c = rng.drawUniform(0.5, 10);
  const Scenario s = loadScenario(kWhipple, {arms(J, k, c)});
  const Benchmark b = calcMeijaardMatrices(s);
  for (int v = 0; v <= 10; v += 2) {
    const Eigen::VectorXcd ref = calcArmsEigenvalues(b, s.gravity, v, k, c);
    const Eigen::VectorXcd got = calcEigenvaluesAt(s, v);
    EXPECT_LT(calcSpectrumDistance(ref, got), 1e-8) << "v = " << v << "\nref " << ref.transpose() << "\ngot " << got.transpose();
  }
  EXPECT_DOUBLE_EQ(calcRiderArmsTorque(s.riderArms, 0.1, -0.2), -k * 0.1 + c * 0.2);
}

TEST(RiderArms, BadInputIsAnInputError) {
  EXPECT_THROW(loadScenario(kWhipple, {"rider_arms={inertia_kgm2: 0, stiffness_Nm_per_rad: 1, damping_Nms_per_rad: 1}"}), io::InputError);
  EXPECT_THROW(loadScenario(kWhipple, {"rider_arms={inertia_kgm2: 0.2, stiffness_Nm_per_rad: -1, damping_Nms_per_rad: 1}"}), io::InputError);
  EXPECT_THROW(loadScenario(kWhipple, {"rider_arms={inertia_kgm2: 0.2, stiffness_Nm_per_rad: 1, damping_Nms_per_rad: 1, hands: 2}"}), io::InputError);
  // Grips heavier than the rear frame can give up (1000 kg m^2 at 0.25 m: 16 t).
  EXPECT_THROW(loadScenario(kWhipple, {arms(1000, 50, 5)}), io::InputError);
}

}  // namespace
}  // namespace motostab::vehicle
