// The optional rear suspension at the swingarm pivot (extension section `swingarm.suspension`) on the
// enduro motorcycle: its reader (wheel-referred values, bad input at file:line:col), spring preload,
// bounce frequency against a hand calculation, the stiff limit, labels.
#include <gtest/gtest.h>

#include <algorithm>
#include <complex>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>

#include "core/portable_random.h"
#include "tests/extensions/extension_test_util.h"
#include "tests/support/temp_dir.h"
#include "analysis/sweep.h"
#include "extensions/rear_suspension.h"
#include "plugins/plugin_registry.h"
#include "scenario/parameter_paths.h"

namespace motostab::extensions {

using analysis::SweepOptions;
using analysis::SweepResult;
using analysis::TrimResult;
using analysis::calcTrim;
using analysis::runSweep;
using core::PortableRandom;
using io::InputError;
using scenario::Scenario;
using scenario::calcStaticWheelLoads;
using scenario::formatOverride;
using scenario::loadScenario;
using testing::getExtensionSection;
using testing::kEnduro;
using vehicle::VehicleModel;

namespace {

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

// The suspension's coordinate, found by its role; -1 if the model has none.
int findSuspension(const VehicleModel& vm) {
  const auto& q = vm.getQStates();
  const auto it = std::find_if(q.begin(), q.end(), [](const auto& s) { return s.role == plugins::StateRole::Suspension; });
  return it == q.end() ? -1 : static_cast<int>(it - q.begin());
}

// The section as the plugin reads it.
RearSuspensionParams readSection(const Scenario& s) {
  io::YamlMap section = getExtensionSection(s, "swingarm.suspension");
  const RearSuspensionParams p = readRearSuspension(section, plugins::makeVehicleLayout(s));
  section.finish();
  return p;
}

// The build's error message for `s` ("" if it builds).
std::string errorOf(const std::function<Scenario()>& load) {
  try {
    VehicleModel model(load());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Writes the enduro with a rear suspension mapping `fields` after its compliance line; returns the path.
std::string writeWithSuspension(const std::string& name, const std::string& fields) {
  std::ifstream in(kEnduro);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const std::string from = "  compliance: rigid";
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos);
  text.replace(pos, from.size(), from + "\n  suspension: {" + fields + "}");
  const auto p = makeTempDir("suspension") / (name + ".yaml");
  std::ofstream(p) << text;
  return p.string();
}

// Bad input in the section: an InputError at the line of `lineNeedle` of the file, naming `key` and `reason`.
void expectError(const std::string& name, const std::string& fields, const std::string& lineNeedle, const std::string& key,
                 const std::string& reason) {
  const std::string path = writeWithSuspension(name, fields);
  const std::string m = errorOf([&] { return loadScenario(path); });
  ASSERT_FALSE(m.empty()) << "no error for " << fields;
  std::ifstream in(path);
  std::string line;
  int n = 1;
  while (std::getline(in, line) && line.find(lineNeedle) == std::string::npos) ++n;
  EXPECT_EQ(m.rfind(path + ":" + std::to_string(n) + ":", 0), 0u) << m;
  EXPECT_NE(m.find(key), std::string::npos) << m;
  EXPECT_NE(m.find(reason), std::string::npos) << m;
}

TEST(RearSuspension, BadInputIsNamedAtItsKey) {
  expectError("rate", "wheel_rate_N_per_m: -20000, damping_Ns_per_m: 1500", "wheel_rate_N_per_m: -20000",
              "swingarm.suspension.wheel_rate_N_per_m", "must be positive");
  expectError("damping", "stiffness_Nm_per_rad: 6000, damping_Nms_per_rad: -1", "damping_Nms_per_rad: -1",
              "swingarm.suspension.damping_Nms_per_rad", "must not be negative");
  expectError("unknown", "wheel_rate_N_per_m: 20000, damping_Ns_per_m: 1500, preload_N: 10", "preload_N",
              "swingarm.suspension.preload_N", "unknown key");
  expectError("missing", "damping_Ns_per_m: 1500", "suspension:", "swingarm.suspension.wheel_rate_N_per_m", "missing key");
  expectError("twice", "wheel_rate_N_per_m: 2, stiffness_Nm_per_rad: 1, damping_Ns_per_m: 0", "stiffness_Nm_per_rad",
              "swingarm.suspension.wheel_rate_N_per_m", "give only one");
}

// Wheel-referred values are referred to the pivot by the horizontal pivot-to-hub distance (the
// enduro's pivot_m[0] = 0.5502 m); pivot values are taken unchanged.
TEST(RearSuspension, WheelRateIsReferredToThePivot) {
  EXPECT_EQ(scenario::findExtension(loadScenario(kEnduro), "swingarm.suspension"), nullptr);
  const RearSuspensionParams wheel =
      readSection(loadScenario(kEnduro, {"swingarm.suspension={wheel_rate_N_per_m: 20000, damping_Ns_per_m: 1500}"}));
  EXPECT_NEAR(wheel.stiffness, 20000 * 0.5502 * 0.5502, 1e-9);
  EXPECT_NEAR(wheel.damping, 1500 * 0.5502 * 0.5502, 1e-12);
  EXPECT_DOUBLE_EQ(wheel.lever, 0.5502);
  const RearSuspensionParams pivot =
      readSection(loadScenario(kEnduro, {"swingarm.suspension={stiffness_Nm_per_rad: 6000, damping_Nms_per_rad: 400}"}));
  EXPECT_DOUBLE_EQ(pivot.stiffness, 6000);
  EXPECT_DOUBLE_EQ(pivot.damping, 400);
}

// Key by key, --set creates the missing `suspension` map; the result equals the whole-section form
// (values drawn in the test). A created section still meets the strict reader.
TEST(RearSuspension, SetCreatesTheSectionKeyByKey) {
  PortableRandom rng(20261124);
  const double rate = 1e4 + 3e4 * rng.drawUniform(), damping = 500 + 2000 * rng.drawUniform();
  const RearSuspensionParams keys = readSection(loadScenario(
      kEnduro, {formatOverride("swingarm.suspension.wheel_rate_N_per_m", rate), formatOverride("swingarm.suspension.damping_Ns_per_m", damping)}));
  const std::string r = formatOverride("r", rate).substr(2), c = formatOverride("c", damping).substr(2);
  const RearSuspensionParams whole =
      readSection(loadScenario(kEnduro, {"swingarm.suspension={wheel_rate_N_per_m: " + r + ", damping_Ns_per_m: " + c + "}"}));
  EXPECT_EQ(keys.stiffness, whole.stiffness);
  EXPECT_EQ(keys.damping, whole.damping);
  EXPECT_NEAR(keys.stiffness, rate * 0.5502 * 0.5502, 1e-9 * rate);
  // Only one of the two required keys: the reader names the missing one.
  const std::string missing = errorOf([] { return loadScenario(kEnduro, {"swingarm.suspension.damping_Ns_per_m=1500"}); });
  EXPECT_NE(missing.find("wheel_rate_N_per_m"), std::string::npos) << missing;
  const std::string deep = errorOf([] {
    return loadScenario(kEnduro, {"swingarm.suspension.wheel_rate_N_per_m=2e4", "swingarm.suspension.damping_Ns_per_m=1e3",
                                  "swingarm.suspension.spring.rate=1"});
  });
  EXPECT_NE(deep.find("spring"), std::string::npos) << deep;
  // Not a mapping: refused by the loader at the key.
  const std::string scalar = errorOf([] { return loadScenario(kEnduro, {"swingarm.suspension=5"}); });
  EXPECT_NE(scalar.find("swingarm.suspension"), std::string::npos) << scalar;
  EXPECT_NE(scalar.find("mapping"), std::string::npos) << scalar;
}

// The section takes the static pivot moment from the vehicle: the rear tyre's load (about 1.3 kN on
// the enduro) at the lever of 0.55 m lifts the hub far more than the arm's and wheel's weights lower it.
TEST(RearSuspension, PreloadIsTheStaticPivotMoment) {
  const Scenario s = loadScenario(kEnduro, {"swingarm.suspension={wheel_rate_N_per_m: 20000, damping_Ns_per_m: 1500}"});
  const RearSuspensionParams p = readSection(s);
  EXPECT_EQ(p.staticPivotMoment, scenario::calcStaticPivotMoment(s));
  EXPECT_GT(p.staticPivotMoment, 0.5502 * (calcStaticWheelLoads(s)[0] - s.rearWheel.mass * s.gravity) -
                                     0.5502 * s.swingarm.body.mass * s.gravity);
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
  EXPECT_EQ(findSuspension(rigid), -1);
  const VehicleModel sprung(loadScenario(kEnduro, {suspensionOverride(kWheelRate, kWheelDamping)}));
  const int qs = findSuspension(sprung);
  ASSERT_GE(qs, 0);
  EXPECT_EQ(sprung.getQNames()[qs], "suspension_pitch");
  EXPECT_EQ(sprung.getUNames()[qs], "suspension_pitch_rate");
  EXPECT_EQ(sprung.getNumQ(), rigid.getNumQ() + 1);
  // A positive angle turns the arm about +y through the pivot: hub - pivot = (-l, 0, -dz) becomes
  // (-l cos q - dz sin q, 0, l sin q - dz cos q), so the hub rises (rear frame fixed).
  SimTK::State st = sprung.getDefaultState();
  const double q = 0.01, l = 0.5502, dz = 0.4060 - 0.289;
  st.updQ()[qs] = q;
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
  EXPECT_NEAR(calcLockedOmegaSquared(vm, st, findSuspension(vm)), omega2, 1e-6 * omega2);
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
  const int qs = findSuspension(vm);
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
}  // namespace motostab::extensions
