// The optional rear suspension at the swingarm pivot (scenario `swingarm.suspension`) on the enduro
// motorcycle: spring preload, bounce frequency against a hand calculation, the stiff limit, labels.
#include <gtest/gtest.h>

#include <complex>
#include <iostream>
#include <map>

#include "analysis/sweep.h"

namespace motostab::vehicle {

using analysis::SweepOptions;
using analysis::SweepResult;
using analysis::TrimResult;
using analysis::calcTrim;
using analysis::runSweep;
using scenario::Scenario;
using scenario::calcStaticWheelLoads;
using scenario::loadScenario;

namespace {

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

// Wheel-referred rate and damping used below: a soft enduro rear end (the rear sprung mass of about
// 130 kg on 20 kN/m rides at about 2 Hz).
constexpr double kWheelRate = 20000;    // N/m
constexpr double kWheelDamping = 1500;  // N s/m

std::string suspensionOverride(double wheelRate, double damping) {
  return "swingarm.suspension={wheel_rate_N_per_m: " + std::to_string(wheelRate) +
         ", damping_Ns_per_m: " + std::to_string(damping) + "}";
}

// Hand calculation from the scenario's input numbers only. The swingarm and the rear wheel (spin
// locked to the arm) turn together about the pivot's lateral axis.
struct PivotHand {
  double lever = 0;  // horizontal pivot-to-hub distance l, m
  double height = 0; // pivot height above the hub, m
  double J = 0;      // inertia about the pivot axis, kg m^2
};

PivotHand calcPivotHand(const Scenario& s) {
  PivotHand h;
  h.lever = s.swingarm.pivot[0];
  h.height = s.swingarm.pivot[2] - s.rearWheel.radius;
  const double L2 = h.lever * h.lever + h.height * h.height;
  // Table 1 gives the CoM and inertia in S, whose y axis is the pivot axis (up to sign).
  const auto& c = s.swingarm.body.com;
  const double Jarm = s.swingarm.body.inertia.yy + s.swingarm.body.mass * (c[0] * c[0] + c[2] * c[2]);
  h.J = Jarm + s.rearWheel.mass * L2 + s.rearWheel.axialInertia;
  return h;
}

// Locks every mobilizer except the one whose q is `keep`, then returns -d(udot_keep)/dq_keep by
// central differences (omega^2 of the one-DOF system when only springs act on it).
double calcLockedOmegaSquared(const VehicleModel& vm, SimTK::State st, int keep) {
  const SimTK::SimbodyMatterSubsystem& matter = vm.getMatter();
  for (SimTK::MobilizedBodyIndex b(1); b < matter.getNumBodies(); ++b) {
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(b);
    if (mb.getNumU(st) > 0 && mb.getFirstQIndex(st) != keep) mb.lock(st, SimTK::Motion::Position);
  }
  const double q0 = st.getQ()[keep], h = 1e-5;
  double udot[2];
  for (int i = 0; i < 2; ++i) {
    st.updQ()[keep] = q0 + (i == 0 ? h : -h);
    vm.getSystem().realize(st, SimTK::Stage::Acceleration);
    udot[i] = st.getUDot()[keep];
  }
  return -(udot[0] - udot[1]) / (2 * h);
}

TEST(RearSuspension, AbsentKeyKeepsTheRigidPivot) {
  const VehicleModel rigid(loadScenario(kEnduro));
  EXPECT_EQ(rigid.getIndices().suspension, -1);
  const VehicleModel sprung(loadScenario(kEnduro, {suspensionOverride(kWheelRate, kWheelDamping)}));
  ASSERT_GE(sprung.getIndices().suspension, 0);
  EXPECT_EQ(sprung.getQNames()[sprung.getIndices().suspension], "suspension_pitch");
  EXPECT_EQ(sprung.getUNames()[sprung.getIndices().suspension], "suspension_pitch_rate");
  EXPECT_EQ(sprung.getNumQ(), rigid.getNumQ() + 1);
  // A positive angle turns the arm about +y through the pivot: hub - pivot = (-l, 0, -dz) becomes
  // (-l cos q - dz sin q, 0, l sin q - dz cos q), so the hub rises (rear frame fixed).
  SimTK::State st = sprung.getDefaultState();
  const double q = 0.01, l = 0.5502, dz = 0.4060 - 0.289;
  st.updQ()[sprung.getIndices().suspension] = q;
  sprung.getSystem().realize(st, SimTK::Stage::Position);
  const SimTK::Vec3 hub = sprung.getRearWheel().getBodyOriginLocation(st);
  EXPECT_NEAR(hub[2] - 0.289, l * std::sin(q) + dz * (1 - std::cos(q)), 1e-12);
  EXPECT_NEAR(hub[0], l * (1 - std::cos(q)) - dz * std::sin(q), 1e-12);
}

// Lifted off the ground without gravity, only the suspension spring acts: omega^2 = k_theta / J with
// the wheel rate referred to the pivot by the horizontal lever, k_theta = k_wheel l^2.
TEST(RearSuspension, LiftedArmOscillatesAtWheelRateTimesLeverSquaredOverJ) {
  const Scenario s = loadScenario(kEnduro, {suspensionOverride(kWheelRate, 0), "gravity_mps2=0"});
  const VehicleModel vm(s);
  SimTK::State st = vm.getDefaultState();
  st.updQ()[vm.getIndices().height] += 1.0;
  const PivotHand h = calcPivotHand(s);
  const double omega2 = kWheelRate * h.lever * h.lever / h.J;
  EXPECT_NEAR(calcLockedOmegaSquared(vm, st, vm.getIndices().suspension), omega2, 1e-6 * omega2);
  std::cout << "lifted: J = " << h.J << " kg m^2, f = " << std::sqrt(omega2) / (2 * M_PI) << " Hz\n";
}

// On the ground at rest: the trim converges with the suspension near its design angle (the spring
// preload carries the static pivot moment), and with the rear frame held, the arm bounces on the
// spring and the tyre's radial stiffness in parallel: k = k_wheel l^2 + k_r l^2, less the geometric
// stiffness of the loads that move aft as the hub rises ((pivot height - hub height) per radian).
TEST(RearSuspension, TrimmedBounceFrequencyMatchesHandCalculation) {
  const Scenario s = loadScenario(kEnduro, {suspensionOverride(kWheelRate, kWheelDamping)});
  const VehicleModel vm(s);
  const TrimResult trim = calcTrim(vm, 0.0);
  EXPECT_LT(trim.residualNorm, 1e-10);
  const int qs = vm.getIndices().suspension;
  // A preload error as small as the rear wheel's weight would deflect the arm by 0.01 rad.
  EXPECT_LT(std::abs(trim.state.getQ()[qs]), 1e-3) << "suspension angle at trim";

  const PivotHand h = calcPivotHand(s);
  const double kTyre = 120000;  // enduro rear radial_stiffness_N_per_m
  const double rearLoad = calcStaticWheelLoads(s)[0], g = s.gravity;
  // Height of the pivot above the arm's CoM: S x points to the hub, S z up, normal to it.
  const double L = std::hypot(h.lever, h.height);
  const auto& c = s.swingarm.body.com;
  const double pivotOverArmCom = c[0] * h.height / L - c[2] * h.lever / L;
  const double kGeometric = -h.height * (rearLoad - s.rearWheel.mass * g) + pivotOverArmCom * s.swingarm.body.mass * g;
  const double k = (kWheelRate + kTyre) * h.lever * h.lever + kGeometric;
  const double omegaHand = std::sqrt(k / h.J);
  const double omegaModel = std::sqrt(calcLockedOmegaSquared(vm, trim.state, qs));
  EXPECT_NEAR(omegaModel, omegaHand, 5e-4 * omegaHand);
  std::cout << "on the ground: hand " << omegaHand / (2 * M_PI) << " Hz, model " << omegaModel / (2 * M_PI)
            << " Hz, geometric share " << kGeometric / k << "\n";
}

SweepResult sweepNear(const std::vector<std::string>& overrides, double v) {
  const VehicleModel model(loadScenario(kEnduro, overrides));
  SweepOptions opt;
  opt.start = v - 2, opt.stop = v, opt.step = 1;
  return runSweep(model, opt);
}

// The eigenvalue in the upper half plane (or on the real axis) labelled `label` at the last speed.
std::complex<double> eigenvalueOf(const SweepResult& r, const std::string& label) {
  for (const auto& b : r.branches)
    if (analysis::toString(b.labels.back()) == label && b.eigenvalue.back().imag() >= 0) return b.eigenvalue.back();
  ADD_FAILURE() << "no " << label << " mode";
  return 0;
}

// A very stiff suspension converges to the rigid pivot: weave and wobble at 20 m/s.
TEST(RearSuspension, StiffLimitReproducesRigidPivot) {
  const SweepResult rigid = sweepNear({}, 20.0);
  for (const char* mode : {"weave", "wobble"}) {
    const std::complex<double> ref = eigenvalueOf(rigid, mode);
    double previous = INFINITY;
    for (double rate : {1e5, 1e7, 1e9}) {
      const std::complex<double> l = eigenvalueOf(sweepNear({suspensionOverride(rate, kWheelDamping)}, 20.0), mode);
      const double err = std::abs(l - ref) / std::abs(ref);
      std::cout << mode << " " << rate << " N/m: " << l << " (rigid " << ref << "), relative error " << err << "\n";
      EXPECT_LT(err, previous) << mode << " " << rate;
      previous = err;
    }
    EXPECT_LT(previous, 1e-5) << mode;
  }
}

// Labels with suspension and swingarm compliance together: one rear_hop pair, the compliance modes
// still swingarm_*, weave, wobble and capsize present. The rear_hop frequency must lie within 10 %
// of the held-frame hand calculation (here the rear frame moves, the wheel spins freely against the
// tyre's longitudinal slip, and the arm bends: -6 % to +3 % at 10-50 kN/m), which sets it apart from
// the sprung bounce (1.6-2.9 Hz) and pitch (6.4 Hz) modes.
TEST(RearSuspension, ModeLabels) {
  const Scenario s = loadScenario(kEnduro);
  const PivotHand h = calcPivotHand(s);
  const double kTyre = 120000;  // enduro rear radial_stiffness_N_per_m
  for (double rate : {10000.0, kWheelRate, 50000.0}) {
    const SweepResult r = sweepNear({suspensionOverride(rate, kWheelDamping), "swingarm.compliance=bending+torsion"}, 20.0);
    std::map<std::string, int> count;
    for (const auto& b : r.branches)
      if (b.eigenvalue.back().imag() >= 0) ++count[analysis::toString(b.labels.back())];
    for (const char* label : {"rear_hop", "weave", "wobble", "capsize", "swingarm_bending", "swingarm_torsion"})
      EXPECT_EQ(count[label], 1) << label << " at " << rate << " N/m";
    EXPECT_EQ(count["bounce"] + count["pitch"], 2) << rate << " N/m";
    const double fHand = std::sqrt((rate + kTyre) * h.lever * h.lever / h.J) / (2 * M_PI);
    const double fModel = std::abs(eigenvalueOf(r, "rear_hop")) / (2 * M_PI);
    EXPECT_NEAR(fModel, fHand, 0.10 * fHand) << rate << " N/m";
    std::cout << rate << " N/m: rear_hop " << fModel << " Hz, held-frame hand calculation " << fHand << " Hz\n";
    for (const auto& b : r.branches)
      if (b.eigenvalue.back().imag() >= 0)
        std::cout << "  " << analysis::toString(b.labels.back()) << " " << b.eigenvalue.back() << " (" << std::abs(b.eigenvalue.back()) / (2 * M_PI) << " Hz)\n";
  }
}

}  // namespace
}  // namespace motostab::vehicle
