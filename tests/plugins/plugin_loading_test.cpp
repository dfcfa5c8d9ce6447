#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "vehicle/vehicle_model.h"

namespace motostab {
namespace {

// The benchmark scenario with its contact replaced and a plugin library listed.
std::string scenarioWith(const std::string& name, const std::string& contact, const std::string& library) {
  std::ifstream in(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const std::string from = "contact: {model: rolling_no_slip}";
  text.replace(text.find(from), from.size(), contact + "\nplugins: [" + library + "]");
  const auto p = std::filesystem::temp_directory_path() / ("motostab_plugin_" + name + ".yaml");
  std::ofstream(p) << text;
  return p.string();
}

TEST(Plugins, ExternalContactModelLoadsAndWorks) {
  const Scenario s = loadScenario(
      scenarioWith("ok", "contact: {model: example_vertical_spring, stiffness_N_per_m: 1.0e5}", MOTOSTAB_EXAMPLE_PLUGIN));
  const VehicleModel model(s);
  // The plugin's springs carry the weight: with both wheels deflected by d = m g / (2 k) the
  // vertical acceleration of the whole vehicle's centre of mass vanishes (Newton's second law).
  SimTK::State st = model.getDefaultState();
  const double weight = 94.0 * 9.81, d = weight / (2 * 1.0e5);
  st.updQ()[model.getIndices().height] = 0.3 - d;
  model.getSystem().realize(st, SimTK::Stage::Acceleration);
  EXPECT_NEAR(model.getMatter().calcSystemMassCenterAccelerationInGround(st)[2], 0.0, 1e-9);
  st.updQ()[model.getIndices().height] = 0.3 - 2 * d;  // twice the deflection: net upward g
  model.getSystem().realize(st, SimTK::Stage::Acceleration);
  EXPECT_NEAR(model.getMatter().calcSystemMassCenterAccelerationInGround(st)[2], 9.81, 1e-9);
}

TEST(Plugins, MissingLibraryIsAClearError) {
  const std::string file = scenarioWith("missing", "contact: {model: rolling_no_slip}", "/nonexistent/libnothing.so");
  try {
    VehicleModel model(loadScenario(file));
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(file), std::string::npos) << m;
    EXPECT_NE(m.find("plugins[0]"), std::string::npos) << m;
    EXPECT_NE(m.find("cannot load plugin library"), std::string::npos) << m;
  }
}

TEST(Plugins, DuplicateNameIsAClearError) {
  const std::string file = scenarioWith("dup", "contact: {model: rolling_no_slip}", MOTOSTAB_DUPLICATE_PLUGIN);
  try {
    VehicleModel model(loadScenario(file));
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("'rolling_no_slip' is registered twice"), std::string::npos) << m;
    EXPECT_NE(m.find("plugins[0]"), std::string::npos) << m;
  }
}

TEST(Plugins, UnknownPluginParameterIsRejectedByThePlugin) {
  const std::string file = scenarioWith("param", "contact: {model: example_vertical_spring, stiffnes_N_per_m: 1.0e5}",
                                        MOTOSTAB_EXAMPLE_PLUGIN);
  EXPECT_THROW(VehicleModel model(loadScenario(file)), InputError);
}

}  // namespace
}  // namespace motostab
