// One scenario source: typed parameter changes applied to a copy of the parsed tree give what the
// same changes as --set text give, keep doubles to the bit, and fail with the same messages.
#include "tests/support/extension_sections.h"
#include "scenario/scenario_source.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>

#include "core/portable_random.h"
#include "io/number.h"
#include "io/yaml_map.h"
#include "tests/support/temp_dir.h"
#include "vehicle/vehicle_model.h"

namespace motostab::scenario {

using core::PortableRandom;
using io::InputError;
using io::copyTree;
using io::formatShortest;
using io::getYamlFileOpenCount;
using io::loadYamlFile;

namespace {

const std::string kScenario = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";
const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

// "path=value" with 17 significant digits, written here (not by the code under test).
std::string makeText(const std::string& path, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return path + "=" + buf;
}

std::string catchMessage(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

TEST(ScenarioSource, TypedChangesEqualTextChangesToTheBit) {
  PortableRandom random(20261125);
  const ScenarioSource source(kScenario);
  for (int trial = 0; trial < 20; ++trial) {
    const double trail = random.drawUniform(0.02, 0.15), mass = random.drawUniform(60, 110);
    const double comZ = random.drawUniform(-1.2, -0.8), radius = random.drawUniform(0.3, 0.4);
    ParameterOverrides typed;
    typed.set("geometry.trail_m", trail);
    typed.set("rear_frame.mass_kg", mass);
    typed.set("rear_frame.com_m[2]", comZ);
    typed.set("front_wheel.radius_m", radius);
    const Scenario a = source.load(typed);
    const Scenario b = loadScenario(kScenario, {makeText("geometry.trail_m", trail), makeText("rear_frame.mass_kg", mass),
                                                makeText("rear_frame.com_m[2]", comZ),
                                                makeText("front_wheel.radius_m", radius)});
    EXPECT_EQ(a.geometry.trail, trail);
    EXPECT_EQ(a.rearFrame.mass, mass);
    EXPECT_EQ(a.rearFrame.com[2], comZ);
    EXPECT_EQ(a.frontWheel.radius, radius);
    EXPECT_EQ(a.geometry.trail, b.geometry.trail);
    EXPECT_EQ(a.rearFrame.mass, b.rearFrame.mass);
    EXPECT_EQ(a.rearFrame.com[2], b.rearFrame.com[2]);
    EXPECT_EQ(a.frontWheel.radius, b.frontWheel.radius);
  }
}

// 1/sqrt(2) = 0.70710678118654757 (17 digits); six digits ("0.707107") would lose 2.8e-7 of it.
TEST(ScenarioSource, FullPrecisionSurvives) {
  const double v = 1.0 / std::sqrt(2.0);
  ParameterOverrides o;
  o.set("geometry.trail_m", 0.1 * v);
  o.set("rear_frame.mass_kg", 100 * v);
  const Scenario s = ScenarioSource(kScenario).load(o);
  EXPECT_EQ(s.geometry.trail, 0.1 * v);
  EXPECT_EQ(s.rearFrame.mass, 100 * v);
  EXPECT_EQ(std::strtod(formatShortest(v).c_str(), nullptr), v);
  EXPECT_NE(std::strtod(std::to_string(v).c_str(), nullptr), v);
  EXPECT_EQ(formatShortest(0.1), "0.1");
}

// Text that reads as a number keeps the user's digits where the scenario expects text, and its value
// where it expects a number.
TEST(ScenarioSource, NumberLikeTextKeepsItsDigits) {
  const Scenario s = ScenarioSource(kScenario).load(ParameterOverrides(
      std::vector<std::string>{"name=1e3", "description=1.50", "geometry.trail_m=8.0e-2"}));
  EXPECT_EQ(s.name, "1e3");
  EXPECT_EQ(s.description, "1.50");
  EXPECT_EQ(s.geometry.trail, 0.08);
}

TEST(ScenarioSource, SwitchesAndSectionsAsTyped) {
  const ScenarioSource source(kEnduro);
  ParameterOverrides o;
  o.set("swingarm.compliance", "twist");
  o.setNode("steer_damper", YAML::Load("{damping_Nms_per_rad: 0.4}"));
  const Scenario s = source.load(o);
  EXPECT_EQ(s.swingarm.compliance, "twist");
  EXPECT_EQ(testing::getExtensionValue(s, "steer_damper", "damping_Nms_per_rad").as<double>(), 0.4);
  EXPECT_NO_THROW(vehicle::VehicleModel{s});  // a valid steer_damper section
  // A later key inside a section set before it wins, and the section stays the override's own copy.
  o.set("steer_damper.damping_Nms_per_rad", 0.7);
  EXPECT_EQ(testing::getExtensionValue(source.load(o), "steer_damper", "damping_Nms_per_rad").as<double>(), 0.7);
  EXPECT_EQ(std::get<YAML::Node>(o.getItems()[1].value)["damping_Nms_per_rad"].as<double>(), 0.4);
}

TEST(ScenarioSource, UnknownKeyInAChangeNamesTheKey) {
  const ScenarioSource source(kScenario);
  ParameterOverrides o;
  o.set("geometry.trial_m", 0.08);
  const std::string typed = catchMessage([&] { source.load(o); });
  EXPECT_NE(typed.find("geometry.trial_m"), std::string::npos) << typed;
  EXPECT_NE(typed.find("unknown key"), std::string::npos) << typed;
  EXPECT_EQ(typed, catchMessage([&] { loadScenario(kScenario, {"geometry.trial_m=0.08"}); }));
  ParameterOverrides section;
  section.setNode("steer_damper", YAML::Load("{damping_Nms_per_rad: 0.4, dampnig: 1}"));
  const std::string inSection = catchMessage([&] { vehicle::VehicleModel{source.load(section)}; });
  EXPECT_NE(inSection.find("steer_damper.dampnig"), std::string::npos) << inSection;
}

TEST(ScenarioSource, BadValueGivesTheTextRoutesMessage) {
  PortableRandom random(77);
  const double w = -random.drawUniform(0.5, 1.5);
  ParameterOverrides o;
  o.set("geometry.wheelbase_m", w);
  const std::string typed = catchMessage([&] { ScenarioSource(kScenario).load(o); });
  const std::string text = catchMessage([&] { loadScenario(kScenario, {makeText("geometry.wheelbase_m", w)}); });
  // At the key's place in the file (its line found here in the file's text), as for --set text.
  std::ifstream in(kScenario);
  std::string line;
  int number = 0, keyLine = 0;
  while (std::getline(in, line) && keyLine == 0)
    if (++number && line.rfind("  wheelbase_m:", 0) == 0) keyLine = number;
  const std::string head = kScenario + ":" + std::to_string(keyLine) + ":3: geometry.wheelbase_m: must be positive";
  EXPECT_EQ(typed.substr(0, head.size()), head) << typed;
  EXPECT_EQ(text.substr(0, head.size()), head) << text;
  EXPECT_EQ(typed.substr(0, typed.find("(value from")), text.substr(0, text.find("(value from")));
  EXPECT_NE(typed.find("(value from --set geometry.wheelbase_m="), std::string::npos) << typed;
}

// Every node of the copy carries the original's mark (YAML::Clone would drop them).
void expectSameMarks(const YAML::Node& a, const YAML::Node& b) {
  ASSERT_EQ(a.Type(), b.Type());
  EXPECT_EQ(a.Mark().line, b.Mark().line);
  EXPECT_EQ(a.Mark().column, b.Mark().column);
  if (a.IsMap()) {
    auto ib = b.begin();
    for (auto ia = a.begin(); ia != a.end(); ++ia, ++ib) {
      EXPECT_EQ(ia->first.Scalar(), ib->first.Scalar());
      EXPECT_EQ(ia->first.Mark().line, ib->first.Mark().line);
      expectSameMarks(ia->second, ib->second);
    }
  } else if (a.IsSequence()) {
    for (size_t i = 0; i < a.size(); ++i) expectSameMarks(a[i], b[i]);
  } else if (a.IsScalar()) {
    EXPECT_EQ(a.Scalar(), b.Scalar());
  }
}

TEST(ScenarioSource, CopyKeepsEveryMark) {
  const YAML::Node original = loadYamlFile(kEnduro).getNode();
  const YAML::Node copy = copyTree(original);
  expectSameMarks(original, copy);
  EXPECT_GT(copy["geometry"]["wheelbase_m"].Mark().line, 0);
}

// A check on an unchanged key of the file points at its line in the file, read from the copy.
TEST(ScenarioSource, ErrorsInTheCopyPointAtTheFile) {
  const auto dir = makeTempDir("scenario_source_marks");
  std::ifstream in(kScenario);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = "  crown_radius_m: 0\n";
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, from.size(), "  crown_radius_m: 0.2\n");
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  const std::string file = (dir / "crown.yaml").string();
  std::ofstream(file) << text;
  ParameterOverrides o;
  o.set("rear_wheel.radius_m", 0.15);  // now below the file's crown radius of 0.2 m
  const std::string message = catchMessage([&] { ScenarioSource(file).load(o); });
  EXPECT_EQ(message.find(file + ":" + std::to_string(line) + ":3: rear_wheel.crown_radius_m"), 0u) << message;
}

TEST(ScenarioSource, ReadsTheFileOnce) {
  const long before = getYamlFileOpenCount(kScenario);
  const ScenarioSource source(kScenario);
  PortableRandom random(5);
  for (int i = 0; i < 10; ++i) {
    ParameterOverrides o;
    o.set("geometry.trail_m", random.drawUniform(0.05, 0.1));
    source.load(o);
  }
  EXPECT_EQ(getYamlFileOpenCount(kScenario) - before, 1);
}

}  // namespace
}  // namespace motostab::scenario
