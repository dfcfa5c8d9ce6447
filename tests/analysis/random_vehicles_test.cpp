// Mode labels and critical speeds on motorcycles nobody tuned for: seeded random variations (+/-20 %
// on masses, inertias, geometry and tyre coefficients) of the bundled motorcycles, swept upright and in
// 20 and 35 deg turns. Checks written here, apart from the labelling (analysis/modes.h):
//   - the wobble is the oscillation that a steering damper damps most: with a small damper c added
//     about the steer axis (the dissipation c |delta'|^2 goes where the steer rate is), the root whose
//     real part falls most, where it falls at least twice as much as any other oscillation's, is the
//     wobble (where two roots share the steer motion the test does not say which is the wobble);
//   - no root with a positive real part is `other`;
//   - every change in the number of roots with a positive real part (roots below 1e-6 1/s excepted)
//     between neighbouring speeds has a critical speed between them, and a refined critical speed is
//     a crossing: trimmed and linearised again here just below and just above it, the numbers of
//     roots with a positive real part (roots below 1e-8 1/s excepted) differ (a sign change of a
//     tracked branch may be a jump between roots, not a crossing).
// The main suite draws a few vehicles; the `long` label (test_analysis_long) draws many.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <optional>
#include <cmath>
#include <sstream>

#include "tests/support/extension_sections.h"
#include "analysis/linearize.h"
#include "analysis/sweep.h"
#include "analysis/trim.h"
#include "core/portable_random.h"
#include "io/input_error.h"
#include "io/number.h"
#include "scenario/scenario.h"

#ifndef MOTOSTAB_RANDOM_VEHICLES
#define MOTOSTAB_RANDOM_VEHICLES 1
#endif

namespace motostab::analysis {

using core::PortableRandom;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

const std::string kScenarios = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/";

std::string formatOverride(const std::string& key, double value) {
  std::ostringstream os;
  os.precision(17);
  os << key << "=" << value;
  return os.str();
}

std::string formatVector(const std::string& key, double x, double z) {
  std::ostringstream os;
  os.precision(17);
  os << key << "=[" << x << ", 0, " << z << "]";
  return os.str();
}

// Overrides that scale the masses, inertias, geometry and linear-tyre coefficients of `s` by factors
// drawn uniformly in [0.8, 1.2]. The front frame moves with the wheelbase; each pitch inertia is kept
// within the triangle inequality of its body.
std::vector<std::string> drawVariation(const Scenario& s, PortableRandom& g) {
  auto f = [&]() { return g.drawUniform(0.8, 1.2); };
  std::vector<std::string> o;
  const double w = s.geometry.wheelbase * f(), dw = w - s.geometry.wheelbase;
  o.push_back(formatOverride("geometry.wheelbase_m", w));
  o.push_back(formatOverride("geometry.steer_axis_tilt_deg", s.geometry.steerAxisTilt * 180 / M_PI * f()));
  // The trail under the key the file uses (normal trail = trail cos(tilt)).
  const bool normal = YAML::LoadFile(s.sourceFile)["geometry"]["normal_trail_m"].IsDefined();
  const double trail = s.geometry.trail * f();
  o.push_back(normal ? formatOverride("geometry.normal_trail_m", trail * std::cos(s.geometry.steerAxisTilt))
                     : formatOverride("geometry.trail_m", trail));
  // A file with the whole vehicle (total:) derives its rear frame from it: vary the total instead.
  const YAML::Node total = YAML::LoadFile(s.sourceFile)["total"];
  if (total.IsDefined()) {
    o.push_back(formatOverride("total.mass_kg", total["mass_kg"].as<double>() * f()));
    o.push_back(formatVector("total.com_m", total["com_m"][0].as<double>() * f(), total["com_m"][2].as<double>() * f()));
    const double xx = total["inertia_kgm2"]["xx"].as<double>() * f(), zz = total["inertia_kgm2"]["zz"].as<double>() * f();
    const double yy = std::clamp(total["inertia_kgm2"]["yy"].as<double>() * f(), std::abs(xx - zz) * 1.01, (xx + zz) * 0.99);
    o.push_back(formatOverride("total.inertia_kgm2.xx", xx));
    o.push_back(formatOverride("total.inertia_kgm2.yy", yy));
    o.push_back(formatOverride("total.inertia_kgm2.zz", zz));
  }
  for (const char* body : {"rear_frame", "front_frame"}) {
    if (total.IsDefined() && std::string(body) == "rear_frame") continue;
    const scenario::BodySpec& b = std::string(body) == "rear_frame" ? s.rearFrame : s.frontFrame;
    const std::string p = std::string(body) + ".";
    o.push_back(formatOverride(p + "mass_kg", b.mass * f()));
    const double x = std::string(body) == "rear_frame" ? b.com[0] * f() : b.com[0] + dw;
    o.push_back(formatVector(p + "com_m", x, b.com[2] * f()));
    const double xx = b.inertia.xx * f(), zz = b.inertia.zz * f();
    const double yy = std::clamp(b.inertia.yy * f(), std::abs(xx - zz) * 1.01, (xx + zz) * 0.99);
    o.push_back(formatOverride(p + "inertia_kgm2.xx", xx));
    o.push_back(formatOverride(p + "inertia_kgm2.yy", yy));
    o.push_back(formatOverride(p + "inertia_kgm2.zz", zz));
  }
  for (const char* wheel : {"rear_wheel", "front_wheel"}) {
    const scenario::WheelSpec& ws = std::string(wheel) == "rear_wheel" ? s.rearWheel : s.frontWheel;
    o.push_back(formatOverride(std::string(wheel) + ".mass_kg", ws.mass * f()));
  }
  for (const char* tyre : {"front", "rear"})
    for (const char* key : {"cornering_stiffness_per_rad", "camber_stiffness_per_rad", "relaxation_length_m"}) {
      const std::string path = std::string("contact.") + tyre + "." + key;
      o.push_back(formatOverride(path, s.contact.params[tyre][key].as<double>() * f()));
    }
  return o;
}

// How far a small steering damper moves each oscillation (imag > 0) of `lin` to the right (1/s; the
// most negative first), with its index: `damped` is the same vehicle and operating point with the
// damper, its roots matched to lin's by distance.
std::vector<std::pair<double, int>> listSteerDamperShifts(const LinearModel& lin, const LinearModel& damped) {
  std::vector<std::pair<double, int>> drops;
  for (int e = 0; e < lin.eigenvalues.size(); ++e) {
    const std::complex<double> l = lin.eigenvalues[e];
    if (!(l.imag() > 1e-6)) continue;
    int nearest = 0;
    for (int d = 1; d < damped.eigenvalues.size(); ++d)
      if (std::abs(damped.eigenvalues[d] - l) < std::abs(damped.eigenvalues[nearest] - l)) nearest = d;
    drops.push_back({damped.eigenvalues[nearest].real() - l.real(), e});
  }
  std::sort(drops.begin(), drops.end());
  return drops;
}

// The index in `lin` of the oscillation that the damper moves left most, or -1 where no oscillation
// falls at least twice as much as every other.
int findMostDampedBySteerDamper(const LinearModel& lin, const LinearModel& damped) {
  const std::vector<std::pair<double, int>> drops = listSteerDamperShifts(lin, damped);
  if (drops.empty() || !(drops[0].first < 0)) return -1;
  if (drops.size() > 1 && !(drops[0].first < 2 * std::min(drops[1].first, 0.0))) return -1;
  return drops[0].second;
}

// The three checks of the file's header on one sweep (`damped`: the same with a small steering damper);
// `what` names it in messages. Returns the number of wobble checks made.
int checkSweep(const SweepResult& s, const SweepResult& damped, const std::string& what) {
  int wobbles = 0;
  for (size_t k = 0; k < s.speeds.size(); ++k) {
    const LinearModel& lin = s.models[k];
    EXPECT_EQ(lin.labels.size(), static_cast<size_t>(lin.eigenvalues.size()));
    if (lin.labels.size() != static_cast<size_t>(lin.eigenvalues.size())) continue;
    for (int e = 0; e < lin.eigenvalues.size(); ++e)
      if (lin.eigenvalues[e].real() > 0) {
        EXPECT_NE(lin.labels[e], ModeLabel::Other) << what << " at " << s.speeds[k] << " m/s: unstable root " << lin.eigenvalues[e];
      }
    // Below 12 m/s the wobble is strongly damped (or real) and the weave carries most of the steer rate.
    if (s.speeds[k] < 12 || k >= damped.models.size() || damped.speeds[k] != s.speeds[k]) continue;
    const int best = findMostDampedBySteerDamper(lin, damped.models[k]);
    if (best < 0) continue;
    ++wobbles;
    EXPECT_EQ(lin.labels[best], ModeLabel::Wobble) << what << " at " << s.speeds[k] << " m/s: " << lin.eigenvalues[best]
                                                   << ", damped most by a steering damper, is " << toString(lin.labels[best]);
  }
  auto countUnstable = [](const LinearModel& lin) {
    return std::count_if(lin.eigenvalues.begin(), lin.eigenvalues.end(),
                         [](std::complex<double> l) { return l.real() > 0 && std::abs(l) >= 1e-6; });
  };
  for (size_t k = 0; k + 1 < s.speeds.size(); ++k) {
    const auto n0 = countUnstable(s.models[k]), n1 = countUnstable(s.models[k + 1]);
    if (n0 == n1) continue;
    const bool found = std::any_of(s.criticalSpeeds.begin(), s.criticalSpeeds.end(), [&](const CriticalSpeed& c) {
      return c.speed >= s.speeds[k] - 1e-9 && c.speed <= s.speeds[k + 1] + 1e-9;
    });
    EXPECT_TRUE(found) << what << ": " << n0 << " unstable roots at " << s.speeds[k] << " m/s, " << n1 << " at "
                       << s.speeds[k + 1] << " m/s, and no critical speed between";
  }
  return wobbles;
}

// Every refined critical speed of `s` is a crossing (the header's last check).
void checkCriticalSpeedsAreCrossings(const VehicleModel& model, const SweepOptions& opt, const SweepResult& s,
                                     const std::string& what) {
  auto linearizeAt = [&](double v) { return linearize(model, calcTrim(model, v, opt.trim)); };
  auto countUnstable = [](const LinearModel& lin) {
    return std::count_if(lin.eigenvalues.begin(), lin.eigenvalues.end(),
                         [](std::complex<double> l) { return l.real() > 0 && std::abs(l) >= 1e-8; });
  };
  // Roots within 5e-7 1/s of the imaginary axis: oscillations (complex) or real roots.
  auto countNearZero = [](const LinearModel& lin, bool complex) {
    return std::count_if(lin.eigenvalues.begin(), lin.eigenvalues.end(), [&](std::complex<double> l) {
      return (l.imag() > 1e-6) == complex && std::abs(l.real()) < 5e-7;
    });
  };
  for (size_t i = 0; i < s.criticalSpeeds.size(); ++i) {
    const CriticalSpeed& c = s.criticalSpeeds[i];
    if (!c.refined) continue;
    // Half the distance to the next critical speed on either side, at most 0.01 m/s.
    double d = 0.01;
    if (i > 0) d = std::min(d, 0.5 * (c.speed - s.criticalSpeeds[i - 1].speed));
    if (i + 1 < s.criticalSpeeds.size()) d = std::min(d, 0.5 * (s.criticalSpeeds[i + 1].speed - c.speed));
    const LinearModel at = linearizeAt(c.speed);
    const bool apart = d > 1e-6;  // else two crossings at one speed (a pair): the count may not change
    const std::optional<LinearModel> below = apart ? std::optional(linearizeAt(c.speed - d)) : std::nullopt;
    const std::optional<LinearModel> above = apart ? std::optional(linearizeAt(c.speed + d)) : std::nullopt;
    // A root is on the imaginary axis at the critical speed, within 5e-7 1/s (below the sweep's smallest
    // zero-root threshold, 1e-6 1/s, so that a real root found where it passes that threshold, not
    // where it is zero, fails): an oscillation there, or one more real root within it than d away on
    // either side (the neutral roots, heading and speed drift, are within it everywhere).
    const bool onAxis = c.frequency > 0 ? countNearZero(at, true) > 0
                        : !apart || countNearZero(at, false) > std::max(countNearZero(*below, false), countNearZero(*above, false));
    EXPECT_TRUE(onAxis) << what << ": no root on the imaginary axis at the critical speed " << c.speed << " m/s ("
                        << toString(c.mode) << ", " << c.frequency << " Hz)";
    if (!apart) continue;
    EXPECT_NE(countUnstable(*below), countUnstable(*above))
        << what << ": the number of unstable roots is the same at " << c.speed - d << " and " << c.speed + d
        << " m/s, around the critical speed " << c.speed << " m/s (" << toString(c.mode) << ")";
  }
}

// `s` with `damping` (N m s/rad) added about the steer axis: a steering damper, or more on the one it has.
Scenario addSteerDamping(const Scenario& s, double damping) {
  Scenario out = s;
  double c = damping;
  if (scenario::findExtension(s, "steer_damper"))
    c += testing::getExtensionValue(s, "steer_damper", "damping_Nms_per_rad").as<double>();
  testing::setExtension(out, "steer_damper", "{damping_Nms_per_rad: " + io::formatShortest(c) + "}");
  return out;
}

// Sweeps `s` over start:stop:step at each roll (deg), with and without a small steering damper, and
// makes the header's checks; returns the number of wobble checks.
int sweepAndCheck(const Scenario& s, double start, double stop, double step, const std::vector<double>& rollsDeg,
                  const std::string& what) {
  const VehicleModel model(s);
  const Scenario withDamper = addSteerDamping(s, 0.05);
  const VehicleModel damperModel(withDamper);
  int wobbles = 0;
  for (double rollDeg : rollsDeg) {
    SweepOptions opt;
    opt.start = start, opt.stop = stop, opt.step = step;
    opt.keepFailedSpeeds = true;
    if (rollDeg != 0) opt.trim.roll = rollDeg * M_PI / 180;
    const SweepResult sweep = runSweep(model, opt);
    const SweepResult damped = runSweep(damperModel, opt);
    const std::string at = what + " at " + std::to_string(rollDeg) + " deg";
    wobbles += checkSweep(sweep, damped, at);
    checkCriticalSpeedsAreCrossings(model, opt, sweep, at);
  }
  return wobbles;
}

// A variant of the bundled `scenario` (drawVariation) with `extra` overrides; a draw whose derived rear
// frame (total: less the other bodies) is not a physical body is drawn again (none after 20 draws).
std::optional<Scenario> drawVariant(const std::string& scenario, PortableRandom& g, const std::vector<std::string>& extra = {}) {
  const Scenario nominal = loadScenario(kScenarios + scenario + ".yaml");
  for (int attempt = 0; attempt < 20; ++attempt) {
    std::vector<std::string> o = drawVariation(nominal, g);
    o.insert(o.end(), extra.begin(), extra.end());
    try {
      return loadScenario(kScenarios + scenario + ".yaml", o);
    } catch (const io::InputError&) {
    }
  }
  return std::nullopt;
}

void checkRandomVariants(const std::string& scenario, std::uint64_t seed, int variants) {
  PortableRandom g(seed);
  int wobbles = 0;
  for (int v = 0; v < variants; ++v) {
    const std::optional<Scenario> drawn = drawVariant(scenario, g);
    ASSERT_TRUE(drawn) << "no physical variant of " << scenario << " in 20 draws";
    std::ostringstream what;
    what << scenario << " variant " << v << " (seed " << seed << ")";
    wobbles += sweepAndCheck(*drawn, 4, 48, 4, {0.0, 20.0, 35.0}, what.str());
  }
  std::cout << scenario << ": " << wobbles << " wobble checks\n";
  EXPECT_GT(wobbles, 0) << "no oscillation clearly damped most by the steering damper: the wobble check checked nothing";
}

// A cruiser written from the documentation alone (tests/data/vehicles/): upright and in turns, and on a
// 1 m/s grid at 20 deg, where two real roots joining into the weave pair once made the tracked branch
// jump sign with no root crossing zero (reported then as capsize and longitudinal critical speeds).
TEST(RandomVehicles, CruiserWrittenFromTheDocsHasItsModesNamedAndOnlyTrueCrossings) {
  const Scenario cruiser = loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/tests/data/vehicles/cruiser.yaml");
  EXPECT_GT(sweepAndCheck(cruiser, 4, 48, 4, {0.0, 20.0, 35.0}, "cruiser"), 0);
  sweepAndCheck(cruiser, 4, 8, 1, {20.0}, "cruiser (1 m/s grid)");
}

// A city bicycle on tyres written from the documentation alone: at walking pace its weave has split into
// two unstable real roots beside roll-led tyre and frame oscillations at 15-20 Hz (once an unstable
// `other`), and in turns its weave is slow. In the 10 deg turn below 1.5 m/s (tighter than the
// wheelbase) the trims between grid speeds once jumped between equilibria, and the count of unstable
// roots with them: reported then as critical speeds with no root on the axis.
TEST(RandomVehicles, CityBicycleWrittenFromTheDocsHasItsModesNamedAndOnlyTrueCrossings) {
  const Scenario bike = loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/tests/data/vehicles/citybike.yaml");
  sweepAndCheck(bike, 1, 12, 0.5, {0.0}, "city bicycle");
  sweepAndCheck(bike, 1, 12, 0.5, {10.0}, "city bicycle");
}

TEST(RandomVehicles, EnduroVariantsHaveTheirModesNamedAndEveryCrossing) {
  checkRandomVariants("enduro", 20261127, MOTOSTAB_RANDOM_VEHICLES);
}

TEST(RandomVehicles, SupersportVariantsHaveTheirModesNamedAndEveryCrossing) {
  checkRandomVariants("supersport", 1971, MOTOSTAB_RANDOM_VEHICLES);
}

// The wobble couples with the pitch in a turn on a motorcycle with a rear suspension: where their
// frequencies meet, two oscillations share the steer and the pitch motion and a steering damper damps
// both (a 6.7 Hz root unstable from 57 m/s at 20 deg was once `other`). Supersport and enduro variants
// with a drawn rear suspension and steering damper, 6-60 m/s at a drawn roll of 12-36 deg: the header's
// checks; from 12 m/s, where the two oscillations (damping ratio below 0.5) the small damper moves left
// most each fall at least half as much as the other and three times as much as any third, both are
// wobbles, and no wobble falls less than a tenth as much as the root the damper moves left most.
TEST(RandomVehicles, SprungMotorcyclesInATurnHaveTheirCoupledWobbleNamed) {
  PortableRandom g(20261129);
  int pairs = 0;
  for (int v = 0; v < 4 * MOTOSTAB_RANDOM_VEHICLES; ++v) {
    // Drawn in this order (the operands of one expression are evaluated in no fixed order).
    const double rate = g.drawUniform(25e3, 45e3), damping = g.drawUniform(1500, 3500), damper = g.drawUniform(0, 6);
    const std::vector<std::string> extra{"swingarm.suspension={wheel_rate_N_per_m: " + io::formatShortest(rate) +
                                             ", damping_Ns_per_m: " + io::formatShortest(damping) + "}",
                                         "steer_damper={damping_Nms_per_rad: " + io::formatShortest(damper) + "}"};
    const std::string name = v % 2 ? "enduro" : "supersport";
    const std::optional<Scenario> sprung = drawVariant(name, g, extra);
    ASSERT_TRUE(sprung) << "no physical variant of the " << name << " in 20 draws";
    const double roll = g.drawUniform(12, 36);
    const std::string what = "sprung " + name + " variant " + std::to_string(v);
    sweepAndCheck(*sprung, 6, 60, 2, {roll}, what);
    // The coupled wobble, from the same sweep with the damper raised by 0.05 N m s/rad.
    const VehicleModel model(*sprung), raised(addSteerDamping(*sprung, 0.05));
    SweepOptions opt;
    opt.start = 6, opt.stop = 60, opt.step = 2;
    opt.trim.roll = roll * M_PI / 180;
    const SweepResult sweep = runSweep(model, opt), damped = runSweep(raised, opt);
    ASSERT_EQ(sweep.speeds, damped.speeds);
    for (size_t k = 0; k < sweep.speeds.size(); ++k) {
      const auto shifts = listSteerDamperShifts(sweep.models[k], damped.models[k]);
      // No wobble that the damper does not damp: every `wobble` falls at least a tenth as much as the
      // root it moves left most (from 12 m/s: below, a weave the damper damps most may take the name).
      for (const auto& [shift, e] : shifts) {
        if (sweep.speeds[k] >= 12 && sweep.models[k].labels[e] == ModeLabel::Wobble) {
          EXPECT_LT(shift, 0.1 * std::min(shifts[0].first, 0.0))
              << what << " at " << roll << " deg, " << sweep.speeds[k] << " m/s: " << sweep.models[k].eigenvalues[e]
              << " is a wobble the steering damper hardly damps (" << shift << " against " << shifts[0].first << " 1/s)";
        }
      }
      // The pair: of the oscillations proper (damping ratio below 0.5: a near-real root at 0.85 Hz with
      // ratio 0.95 that the damper damps is no wobble), the two the damper moves left most.
      std::vector<std::pair<double, int>> oscillations;
      for (const auto& s : shifts)
        if (-sweep.models[k].eigenvalues[s.second].real() < 0.5 * std::abs(sweep.models[k].eigenvalues[s.second])) oscillations.push_back(s);
      if (sweep.speeds[k] < 12 || oscillations.size() < 2 || !(oscillations[1].first < 0.5 * oscillations[0].first)) continue;
      if (oscillations.size() > 2 && !(oscillations[1].first < 3 * std::min(oscillations[2].first, 0.0))) continue;
      ++pairs;
      for (int i : {0, 1}) {
        const int e = oscillations[i].second;
        EXPECT_EQ(sweep.models[k].labels[e], ModeLabel::Wobble)
            << what << " at " << roll << " deg, " << sweep.speeds[k] << " m/s: " << sweep.models[k].eigenvalues[e]
            << ", damped by a steering damper as much as the other wobble root, is " << toString(sweep.models[k].labels[e]);
      }
    }
  }
  std::cout << "sprung motorcycles: " << pairs << " coupled wobble checks\n";
  EXPECT_GT(pairs, 0) << "no two oscillations damped alike by the steering damper: the check checked nothing";
}

// Sharp's (1971) machine in a tight turn (30-36 deg, drawn, and 35 deg, 4-12 m/s on a 1 m/s grid): his
// stiff radial tyres (1e7 N/m, a static deflection near 0.1 mm) admit equilibria with a wheel in the
// air (the rear frame pitched by tens of degrees), which a warm-started trim once found at 8 m/s and
// 35 deg. Every speed of the sweep is a turn on both wheels: the lowest point of each knife-edge wheel
// plane, from the wheel's pose, z_C - R sqrt(1 - a_z^2) with a its spin axis, is at or below the
// ground. And the checks of the file's header: a count of unstable roots that changes between grid
// speeds has its critical speed (the capsize root leaving the weave pair near 4.2 m/s once had
// none), and every critical speed is a crossing.
TEST(RandomVehicles, SharpsMachineInATightTurnStaysOnBothWheels) {
  const Scenario sharp = loadScenario(kScenarios + "sharp1971.yaml");
  const VehicleModel model(sharp);
  PortableRandom g(1971035);
  for (double rollDeg : {35.0, g.drawUniform(30.0, 36.0)}) {
    SweepOptions opt;
    opt.start = 4, opt.stop = 12, opt.step = 1;
    opt.keepFailedSpeeds = true;
    opt.trim.roll = rollDeg * M_PI / 180;
    const SweepResult s = runSweep(model, opt);
    EXPECT_TRUE(s.failures.empty()) << rollDeg << " deg";
    for (const TrimPoint& p : s.trims) {
      const TrimResult t = restoreTrim(model, p);
      model.getSystem().realize(t.state, SimTK::Stage::Position);
      for (const auto& [w, radius] : {std::pair{&model.getRearWheel(), sharp.rearWheel.radius}, {&model.getFrontWheel(), sharp.frontWheel.radius}}) {
        const SimTK::Transform& X_GW = w->getBodyTransform(t.state);
        const double az = X_GW.R().y()[2];  // the spin axis: the wheel's y
        EXPECT_LE(X_GW.p()[2] - radius * std::sqrt(1 - az * az), 1e-9) << rollDeg << " deg, " << p.speed << " m/s: a wheel in the air";
      }
    }
    const std::string at = "Sharp (1971) at " + std::to_string(rollDeg) + " deg";
    checkSweep(s, s, at);
    checkCriticalSpeedsAreCrossings(model, opt, s, at);
  }
}

// In a tight turn at walking pace (35 deg, 4-10 m/s) on drawn supersport variants: every critical speed
// is a zero of some root (checked here on a cold trim and linearisation at that speed, apart from the
// sweep's tracking: where the tracked root jumps between eigenvalues the crossing must still be a
// zero), and the slow roll oscillation that the speed joins (|lambda| < 1 1/s, roll >= steer and at
// least a fifth of the motion lateral by the content shares) is named as lean motion, capsize or weave,
// never `other` or `longitudinal`.
TEST(RandomVehicles, TightTurnCrossingsAreZerosAndTheSlowLeanPairIsNamed) {
  const Scenario nominal = loadScenario(kScenarios + "supersport.yaml");
  PortableRandom g(3528);
  int slowPairs = 0;
  for (int v = 0; v < 2; ++v) {
    std::optional<Scenario> drawn;  // a draw whose derived rear frame is not a physical body is drawn again
    for (int attempt = 0; attempt < 20 && !drawn; ++attempt) {
      try {
        drawn = loadScenario(kScenarios + "supersport.yaml", drawVariation(nominal, g));
      } catch (const io::InputError&) {
      }
    }
    ASSERT_TRUE(drawn);
    const VehicleModel model(*drawn);
    SweepOptions opt;
    opt.start = 4, opt.stop = 10, opt.step = 1;
    opt.keepFailedSpeeds = true;
    opt.trim.roll = 35 * M_PI / 180;
    const SweepResult s = runSweep(model, opt);
    for (const CriticalSpeed& c : s.criticalSpeeds) {
      if (!c.refined) continue;
      TrimResult t = calcTrim(model, c.speed, opt.trim);
      const LinearModel lin = linearizeInPlace(model, t);
      // An oscillation crossing: a complex root on the imaginary axis; a real root crossing: one more
      // root at zero than the zero roots (heading, speed) of the grid speed below.
      auto countNear = [](const LinearModel& m, bool complex, double tol) {
        int n = 0;
        for (int e = 0; e < m.eigenvalues.size(); ++e)
          n += (m.eigenvalues[e].imag() > 1e-6) == complex && std::abs(m.eigenvalues[e].real()) < tol;
        return n;
      };
      size_t below = 0;
      while (below + 1 < s.speeds.size() && s.speeds[below + 1] < c.speed) ++below;
      if (c.frequency > 0) EXPECT_GT(countNear(lin, true, 1e-5), 0) << "variant " << v << ": " << toString(c.mode) << " at " << c.speed << " m/s";
      else EXPECT_GT(countNear(lin, false, 1e-5), countNear(s.models[below], false, 1e-5))
          << "variant " << v << ": " << toString(c.mode) << " at " << c.speed << " m/s";
    }
    for (const LinearModel& lin : s.models) {
      const std::vector<ModeContent> content = calcModeContents(lin);
      for (int e = 0; e < lin.eigenvalues.size(); ++e) {
        const std::complex<double> l = lin.eigenvalues[e];
        const ModeContent& c = content[e];
        if (!(l.imag() > 1e-6 && std::abs(l) < 1.0)) continue;
        if (c.get(vehicle::StateRole::Roll) < c.get(vehicle::StateRole::Steer) || c.calcRollYawLateral() + c.get(vehicle::StateRole::Steer) < 0.2) continue;
        ++slowPairs;
        EXPECT_TRUE(lin.labels[e] == ModeLabel::Capsize || lin.labels[e] == ModeLabel::Weave)
            << "variant " << v << " at " << lin.speed << " m/s: " << l << " is " << toString(lin.labels[e]);
      }
    }
  }
  EXPECT_GT(slowPairs, 0) << "no slow roll pair in the draws: the check checked nothing";
}

}  // namespace
}  // namespace motostab::analysis
