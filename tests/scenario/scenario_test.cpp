// Strict scenario loading: each class of bad input has its own error naming file, line, column and key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>

#include "tests/support/temp_dir.h"
#include "core/portable_random.h"
#include "scenario/parameter_paths.h"
#include "scenario/scenario.h"
#include "vehicle/vehicle_model.h"

namespace motostab::scenario {

using core::PortableRandom;
using io::InputError;
using vehicle::VehicleModel;

namespace {

const std::string kScenario = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

// Writes the benchmark (or `base`) scenario with one textual replacement and returns the path.
std::string variant(const std::string& name, const std::string& from, const std::string& to,
                    const std::string& base = kScenario) {
  std::string text = readText(base);
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  text.replace(pos, from.size(), to);
  const auto p = makeTempDir("bad") / ("motostab_bad_" + name + ".yaml");
  std::ofstream(p) << text;
  return p.string();
}

int lineOf(const std::string& path, const std::string& needle) {
  std::istringstream in(readText(path));
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.find(needle) != std::string::npos) return n;
  return -1;
}

// Loads (and builds, for plugin errors) and returns the error message.
std::string errorOf(const std::string& path) {
  try {
    VehicleModel model(loadScenario(path));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expectError(const std::string& path, const std::string& lineNeedle, const std::string& key, const std::string& reason) {
  const std::string m = errorOf(path);
  ASSERT_FALSE(m.empty()) << "no error for " << path;
  const std::string where = path + ":" + std::to_string(lineOf(path, lineNeedle)) + ":";
  EXPECT_EQ(m.rfind(where, 0), 0u) << m << " (expected to start with " << where << ")";
  EXPECT_TRUE(std::regex_search(m, std::regex(":[0-9]+:[0-9]+: "))) << "no line:column in " << m;
  EXPECT_NE(m.find(key), std::string::npos) << m;
  EXPECT_NE(m.find(reason), std::string::npos) << m;
}

TEST(Scenario, BenchmarkLoads) {
  const Scenario s = loadScenario(kScenario);
  EXPECT_EQ(s.name, "whipple-benchmark");
  EXPECT_DOUBLE_EQ(s.rearFrame.inertia.xz, -2.4);
  EXPECT_NEAR(s.geometry.steerAxisTilt, M_PI / 10, 1e-15);
}

TEST(Scenario, UnknownKey) {
  expectError(variant("unknown", "  trail_m: 0.08", "  trail_m: 0.08\n  trial_m: 0.08"), "trial_m", "geometry.trial_m",
              "unknown key");
}

TEST(Scenario, MissingKey) {
  expectError(variant("missing", "  trail_m: 0.08\n", ""), "wheelbase_m", "geometry.trail_m", "missing key");
}

TEST(Scenario, NonPositiveMass) {
  expectError(variant("mass", "  mass_kg: 85", "  mass_kg: -85"), "mass_kg: -85", "rear_frame.mass_kg", "must be positive");
}

TEST(Scenario, NonPositiveRadius) {
  expectError(variant("radius", "  radius_m: 0.35", "  radius_m: -0.35"), "radius_m: -0.35", "front_wheel.radius_m",
              "must be positive");
}

TEST(Scenario, InertiaNotPositiveDefinite) {
  expectError(variant("pd", "{xx: 9.2, yy: 11, zz: 2.8, xy: 0, xz: -2.4", "{xx: 9.2, yy: 11, zz: 0.5, xy: 0, xz: -2.4"),
              "zz: 0.5", "rear_frame.inertia_kgm2", "not positive definite");
}

TEST(Scenario, InertiaViolatesTriangleInequality) {
  expectError(variant("triangle", "{xx: 9.2, yy: 11, zz: 2.8, xy: 0, xz: -2.4", "{xx: 9.2, yy: 20, zz: 2.8, xy: 0, xz: 0"),
              "yy: 20", "rear_frame.inertia_kgm2", "triangle inequality");
}

// A speed range whose step count overflows (or would fill the memory) is an input error, not a crash.
TEST(Scenario, SpeedRangeWithTooManySteps) {
  expectError(variant("speeds", "{start: 0, stop: 10, step: 0.1}", "{start: 0, stop: 100, step: 1e-3}"),
              "speeds_mps", "speeds_mps.step", "gives 100001 speeds; at most 10000");
  expectError(variant("speeds4", "{start: 0, stop: 10, step: 0.1}", "{start: 0, stop: 9999, step: 1}"),
              "speeds_mps", "speeds_mps.stop", "speeds above 150 m/s");
  // A number beyond any physical magnitude is refused where it is read, before the range is formed.
  expectError(variant("speeds3", "{start: 0, stop: 10, step: 0.1}", "{start: 0, stop: 1e300, step: 1e-300}"),
              "speeds_mps", "speeds_mps.stop", "a magnitude above 1e12");
  expectError(variant("speeds2", "{start: 0, stop: 10, step: 0.1}", "{start: 0, stop: 1e9, step: 1e-3}"),
              "speeds_mps", "speeds_mps.stop", "speeds above 150 m/s");
}

TEST(Scenario, UnknownPlugin) {
  expectError(variant("plugin", "{model: rolling_no_slip}", "{model: magic_tyre}"), "magic_tyre", "contact.model",
              "unknown contact plugin 'magic_tyre'");
}

TEST(Scenario, WrongType) {
  expectError(variant("type", "  wheelbase_m: 1.02", "  wheelbase_m: long"), "wheelbase_m: long", "geometry.wheelbase_m",
              "expected a finite number");
}

TEST(Scenario, UnknownPluginParameter) {
  expectError(variant("pluginparam", "{model: rolling_no_slip}", "{model: rolling_no_slip, grip: 1}"), "grip", "contact.grip",
              "unknown key");
}

TEST(Scenario, OverrideReplacesValue) {
  const Scenario s = loadScenario(kScenario, {"geometry.trail_m=0.1"});
  EXPECT_DOUBLE_EQ(s.geometry.trail, 0.1);
  EXPECT_THROW(loadScenario(kScenario, {"geometry.trail_m.x=0.1"}), InputError);
}

// The enduro with a rear suspension mapping `fields` after its compliance line.
std::string suspensionVariant(const std::string& name, const std::string& fields) {
  return variant(name, "  compliance: rigid", "  compliance: rigid\n  suspension: {" + fields + "}", kEnduro);
}

TEST(Scenario, SuspensionNegativeWheelRate) {
  expectError(suspensionVariant("susp_rate", "wheel_rate_N_per_m: -20000, damping_Ns_per_m: 1500"),
              "wheel_rate_N_per_m: -20000", "swingarm.suspension.wheel_rate_N_per_m", "must be positive");
}

TEST(Scenario, SuspensionNegativeDamping) {
  expectError(suspensionVariant("susp_damping", "stiffness_Nm_per_rad: 6000, damping_Nms_per_rad: -1"),
              "damping_Nms_per_rad: -1", "swingarm.suspension.damping_Nms_per_rad", "must not be negative");
}

TEST(Scenario, SuspensionUnknownKey) {
  expectError(suspensionVariant("susp_unknown", "wheel_rate_N_per_m: 20000, damping_Ns_per_m: 1500, preload_N: 10"),
              "preload_N", "swingarm.suspension.preload_N", "unknown key");
}

TEST(Scenario, SuspensionMissingStiffness) {
  expectError(suspensionVariant("susp_missing", "damping_Ns_per_m: 1500"), "suspension:",
              "swingarm.suspension.wheel_rate_N_per_m", "missing key");
}

TEST(Scenario, SuspensionStiffnessGivenTwice) {
  expectError(suspensionVariant("susp_twice", "wheel_rate_N_per_m: 2, stiffness_Nm_per_rad: 1, damping_Ns_per_m: 0"),
              "stiffness_Nm_per_rad", "swingarm.suspension.wheel_rate_N_per_m", "give only one");
}

// Wheel-referred values are referred to the pivot by the horizontal pivot-to-hub distance (the
// enduro's pivot_m[0] = 0.5502 m); pivot values are taken unchanged.
TEST(Scenario, SuspensionWheelRateConversion) {
  const Scenario none = loadScenario(kEnduro);
  EXPECT_FALSE(none.swingarm.hasSuspension);
  const Scenario wheel = loadScenario(kEnduro, {"swingarm.suspension={wheel_rate_N_per_m: 20000, damping_Ns_per_m: 1500}"});
  ASSERT_TRUE(wheel.swingarm.hasSuspension);
  EXPECT_NEAR(wheel.swingarm.suspension.stiffness, 20000 * 0.5502 * 0.5502, 1e-9);
  EXPECT_NEAR(wheel.swingarm.suspension.damping, 1500 * 0.5502 * 0.5502, 1e-12);
  const Scenario pivot = loadScenario(kEnduro, {"swingarm.suspension={stiffness_Nm_per_rad: 6000, damping_Nms_per_rad: 400}"});
  EXPECT_DOUBLE_EQ(pivot.swingarm.suspension.stiffness, 6000);
  EXPECT_DOUBLE_EQ(pivot.swingarm.suspension.damping, 400);
}

std::string catchMessage(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Key by key, --set creates the missing `suspension` map; the result equals the whole-section form
// (values drawn in the test). A created section still meets the strict reader.
TEST(Scenario, SetCreatesAMissingSectionKeyByKey) {
  PortableRandom rng(20261124);
  const double rate = 1e4 + 3e4 * rng.drawUniform(), damping = 500 + 2000 * rng.drawUniform();
  const Scenario keys = loadScenario(kEnduro, {formatOverride("swingarm.suspension.wheel_rate_N_per_m", rate),
                                               formatOverride("swingarm.suspension.damping_Ns_per_m", damping)});
  const std::string r = formatOverride("r", rate).substr(2), c = formatOverride("c", damping).substr(2);
  const Scenario whole =
      loadScenario(kEnduro, {"swingarm.suspension={wheel_rate_N_per_m: " + r + ", damping_Ns_per_m: " + c + "}"});
  ASSERT_TRUE(keys.swingarm.hasSuspension);
  EXPECT_EQ(keys.swingarm.suspension.stiffness, whole.swingarm.suspension.stiffness);
  EXPECT_EQ(keys.swingarm.suspension.damping, whole.swingarm.suspension.damping);
  EXPECT_NEAR(keys.swingarm.suspension.stiffness, rate * 0.5502 * 0.5502, 1e-9 * rate);
  // Only one of the two required keys: the reader names the missing one.
  const std::string missing = catchMessage([] { loadScenario(kEnduro, {"swingarm.suspension.damping_Ns_per_m=1500"}); });
  EXPECT_NE(missing.find("wheel_rate_N_per_m"), std::string::npos) << missing;
  // A created section that neither the scenario format nor any extension knows is an unknown section,
  // named when the model is built (its extension sections are read then).
  const std::string unknown = catchMessage([] { vehicle::VehicleModel{loadScenario(kEnduro, {"no_such_section.x_m=1"})}; });
  EXPECT_NE(unknown.find("no_such_section"), std::string::npos) << unknown;
  const std::string deep = catchMessage([] {
    loadScenario(kEnduro, {"swingarm.suspension.wheel_rate_N_per_m=2e4", "swingarm.suspension.damping_Ns_per_m=1e3",
                           "swingarm.suspension.spring.rate=1"});
  });
  EXPECT_NE(deep.find("spring"), std::string::npos) << deep;
}

// Derived quantities against hand calculation from Meijaard et al. (2007) Table 1.
TEST(Scenario, DerivedQuantities) {
  const Scenario s = loadScenario(kScenario);
  const MassSummary m = calcMassSummary(s);
  EXPECT_DOUBLE_EQ(m.mass, 94.0);
  EXPECT_NEAR(m.com[0], (85 * 0.3 + 4 * 0.9 + 3 * 1.02) / 94.0, 1e-14);
  EXPECT_NEAR(m.com[2], (85 * 0.9 + 4 * 0.7 + 2 * 0.3 + 3 * 0.35) / 94.0, 1e-14);
  EXPECT_NEAR(calcNormalTrail(s.geometry), 0.08 * std::cos(M_PI / 10), 1e-15);
  const auto loads = calcStaticWheelLoads(s);
  EXPECT_NEAR(loads[0] + loads[1], 94 * 9.81, 1e-9);
  EXPECT_NEAR(loads[1], 94 * 9.81 * m.com[0] / 1.02, 1e-9);
}

}  // namespace
}  // namespace motostab::scenario
