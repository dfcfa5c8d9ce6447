// Held-out style round trips: virtual swingarm rigs drawn at random inside the test (axes, stiffnesses,
// frequencies, damping, lever arms of the hit down to 1/30 of the other mode's, sensor noise, channel
// count and layout), identified with default settings only (no processing section: automatic band and
// orders). Tolerances of static k_tw 2 % and axis angle 1 deg, frequencies 0.5 %, damping
// ratios 15 % (bending) and 30 % (torsion); bending and torsion labels from the modal axes.
// Truth: the drawn parameters, and seed eq. 5-9 (rig_truth.h) for the static twist axis.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdint>

#include "core/portable_random.h"
#include "output/virtual_rig_output.h"
#include "rig_truth.h"
#include "swingarm/identification/virtual_rig.h"
#include "tests/support/temp_dir.h"

namespace {

using motostab::output::writeFrfTestFiles;
using motostab::output::writeStaticTestFiles;

using namespace motostab::swingarm::identification;

// Portable draws: mt19937_64 is specified bit for bit; the transforms below are ours.
struct Draw {
  explicit Draw(std::uint64_t seed) : rng(seed) {}
  double uniform(double a, double b) { return a + (b - a) * rng.drawUniform(); }
  double logUniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
  int integer(int a, int b) { return a + static_cast<int>(rng.drawBits() % static_cast<std::uint64_t>(b - a + 1)); }
  motostab::core::PortableRandom rng;
};

// |accelerance| at resonance of mode m between the hit and sensor j, written here from the 1-DOF modal
// model J th'' + c th' + k th = a_F F, y_j = a_j th: |A| = w^2 a_F a_j / (k 2 zeta_eff), with the damping
// the exponential window (end value 0.05 over 1 s: decay ln 20 /s) adds.
double calcPeakAccelerance(double f, double zeta, double k, double aF, double aJ) {
  const double w = 2 * M_PI * f, zetaEff = zeta + std::log(20.0) / w;
  return w * w * std::abs(aF * aJ) / (k * 2 * zetaEff);
}

// Signed lever of point r about an axis through p with direction angle beta (deg) in the plate (x, z):
// y = theta (e x (r - p))_y, the same geometry the rig uses (seed Fig. 8).
double calcLever(double px, double pz, double betaDeg, double rx, double rz) {
  const double b = betaDeg * M_PI / 180;
  return std::cos(b) * (rz - pz) - std::sin(b) * (rx - px);
}

struct DrawnRig {
  VirtualSwingarm rig;
  RigNoise noise;
  double weakRatio = 0;   ///< weak mode's best channel peak / that channel's strong peak
  bool torsionWeak = false;
};

// A rig whose weaker mode still meets the detectability criterion (peak >= 1 % of the largest in
// some channel, with a 1.5x margin for leakage and window smearing); redrawn otherwise.
DrawnRig drawRig(Draw& d) {
  for (;;) {
    DrawnRig r;
    VirtualSwingarm& g = r.rig;
    g.forcePoint = {d.uniform(0.4, 0.7), d.uniform(-0.03, 0.03)};
    g.sensorPoints.clear();
    const int channels = d.integer(3, 5);
    for (int j = 0; j < channels; ++j)
      g.sensorPoints.push_back({g.forcePoint.x + d.uniform(-0.12, 0.12), g.forcePoint.z + d.uniform(-0.08, 0.08)});
    g.betaBDeg = d.uniform(70, 110);
    g.betaTDeg = d.uniform(-20, 20);
    r.torsionWeak = d.uniform(0, 1) < 0.6;
    const double strongArm = d.uniform(0.15, 0.5), weakArm = strongArm * d.logUniform(1.0 / 30, 1.0 / 3);
    g.armB = r.torsionWeak ? strongArm : weakArm;
    g.armT = r.torsionWeak ? weakArm : strongArm;
    g.kB = d.uniform(1.2e5, 4e5);
    g.kT = d.uniform(3e4, 1.5e5);
    g.fB = d.uniform(90, 170);
    g.fT = g.fB * (d.uniform(0, 1) < 0.7 ? d.uniform(1.2, 1.9) : d.uniform(0.6, 0.85));
    g.zetaB = d.uniform(0.002, 0.01);
    g.zetaT = d.uniform(0.002, 0.01);
    r.noise = RigNoise().scaled(d.logUniform(0.5, 2.0));
    // Channels must span the plate (not nearly collinear) for the plane fit: the smaller principal spread
    // of their positions at least 25 mm.
    Eigen::MatrixXd xz(channels, 2);
    for (int j = 0; j < channels; ++j) xz.row(j) << g.sensorPoints[j].x, g.sensorPoints[j].z;
    xz.rowwise() -= xz.colwise().mean();
    if (Eigen::JacobiSVD<Eigen::MatrixXd>(xz).singularValues()[1] / std::sqrt(channels) < 0.025) continue;
    const Eigen::Vector2d pb = g.getAxisPoint(0), pt = g.getAxisPoint(1);
    const double aFB = calcLever(pb[0], pb[1], g.betaBDeg, g.forcePoint.x, g.forcePoint.z);
    const double aFT = calcLever(pt[0], pt[1], g.betaTDeg, g.forcePoint.x, g.forcePoint.z);
    double best = 0;
    for (const auto& p : g.sensorPoints) {
      const double b = calcPeakAccelerance(g.fB, g.zetaB, g.kB, aFB, calcLever(pb[0], pb[1], g.betaBDeg, p.x, p.z));
      const double t = calcPeakAccelerance(g.fT, g.zetaT, g.kT, aFT, calcLever(pt[0], pt[1], g.betaTDeg, p.x, p.z));
      best = std::max(best, r.torsionWeak ? t / b : b / t);
    }
    r.weakRatio = best;
    if (best >= 0.015) return r;
  }
}

struct Outcome {
  FrfResult frf;
  StaticResult stat;
};

Outcome runDefaults(const DrawnRig& d, const std::string& name, std::uint64_t seed) {
  const auto dir = makeTempDir(name);
  std::vector<double> loads;
  for (int i = 0; i <= 32; ++i) loads.push_back(250.0 * (i <= 16 ? i : 32 - i));  // 0-4000-0 N
  writeStaticTestFiles(dir, d.rig, simulateStaticReadings(d.rig, loads, d.noise, seed), d.noise.laserResolution);
  writeFrfTestFiles(dir, d.rig, simulateHammerHits(d.rig, {}, d.noise, seed + 1));  // no processing section
  const StaticTest st = readStaticTest(dir / "static.yaml");
  const FrfTest ft = readFrfTest(dir / "frf.yaml");
  return {identifyFrf(ft, readHits(ft)), identifyStatic(st, readStaticReadings(st))};
}

TEST(HeldOutRigs, DefaultsRecoverRandomRigsWithWeakModes) {
  Draw draw(0x5eed14);
  double minRatio = 1;
  for (int i = 0; i < 16; ++i) {
    const DrawnRig d = drawRig(draw);
    const VirtualSwingarm& g = d.rig;
    minRatio = std::min(minRatio, d.weakRatio);
    const Outcome o = runDefaults(d, "held_out" + std::to_string(i), 1000 + 17 * i);
    SCOPED_TRACE("rig " + std::to_string(i) + ": fB " + std::to_string(g.fB) + " fT " + std::to_string(g.fT) +
                 " armB " + std::to_string(g.armB) + " armT " + std::to_string(g.armT) + " weak peak ratio " +
                 std::to_string(d.weakRatio) + " channels " + std::to_string(g.sensorPoints.size()));
    const RigTruth t = calcRigTruth(g);
    EXPECT_LT(std::abs(o.stat.kTw / t.kTw - 1), 0.02);
    EXPECT_LT(std::abs(o.stat.betaDeg - t.beta), 1.0);
    ASSERT_GE(o.frf.bendingIndex, 0) << (o.frf.diagnostics.empty() ? "" : o.frf.diagnostics.back());
    ASSERT_GE(o.frf.torsionIndex, 0) << (o.frf.diagnostics.empty() ? "" : o.frf.diagnostics.back());
    const ModeResult& b = o.frf.modes[o.frf.bendingIndex];
    const ModeResult& tor = o.frf.modes[o.frf.torsionIndex];
    std::printf("[rig %d] %zu ch, weak %s (peak %.3f): f_b %.3f %%, f_t %.3f %%, zeta_b %.1f %%, zeta_t %.1f %%, "
                "beta_b %.2f deg, beta_t %.2f deg, k_tw %.2f %%, static beta %.3f deg\n",
                i, g.sensorPoints.size(), d.torsionWeak ? "torsion" : "bending", d.weakRatio,
                100 * (b.frequencyHz / g.fB - 1), 100 * (tor.frequencyHz / g.fT - 1),
                100 * (b.dampingRatio / g.zetaB - 1), 100 * (tor.dampingRatio / g.zetaT - 1),
                b.axis.betaDeg - g.betaBDeg, wrapDegrees(tor.axis.betaDeg - g.betaTDeg), 100 * (o.stat.kTw / t.kTw - 1),
                o.stat.betaDeg - t.beta);
    EXPECT_LT(std::abs(b.frequencyHz / g.fB - 1), 0.005);
    EXPECT_LT(std::abs(tor.frequencyHz / g.fT - 1), 0.005);
    EXPECT_LT(std::abs(b.dampingRatio / g.zetaB - 1), 0.15);
    EXPECT_LT(std::abs(tor.dampingRatio / g.zetaT - 1), 0.30);
  }
  EXPECT_LT(minRatio, 0.1);  // the draws did include weakly excited modes
}

}  // namespace
