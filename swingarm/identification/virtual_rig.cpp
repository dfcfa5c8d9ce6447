#include "swingarm/identification/virtual_rig.h"

#include <cmath>
#include <string>

#include <unsupported/Eigen/MatrixFunctions>

#include "core/portable_random.h"

namespace motostab::swingarm::identification {

using core::PortableRandom;

namespace {

constexpr double kDeg = M_PI / 180;

}  // namespace

Eigen::Vector2d VirtualSwingarm::getAxisPoint(int mode) const {
  const double a = mode == 0 ? armB : armT, b = (mode == 0 ? betaBDeg : betaTDeg) * kDeg;
  return Eigen::Vector2d(forcePoint.x, forcePoint.z) - a * Eigen::Vector2d(std::sin(b), -std::cos(b));
}

double VirtualSwingarm::getArmAt(int mode, const PlatePoint& r) const {
  return calcArmAt(getAxisPoint(mode), mode == 0 ? betaBDeg : betaTDeg, r);
}

RigNoise RigNoise::scaled(double f) const {
  RigNoise n = *this;
  n.laserResolution *= f;
  n.laserNoise *= f;
  n.accelNoise *= f;
  n.forceNoise *= f;
  return n;
}

StaticReadings simulateStaticReadings(const VirtualSwingarm& rig, const std::vector<double>& loads,
                                      const RigNoise& noise, std::uint64_t seed) {
  PortableRandom rng(seed);
  const int ns = static_cast<int>(rig.sensorPoints.size());
  StaticReadings r;
  r.force = loads;
  r.dy.resize(loads.size(), ns);
  for (int j = 0; j < ns; ++j) {
    const double offset = 5e-3 + 1e-3 * j;  // laser stand-off of the unloaded plate
    const auto& p = rig.sensorPoints[j];
    const double perN = rig.getArmAt(0, rig.forcePoint) * rig.getArmAt(0, p) / rig.kB +
                        rig.getArmAt(1, rig.forcePoint) * rig.getArmAt(1, p) / rig.kT;
    for (size_t i = 0; i < loads.size(); ++i) {
      const double y = offset + loads[i] * perN + noise.laserNoise * rng.drawNormal();
      r.dy(i, j) = noise.laserResolution > 0 ? std::round(y / noise.laserResolution) * noise.laserResolution : y;
    }
  }
  return r;
}

std::vector<modal::ImpactRecord> simulateHammerHits(const VirtualSwingarm& rig, const HammerOptions& o,
                                                    const RigNoise& noise, std::uint64_t seed) {
  PortableRandom rng(seed);
  const double dt = 1.0 / o.sampleRate;
  const size_t n = static_cast<size_t>(std::lround(o.duration * o.sampleRate));
  // Exact first-order-hold discretisation of each modal oscillator J th'' + c th' + k th = a_F F.
  struct Mode {
    Eigen::Matrix2d phi;
    Eigen::Vector2d g1, g2;
    double w, zeta, aF, invJ;
    std::vector<double> armAt;
  };
  std::vector<Mode> modes;
  for (int m = 0; m < 2; ++m) {
    Mode md;
    md.w = 2 * M_PI * (m == 0 ? rig.fB : rig.fT);
    md.zeta = m == 0 ? rig.zetaB : rig.zetaT;
    md.invJ = md.w * md.w / (m == 0 ? rig.kB : rig.kT);
    md.aF = rig.getArmAt(m, rig.forcePoint);
    for (const auto& p : rig.sensorPoints) md.armAt.push_back(rig.getArmAt(m, p));
    Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
    a(0, 1) = 1;
    a(1, 0) = -md.w * md.w;
    a(1, 1) = -2 * md.zeta * md.w;
    a(1, 2) = md.aF * md.invJ;
    a(2, 3) = 1;
    const Eigen::Matrix4d e = (a * dt).exp();
    md.phi = e.topLeftCorner(2, 2);
    md.g1 = e.block<2, 1>(0, 2);
    md.g2 = e.block<2, 1>(0, 3);
    modes.push_back(md);
  }
  std::vector<modal::ImpactRecord> hits;
  for (int h = 0; h < o.hits; ++h) {
    const double amp = o.peakForce * (0.9 + 0.2 * rng.drawUniform());
    const double t0 = o.preTrigger + rng.drawUniform() * dt;
    std::vector<double> f(n, 0.0);
    auto addPulse = [&](double start, double peak) {
      for (size_t k = 0; k < n; ++k) {
        const double s = (k * dt - start) / o.pulseWidth;
        if (s > 0 && s < 1) f[k] += peak * std::sin(M_PI * s);
      }
    };
    addPulse(t0, amp);
    if (o.doubleHitDelay > 0) addPulse(t0 + o.pulseWidth + o.doubleHitDelay, o.doubleHitFraction * amp);
    modal::ImpactRecord r;
    r.dt = dt;
    r.force.resize(n);
    r.responses.assign(rig.sensorPoints.size(), std::vector<double>(n, 0.0));
    for (const auto& md : modes) {
      Eigen::Vector2d x = Eigen::Vector2d::Zero();
      for (size_t k = 0; k < n; ++k) {
        const double acc = -md.w * md.w * x[0] - 2 * md.zeta * md.w * x[1] + md.aF * md.invJ * f[k];
        for (size_t j = 0; j < md.armAt.size(); ++j) r.responses[j][k] += acc * md.armAt[j];
        const double fNext = k + 1 < n ? f[k + 1] : f[k];
        x = md.phi * x + md.g1 * f[k] + md.g2 * (fNext - f[k]) / dt;
      }
    }
    for (size_t k = 0; k < n; ++k) r.force[k] = f[k] + noise.forceNoise * rng.drawNormal();
    for (auto& ch : r.responses)
      for (auto& v : ch) {
        v += noise.accelNoise * rng.drawNormal();
        if (o.accelClip > 0) v = std::clamp(v, -o.accelClip, o.accelClip);
      }
    hits.push_back(std::move(r));
  }
  return hits;
}

CogRigReadings simulateCogReadings(const VirtualPart& part, const Eigen::Vector3d& origin, double cellNoise,
                                   std::uint64_t seed) {
  PortableRandom rng(seed);
  const double g = 9.80665;
  const double cx[4] = {-0.3, 0.3, 0.3, -0.3}, cy[4] = {-0.2, -0.2, 0.2, 0.2};
  Eigen::Matrix<double, 3, 4> e;
  for (int j = 0; j < 4; ++j) e.col(j) << 1.0, cx[j], cy[j];
  const Eigen::Matrix<double, 4, 3> pinv = e.transpose() * (e * e.transpose()).inverse();  // minimum-norm split
  auto cellLoads = [&](double mass, const Eigen::Vector3d& c, double alpha) {
    const double w = mass * g;
    const Eigen::Vector3d res(w * std::cos(alpha), w * (c[0] * std::cos(alpha) - c[2] * std::sin(alpha)),
                              w * c[1] * std::cos(alpha));
    return Eigen::Vector4d(pinv * res);
  };
  const Eigen::Vector3d platformCog(0.01, 0.0, -0.03);
  const double platformMass = 20.0;
  CogRigReadings r;
  for (int j = 0; j < 4; ++j) r.cells.push_back({"N" + std::to_string(j + 1), cx[j], cy[j]});
  r.partOrigin = origin;
  for (int a = 0; a <= 30; a += 3) {
    const double alpha = a * kDeg;
    const Eigen::Vector4d plat = cellLoads(platformMass, platformCog, alpha);
    const Eigen::Vector4d withPart = plat + cellLoads(part.mass, origin + part.cog, alpha);
    Eigen::Vector4d loads, tare;
    for (int j = 0; j < 4; ++j) {
      loads[j] = withPart[j] + cellNoise * rng.drawNormal();
      tare[j] = plat[j] + cellNoise * rng.drawNormal();
    }
    r.tiltDeg.push_back(a);
    r.loads.push_back(loads);
    r.tareLoads.push_back(tare);
  }
  return r;
}

InertiaTest simulateTrifilarTest(const VirtualPart& part, double periodNoise, std::uint64_t seed) {
  PortableRandom rng(seed);
  InertiaTest t;
  t.wireLength = 2.0, t.radius = 0.3, t.plateMass = 4.0, t.partMass = part.mass;
  const double plateInertia = 0.25;
  auto periods = [&](double mass, double inertia) {
    const double period = 2 * M_PI * std::sqrt(inertia * t.wireLength / (mass * t.g * t.radius * t.radius));
    std::vector<double> p;
    for (int i = 0; i < 5; ++i) p.push_back(period + periodNoise * rng.drawNormal());
    return p;
  };
  t.platePeriods = periods(t.plateMass, plateInertia);
  const double s2 = std::sqrt(0.5);
  const Eigen::Vector3d axes[6] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {s2, s2, 0}, {s2, 0, s2}, {0, s2, s2}};
  const char* names[6] = {"x", "y", "z", "xy", "xz", "yz"};
  for (int i = 0; i < 6; ++i) {
    const double d = 0.005 * i;  // CoG slightly off the pendulum axis
    const double inertia = plateInertia + axes[i].dot(part.inertia * axes[i]) + part.mass * d * d;
    t.setups.push_back({names[i], axes[i], d, periods(t.plateMass + part.mass, inertia)});
  }
  return t;
}

}  // namespace motostab::swingarm::identification
