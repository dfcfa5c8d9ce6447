#include "swingarm/identification/virtual_rig.h"

#include <cmath>
#include <sstream>

#include <unsupported/Eigen/MatrixFunctions>

#include "io/atomic_file.h"
#include "io/csv.h"
#include "core/portable_random.h"

namespace motostab::swingarm::identification {

using core::PortableRandom;
using io::formatNumber;
using io::writeFileAtomically;

namespace {

constexpr double kDeg = M_PI / 180;

std::string num(double v, int digits = 10) { return formatNumber(v, digits); }

std::string sensorList(const VirtualSwingarm& rig, const char* prefix) {
  std::ostringstream s;
  for (size_t j = 0; j < rig.sensorPoints.size(); ++j)
    s << "  - {name: " << prefix << j + 1 << ", x: " << num(rig.sensorPoints[j].x) << ", z: "
      << num(rig.sensorPoints[j].z) << "}\n";
  return s.str();
}

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

void writeStaticTestFiles(const std::filesystem::path& dir, const VirtualSwingarm& rig, const StaticReadings& r,
                          double laserResolution) {
  std::ostringstream y;
  y << "test: static\n"
    << "frame: \"x along the swingarm from the pivot towards the hub, z up, y lateral (the force direction); metres\"\n"
    << "force_point: {x: " << num(rig.forcePoint.x) << ", z: " << num(rig.forcePoint.z) << "}\n"
    << "sensors:\n" << sensorList(rig, "L") << "readings: static.csv\n"
    << "sensor_resolution_m: " << num(laserResolution) << "\n";
  writeFileAtomically(dir / "static.yaml", y.str());
  std::ostringstream c;
  c << "# virtual rig (motostab), laser resolution " << num(laserResolution) << " m\nforce_N";
  for (size_t j = 0; j < rig.sensorPoints.size(); ++j) c << ",L" << j + 1 << "_m";
  c << "\n";
  for (size_t i = 0; i < r.force.size(); ++i) {
    c << num(r.force[i]);
    for (int j = 0; j < r.dy.cols(); ++j) c << "," << num(r.dy(i, j));
    c << "\n";
  }
  writeFileAtomically(dir / "static.csv", c.str());
}

void writeFrfTestFiles(const std::filesystem::path& dir, const VirtualSwingarm& rig,
                       const std::vector<modal::ImpactRecord>& hits, const std::string& processing) {
  std::ostringstream y;
  y << "test: frf\nframe: \"same convention as the static test\"\n"
    << "force_point: {x: " << num(rig.forcePoint.x) << ", z: " << num(rig.forcePoint.z) << "}\n"
    << "channels:\n" << sensorList(rig, "A") << "hits: [";
  for (size_t h = 0; h < hits.size(); ++h) y << (h ? ", " : "") << "hit" << h + 1 << ".csv";
  y << "]\n";
  if (!processing.empty()) y << "processing:\n" << processing;
  writeFileAtomically(dir / "frf.yaml", y.str());
  for (size_t h = 0; h < hits.size(); ++h) {
    std::ostringstream c;
    c << "time_s,force_N";
    for (size_t j = 0; j < hits[h].responses.size(); ++j) c << ",A" << j + 1 << "_mps2";
    c << "\n";
    for (size_t k = 0; k < hits[h].force.size(); ++k) {
      c << num(k * hits[h].dt, 9) << "," << num(hits[h].force[k], 7);
      for (const auto& ch : hits[h].responses) c << "," << num(ch[k], 7);
      c << "\n";
    }
    writeFileAtomically(dir / ("hit" + std::to_string(h + 1) + ".csv"), c.str());
  }
}

void writeCogTestFiles(const std::filesystem::path& dir, const VirtualPart& part, const Eigen::Vector3d& origin,
                       double cellNoise, std::uint64_t seed) {
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
  std::ostringstream rd, tr;
  rd << "tilt_deg,N1_N,N2_N,N3_N,N4_N\n";
  tr << "tilt_deg,N1_N,N2_N,N3_N,N4_N\n";
  for (int a = 0; a <= 30; a += 3) {
    const double alpha = a * kDeg;
    const Eigen::Vector4d plat = cellLoads(platformMass, platformCog, alpha);
    const Eigen::Vector4d withPart = plat + cellLoads(part.mass, origin + part.cog, alpha);
    rd << a;
    tr << a;
    for (int j = 0; j < 4; ++j) {
      rd << "," << num(withPart[j] + cellNoise * rng.drawNormal(), 8);
      tr << "," << num(plat[j] + cellNoise * rng.drawNormal(), 8);
    }
    rd << "\n";
    tr << "\n";
  }
  writeFileAtomically(dir / "cog.csv", rd.str());
  writeFileAtomically(dir / "cog_tare.csv", tr.str());
  std::ostringstream y;
  y << "test: cog\nframe: \"platform: x normal to the tilt hinge towards the raised side, y along the hinge, z up "
       "from the platform surface; metres\"\nload_cells:\n";
  for (int j = 0; j < 4; ++j) y << "  - {name: N" << j + 1 << ", x: " << cx[j] << ", y: " << cy[j] << "}\n";
  y << "readings: cog.csv\ntare: cog_tare.csv\nload_cell_resolution_N: 0.05\npart_origin_m: [" << num(origin[0])
    << ", " << num(origin[1]) << ", " << num(origin[2]) << "]\n";
  writeFileAtomically(dir / "cog.yaml", y.str());
}

void writeInertiaTestFiles(const std::filesystem::path& dir, const VirtualPart& part, double periodNoise,
                           std::uint64_t seed) {
  PortableRandom rng(seed);
  const double g = 9.80665, length = 2.0, radius = 0.3, plateMass = 4.0, plateInertia = 0.25;
  auto period = [&](double mass, double inertia) {
    return 2 * M_PI * std::sqrt(inertia * length / (mass * g * radius * radius));
  };
  auto periods = [&](double mass, double inertia) {
    std::ostringstream s;
    s << "[";
    for (int i = 0; i < 5; ++i) s << (i ? ", " : "") << num(period(mass, inertia) + periodNoise * rng.drawNormal(), 8);
    return s.str() + "]";
  };
  std::ostringstream y;
  y << "test: inertia\nframe: \"part frame of the CoG test; setup axes in that frame\"\n"
    << "pendulum: {wire_length_m: " << length << ", radius_m: " << radius << ", plate_mass_kg: " << plateMass << "}\n"
    << "period_resolution_s: 0.001\npart_mass_kg: " << num(part.mass) << "\n"
    << "plate_periods_s: " << periods(plateMass, plateInertia) << "\nsetups:\n";
  const double s2 = std::sqrt(0.5);
  const Eigen::Vector3d axes[6] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {s2, s2, 0}, {s2, 0, s2}, {0, s2, s2}};
  const char* names[6] = {"x", "y", "z", "xy", "xz", "yz"};
  for (int i = 0; i < 6; ++i) {
    const double d = 0.005 * i;  // CoG slightly off the pendulum axis
    const double inertia = plateInertia + axes[i].dot(part.inertia * axes[i]) + part.mass * d * d;
    y << "  - {name: " << names[i] << ", axis: [" << num(axes[i][0]) << ", " << num(axes[i][1]) << ", "
      << num(axes[i][2]) << "], cog_offset_m: " << d << ", periods_s: " << periods(plateMass + part.mass, inertia)
      << "}\n";
  }
  writeFileAtomically(dir / "inertia.yaml", y.str());
}

}  // namespace motostab::swingarm::identification
