// Strict scenario loading: each class of bad input has its own error naming file, line, column and key.
#include <gtest/gtest.h>

#include "tests/support/text_file.h"

#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>

#include "tests/support/temp_dir.h"
#include "scenario/scenario.h"
#include "vehicle/vehicle_model.h"

namespace motostab::scenario {

using io::InputError;
using vehicle::VehicleModel;

namespace {

const std::string kScenario = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

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

std::string catchMessage(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A section --set creates that neither the scenario format nor any extension knows is an unknown
// section, named when the model is built (its extension sections are read then).
TEST(Scenario, SetCreatingAnUnknownSectionIsNamedAtBuild) {
  const std::string unknown = catchMessage([] { vehicle::VehicleModel{loadScenario(kEnduro, {"no_such_section.x_m=1"})}; });
  EXPECT_NE(unknown.find("no_such_section"), std::string::npos) << unknown;
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
