// Virtual rig round trip: files written in the documented formats, identified by the full chain, compared
// with the rig's known truth (computed here from seed eq. 5-9 and the rig parameters).
#include <gtest/gtest.h>

#include <cmath>

#include "output/virtual_rig_output.h"
#include "rig_round_trip.h"
#include "rig_truth.h"
#include "tests/support/temp_dir.h"

namespace {

using motostab::output::writeFrfTestFiles;

using namespace motostab::swingarm::identification;
constexpr double kDeg = M_PI / 180;

struct Errors {
  double beta, kTw, fB, fT, zB, zT, kB, kT, cTw;  // deg or relative
};

struct RoundTrip : IdentifiedRig {
  Errors err;
};

RoundTrip runRoundTrip(const std::string& name, double noiseFactor, std::uint64_t seed, const std::string& extra = "") {
  const VirtualSwingarm rig;
  const RigNoise noise = RigNoise().scaled(noiseFactor);
  RoundTrip r;
  static_cast<IdentifiedRig&>(r) =
      identifyRigTests(rig, noise, seed, makeTempDir(name), "  band_hz: [60, 400]\n  model_order: [4, 24]\n" + extra);
  const RigTruth t = calcRigTruth(rig);
  const double cB = rig.kB * rig.zetaB / (M_PI * rig.fB), cT = rig.kT * rig.zetaT / (M_PI * rig.fT);
  const double rb = rig.armB * t.kTw / (rig.kB * t.aTw), rt = rig.armT * t.kTw / (rig.kT * t.aTw);
  const double cTw = cB * rb * rb + cT * rt * rt;  // seed eq. 25 with the true values
  auto rel = [](double a, double b) { return std::abs(a / b - 1); };
  const auto& b = r.id.bending;
  const auto& tor = r.id.torsion;
  r.err = {std::abs(r.stat.betaDeg - t.beta), rel(r.stat.kTw, t.kTw), rel(b.frequencyHz.value, rig.fB),
           rel(tor.frequencyHz.value, rig.fT), rel(b.dampingRatio.value, rig.zetaB), rel(tor.dampingRatio.value, rig.zetaT),
           rel(b.stiffness.value, rig.kB), rel(tor.stiffness.value, rig.kT), rel(r.id.twist.damping.value, cTw)};
  std::printf("[%s] noise x%.2g: beta %.3f deg, k_tw %.2f %%, f_b %.3f %%, f_t %.3f %%, zeta_b %.2f %%, zeta_t %.2f %%, "
              "k_b %.2f %%, k_t %.2f %%, c_tw %.2f %%\n", name.c_str(), noiseFactor, r.err.beta, 100 * r.err.kTw,
              100 * r.err.fB, 100 * r.err.fT, 100 * r.err.zB, 100 * r.err.zT, 100 * r.err.kB, 100 * r.err.kT,
              100 * r.err.cTw);
  return r;
}

// Acceptance: static axis angle 0.5 deg, k_tw 2 %, frequencies 0.5 %, damping ratios 10 %;
// plus k_b 2 %, k_t 10 %, c_tw 10 % at realistic noise (4 um lasers, 0.05 m/s^2 accelerometers).
TEST(VirtualRig, RoundTripRecoversTruthAtRealisticNoise) {
  for (std::uint64_t seed : {1, 2, 3}) {
    const RoundTrip r = runRoundTrip("realistic" + std::to_string(seed), 1.0, seed);
    EXPECT_LT(r.err.beta, 0.5);
    EXPECT_LT(r.err.kTw, 0.02);
    EXPECT_LT(r.err.fB, 0.005);
    EXPECT_LT(r.err.fT, 0.005);
    EXPECT_LT(r.err.zB, 0.10);
    EXPECT_LT(r.err.zT, 0.10);
    EXPECT_LT(r.err.kB, 0.02);
    EXPECT_LT(r.err.kT, 0.10);
    EXPECT_LT(r.err.cTw, 0.10);
    EXPECT_EQ(r.frf.modes[r.frf.bendingIndex].label, "bending");
    EXPECT_TRUE(r.frf.rejectedHits.empty());
    // The stated standard errors cover the actual errors (z-score below 4; jackknife over 3 hits is coarse).
    const VirtualSwingarm rig;
    const RigTruth t = calcRigTruth(rig);
    const auto& b = r.id.bending;
    const auto& tor = r.id.torsion;
    std::printf("  z: beta %.2f k_tw %.2f f_b %.2f f_t %.2f zeta_b %.2f zeta_t %.2f\n",
                (r.stat.betaDeg - t.beta) / r.stat.betaStderrDeg, (r.stat.kTw - t.kTw) / r.stat.kTwStderr,
                (b.frequencyHz.value - rig.fB) / b.frequencyHz.stderr_, (tor.frequencyHz.value - rig.fT) / tor.frequencyHz.stderr_,
                (b.dampingRatio.value - rig.zetaB) / b.dampingRatio.stderr_, (tor.dampingRatio.value - rig.zetaT) / tor.dampingRatio.stderr_);
    EXPECT_LT(std::abs(r.stat.betaDeg - t.beta), 4 * r.stat.betaStderrDeg);
    EXPECT_LT(std::abs(r.stat.kTw - t.kTw), 4 * r.stat.kTwStderr);
    EXPECT_LT(std::abs(b.frequencyHz.value - rig.fB), 4 * b.frequencyHz.stderr_);
    EXPECT_LT(std::abs(tor.frequencyHz.value - rig.fT), 4 * tor.frequencyHz.stderr_);
    EXPECT_LT(std::abs(b.dampingRatio.value - rig.zetaB), 4 * b.dampingRatio.stderr_);
    EXPECT_LT(std::abs(tor.dampingRatio.value - rig.zetaT), 4 * tor.dampingRatio.stderr_);
  }
}

// Ten times quieter sensors: tighter tolerances, and smaller errors than at realistic noise.
TEST(VirtualRig, LowerNoiseGivesTighterResults) {
  double loud = 0, quiet = 0;
  for (std::uint64_t seed : {11, 12, 13}) {
    const RoundTrip hi = runRoundTrip("loud" + std::to_string(seed), 1.0, seed);
    const RoundTrip lo = runRoundTrip("quiet" + std::to_string(seed), 0.1, seed);
    EXPECT_LT(lo.err.beta, 0.1);
    EXPECT_LT(lo.err.kTw, 0.004);
    EXPECT_LT(lo.err.fB, 0.001);
    EXPECT_LT(lo.err.fT, 0.001);
    EXPECT_LT(lo.err.zB, 0.03);
    EXPECT_LT(lo.err.zT, 0.03);
    EXPECT_LT(lo.err.kB, 0.005);
    EXPECT_LT(lo.err.kT, 0.03);
    loud += hi.err.beta / 0.5 + hi.err.kTw / 0.02;
    quiet += lo.err.beta / 0.5 + lo.err.kTw / 0.02;
    EXPECT_LT(lo.stat.betaStderrDeg, 0.2 * hi.stat.betaStderrDeg);
    EXPECT_LT(lo.stat.kTwStderr, 0.2 * hi.stat.kTwStderr);
  }
  EXPECT_LT(quiet, 0.3 * loud);
}

// The ODS at the torsion resonance still carries the bending mode's quadrature response (a bias of ~1 % in
// a_t, ~1.5 % in k_t, independent of noise); axes from the modal-model residues remove it.
TEST(VirtualRig, ModalModelAxesRemoveTheOdsBias) {
  const VirtualSwingarm rig;
  const RoundTrip ods = runRoundTrip("ods", 0.1, 31);
  const RoundTrip mm = runRoundTrip("modal_model", 0.1, 31, "  modal_axes_from: modal_model\n");
  EXPECT_NEAR(ods.id.torsion.arm.value, rig.armT, 0.03 * rig.armT);
  EXPECT_NEAR(ods.id.torsion.betaDeg.value, rig.betaTDeg, 0.2);
  EXPECT_NEAR(mm.id.torsion.arm.value, rig.armT, 0.005 * rig.armT);
  EXPECT_NEAR(mm.id.torsion.betaDeg.value, rig.betaTDeg, 0.05);
  EXPECT_NEAR(mm.id.bending.arm.value, rig.armB, 0.001 * rig.armB);
  EXPECT_NEAR(mm.id.bending.betaDeg.value, rig.betaBDeg, 0.05);
  EXPECT_LT(mm.err.kT, 0.005);
  EXPECT_LT(mm.err.kB, 0.002);
}

TEST(VirtualRig, DoubleHitAndOverloadedHitsAreRejected) {
  const VirtualSwingarm rig;
  const auto dir = makeTempDir("rejects");
  auto hits = simulateHammerHits(rig, {}, RigNoise(), 5);
  HammerOptions dbl;
  dbl.hits = 1;
  dbl.doubleHitDelay = 0.01;
  hits.push_back(simulateHammerHits(rig, dbl, RigNoise(), 6)[0]);
  HammerOptions clip;
  clip.hits = 1;
  clip.accelClip = 50;
  hits.push_back(simulateHammerHits(rig, clip, RigNoise(), 7)[0]);
  writeFrfTestFiles(dir, rig, hits, "  band_hz: [60, 400]\n  model_order: [4, 24]\n");
  const FrfTest t = readFrfTest(dir / "frf.yaml");
  const FrfResult r = identifyFrf(t, readHits(t));
  ASSERT_EQ(r.rejectedHits.size(), 2u);
  EXPECT_NE(r.rejectedHits[0].find("hit4.csv: double hit"), std::string::npos) << r.rejectedHits[0];
  EXPECT_NE(r.rejectedHits[1].find("hit5.csv: overload"), std::string::npos) << r.rejectedHits[1];
  EXPECT_EQ(r.frf.averages, 3);
}

}  // namespace
