// Static twist axis (seed eq. 1-4) against analytic rigid rotations and the virtual rig's truth.
#include <gtest/gtest.h>

#include <cmath>

#include "swingarm/identification/static_laser.h"
#include "swingarm/identification/virtual_rig.h"
#include "rig_truth.h"

using motostab::swingarm::identification::PlatePoint;
using motostab::swingarm::identification::RigNoise;
using motostab::swingarm::identification::StaticReadings;
using motostab::swingarm::identification::StaticResult;
using motostab::swingarm::identification::StaticTest;
using motostab::swingarm::identification::VirtualSwingarm;
using motostab::swingarm::identification::identifyStatic;
using motostab::swingarm::identification::simulateStaticReadings;



namespace {

using namespace motostab::swingarm::identification;
constexpr double kDeg = M_PI / 180;

StaticTest makeTest(PlatePoint force, std::vector<PlatePoint> pts, double resolution) {
  StaticTest t;
  t.forcePoint = force;
  for (size_t i = 0; i < pts.size(); ++i) t.sensors.push_back({"L" + std::to_string(i + 1), pts[i]});
  t.sensorResolution = resolution;
  return t;
}

// Noise-free rotation theta' (rad/N) about an axis through p at angle beta: dy = F theta' (sin b (x-px) - cos b (z-pz)).
TEST(StaticTwistAxis, RecoversAnalyticRotationExactly) {
  const double beta = 80, rotPerN = 2e-6, px = 0.1, pz = 0.02;
  const std::vector<PlatePoint> pts{{0.50, 0.04}, {0.60, 0.04}, {0.55, -0.05}, {0.62, -0.03}};
  for (const PlatePoint force : {PlatePoint{0.55, 0.0}, PlatePoint{0.05, 0.3}}) {
    const StaticTest t = makeTest(force, pts, 1e-12);
    StaticReadings r;
    r.force = {0, 500, 1000, 1500, 1000, 0};
    r.dy.resize(r.force.size(), pts.size());
    auto arm = [&](PlatePoint q) { return std::sin(beta * kDeg) * (q.x - px) - std::cos(beta * kDeg) * (q.z - pz); };
    for (size_t i = 0; i < r.force.size(); ++i)
      for (size_t j = 0; j < pts.size(); ++j) r.dy(i, j) = 0.004 + 0.001 * j + r.force[i] * rotPerN * arm(pts[j]);
    const StaticResult s = identifyStatic(t, r);
    const double a = std::abs(arm(force));
    const double expectedBeta = arm(force) > 0 ? beta : beta - 180;  // direction oriented so that a_tw > 0
    EXPECT_NEAR(s.aTw, a, 1e-9);
    EXPECT_NEAR(s.betaDeg, expectedBeta, 1e-6);
    EXPECT_NEAR(s.rotationPerN, rotPerN, 1e-9 * rotPerN);
    EXPECT_NEAR(s.kLat, 1 / (rotPerN * a), 1e-7 / (rotPerN * a));                 // eq. 1
    EXPECT_NEAR(s.kTw, a / rotPerN, 1e-7 * a / rotPerN);                           // eq. 3
    EXPECT_NEAR(s.kTw, s.kLat * s.aTw * s.aTw, 1e-9 * s.kTw);                      // eq. 4
    // Axis point: on the axis (arm 0) and at distance a_tw from the force point.
    EXPECT_NEAR(arm({s.axis.point[0], s.axis.point[1]}), 0.0, 1e-9);
    EXPECT_NEAR(std::hypot(s.axis.point[0] - force.x, s.axis.point[1] - force.z), a, 1e-9);
    // Per-level planes: loaded minus unloaded is the rotation at that load (dx = theta sin(beta)).
    EXPECT_NEAR(s.levels[2].plane[1] - s.levels[0].plane[1], 1000 * rotPerN * std::sin(beta * kDeg), 1e-12);
  }
}

std::vector<double> makeLoadCycle() {
  std::vector<double> loads;
  for (int i = 0; i <= 32; ++i) loads.push_back(250.0 * (i <= 16 ? i : 32 - i));
  return loads;
}

// The stated standard errors must describe the actual scatter: z-scores over 40 noisy repetitions.
TEST(StaticTwistAxis, StandardErrorsMatchMonteCarloScatter) {
  const VirtualSwingarm rig;
  const RigTruth truth = calcRigTruth(rig);
  StaticTest t = makeTest(rig.forcePoint, rig.sensorPoints, 4e-6);
  double zBeta = 0, zKtw = 0, zKlat = 0;
  const int n = 40;
  for (int s = 0; s < n; ++s) {
    const StaticResult r = identifyStatic(t, simulateStaticReadings(rig, makeLoadCycle(), RigNoise(), 100 + s));
    zBeta += std::pow((r.betaDeg - truth.beta) / r.betaStderrDeg, 2) / n;
    zKtw += std::pow((r.kTw - truth.kTw) / r.kTwStderr, 2) / n;
    zKlat += std::pow((r.kLat - truth.kLat) / r.kLatStderr, 2) / n;
  }
  for (double z : {zBeta, zKtw, zKlat}) {
    EXPECT_GT(std::sqrt(z), 0.6);
    EXPECT_LT(std::sqrt(z), 1.5);
  }
}

}  // namespace
