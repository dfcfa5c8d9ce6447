// Key paths of scalar parameters (scenario/parameter_paths.h) and `--set` with sequence indices.
#include "core/portable_random.h"
#include "scenario/parameter_paths.h"

#include <gtest/gtest.h>

#include <set>

#include "scenario/scenario.h"
#include "io/yaml_map.h"
#include "plugins/builtin.h"
#include "vehicle/vehicle_model.h"

namespace motostab::scenario {

using core::PortableRandom;
using io::InputError;
using io::applyOverride;
using io::findKeyPath;
using io::loadYamlFile;

namespace {

const std::string kWhipple = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";
const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

// The parameters of `tree` by the declared sections of the built-in plugins.
std::vector<ScalarParameter> listScalarParameters(const YAML::Node& tree) {
  return scenario::listScalarParameters(tree, plugins::listSectionFields(plugins::makeBuiltinRegistry()));
}

TEST(ParameterPaths, ListsEveryVehicleScalarOfTheBenchmarkOnce) {
  const YAML::Node tree = loadYamlFile(kWhipple).getNode();
  const auto params = listScalarParameters(tree);
  // Meijaard 2007 Table 1 as the scenario writes it: 3 geometry + 2 bodies x (1 + 3 + 6) + 2 wheels x 5.
  EXPECT_EQ(params.size(), 3u + 2 * 10 + 2 * 5);
  std::set<std::string> names;
  for (const auto& p : params) EXPECT_TRUE(names.insert(p.path).second) << p.path;
  for (const char* expected : {"geometry.trail_m", "rear_frame.com_m[2]", "front_frame.inertia_kgm2.xz",
                               "rear_wheel.spin_inertia_kgm2", "geometry.steer_axis_tilt_deg"})
    EXPECT_TRUE(names.count(expected)) << expected;
  for (const auto& p : params) EXPECT_DOUBLE_EQ(getScalarParameter(tree, p.path), p.value) << p.path;
  EXPECT_DOUBLE_EQ(getScalarParameter(tree, "rear_frame.com_m[2]"), 0.9);  // Table 1: z_B = -0.9 (z down)
  EXPECT_DOUBLE_EQ(getScalarParameter(tree, "geometry.steer_axis_tilt_deg"), 18.0);
}

TEST(ParameterPaths, KindsAndDefaultSigmas) {
  const YAML::Node tree = loadYamlFile(kWhipple).getNode();
  for (const auto& p : listScalarParameters(tree)) {
    if (p.path == "geometry.trail_m") {
      EXPECT_EQ(p.kind, ParameterKind::Length);
      EXPECT_DOUBLE_EQ(getDefaultSigma(p), 0.01);
    } else if (p.path == "geometry.steer_axis_tilt_deg") {
      EXPECT_EQ(p.kind, ParameterKind::Angle);
      EXPECT_DOUBLE_EQ(getDefaultSigma(p), 1.0);
    } else if (p.path == "rear_frame.mass_kg") {
      EXPECT_EQ(p.kind, ParameterKind::Mass);
      EXPECT_DOUBLE_EQ(getDefaultSigma(p), 8.5);  // 10 % of 85 kg
    } else if (p.path == "rear_frame.inertia_kgm2.xy") {
      // A zero product of inertia takes its tensor's largest diagonal entry (yy = 11) as scale.
      EXPECT_EQ(p.kind, ParameterKind::Inertia);
      EXPECT_DOUBLE_EQ(getDefaultSigma(p), 1.1);
    }
  }
}

TEST(ParameterPaths, SwingarmBodyAndPivotAreListedButNotItsPluginKeys) {
  const YAML::Node tree = loadYamlFile(kEnduro).getNode();
  bool pivot = false;
  for (const auto& p : listScalarParameters(tree)) {
    pivot |= p.path == "swingarm.pivot_m[0]";
    EXPECT_EQ(p.path.find("stiffness"), std::string::npos) << p.path;
  }
  EXPECT_TRUE(pivot);
}

TEST(ParameterPaths, IndexedOverrideChangesOnlyThatElement) {
  PortableRandom rng(20261124);
  const double z = 0.5 + static_cast<double>(rng.drawBits() % 1000) / 1000.0;
  const Scenario base = loadScenario(kWhipple);
  const Scenario s = loadScenario(kWhipple, {formatOverride("rear_frame.com_m[2]", z)});
  EXPECT_EQ(s.rearFrame.com[2], z);  // 17 digits round-trip exactly
  EXPECT_EQ(s.rearFrame.com[0], base.rearFrame.com[0]);
  EXPECT_EQ(s.rearFrame.com[1], base.rearFrame.com[1]);
  const Scenario t = loadScenario(kWhipple, {formatOverride("front_frame.inertia_kgm2.xz", 0.01)});
  EXPECT_EQ(t.frontFrame.inertia.xz, 0.01);
}

TEST(ParameterPaths, BadPathsAreNamedInputErrors) {
  EXPECT_THROW(loadScenario(kWhipple, {"rear_frame.com_m[3]=1"}), InputError);
  EXPECT_THROW(loadScenario(kWhipple, {"rear_frame.com_m[x]=1"}), InputError);
  EXPECT_THROW(loadScenario(kWhipple, {"rear_frame.mass_kg[0]=1"}), InputError);
  EXPECT_THROW(vehicle::VehicleModel{loadScenario(kWhipple, {"nothing.here=1"})}, InputError);  // an unknown section
  EXPECT_THROW(loadScenario(kWhipple, {"rear_frame.mass_kg=[1, 2"}), InputError);
  try {
    loadScenario(kWhipple, {"rear_frame.com_m[7]=1"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rear_frame.com_m[7]"), std::string::npos) << e.what();
  }
  const YAML::Node tree = loadYamlFile(kWhipple).getNode();
  EXPECT_THROW(getScalarParameter(tree, "geometry.nothing"), InputError);
  EXPECT_THROW(getScalarParameter(tree, "name"), InputError);
  EXPECT_FALSE(findKeyPath(tree, "geometry.nothing"));
  EXPECT_FALSE(tree["geometry"]["nothing"].IsDefined());  // the lookup inserted nothing
}

TEST(ParameterPaths, SetCanAddAWholeSection) {
  YAML::Node tree = loadYamlFile(kWhipple).getNode();
  applyOverride(tree, "new_section={a_m: 0.4}");
  EXPECT_DOUBLE_EQ(getScalarParameter(tree, "new_section.a_m"), 0.4);
}

}  // namespace
}  // namespace motostab::scenario
