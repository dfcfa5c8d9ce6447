#include <dlfcn.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/temp_dir.h"
#include "analysis/sweep.h"
#include "core/portable_random.h"
#include "diagnosis/candidates.h"
#include "io/number.h"
#include "plugins/builtin.h"
#include "scenario/parameter_paths.h"
#include "vehicle/vehicle_model.h"

namespace motostab::plugins {

using analysis::SweepOptions;
using analysis::SweepResult;
using analysis::runSweep;
using io::InputError;
using io::InputLocation;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::ModelExtension;
using vehicle::VehicleModel;

namespace {

// The benchmark scenario with its contact replaced and a plugin library listed.
std::string scenarioWith(const std::string& name, const std::string& contact, const std::string& library,
                         const std::filesystem::path& dir = makeTempDir("plugins")) {
  std::ifstream in(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const std::string from = "contact: {model: rolling_no_slip}";
  text.replace(text.find(from), from.size(), contact + "\nplugins: [" + library + "]");
  const auto p = dir / ("motostab_plugin_" + name + ".yaml");
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

// Largest distance, relative to 1 + |lambda|, from an eigenvalue of one sweep to its nearest unused
// partner in the other (one-to-one; real parts near zero make any sort order unstable).
double compareSweeps(const SweepResult& r1, const SweepResult& r2) {
  EXPECT_EQ(r2.models.size(), r1.models.size());
  double worst = 0;
  for (size_t k = 0; k < std::min(r1.models.size(), r2.models.size()); ++k) {
    const Eigen::VectorXcd& a = r1.models[k].eigenvalues;
    const Eigen::VectorXcd& b = r2.models[k].eigenvalues;
    if (a.size() != b.size()) return 1e300;
    std::vector<bool> used(b.size(), false);
    for (Eigen::Index i = 0; i < a.size(); ++i) {
      Eigen::Index best = -1;
      for (Eigen::Index j = 0; j < b.size(); ++j)
        if (!used[j] && (best < 0 || std::abs(a[i] - b[j]) < std::abs(a[i] - b[best]))) best = j;
      used[best] = true;
      worst = std::max(worst, std::abs(a[i] - b[best]) / (1 + std::abs(a[i])));
    }
  }
  return worst;
}

SweepResult sweepWithThreads(const VehicleModel& model, int threads) {
  SweepOptions o;
  o.start = 1, o.stop = 4, o.step = 0.5;
  o.threads = threads;
  return runSweep(model, o);
}

// Regression: sweep workers rebuilt the model with the built-in plugins only, dropping plugins
// supplied through the registry and every ModelExtension on --threads 2. Threaded sweeps agree with
// the serial one to the trim tolerance (the workers meet at timing-dependent speeds).
TEST(Plugins, SharedLibraryContactReachesEverySweepWorker) {
  // Listed in the scenario.
  const Scenario listed = loadScenario(
      scenarioWith("sweep", "contact: {model: example_vertical_spring, stiffness_N_per_m: 1.0e5}", MOTOSTAB_EXAMPLE_PLUGIN));
  const VehicleModel model(listed);
  const SweepResult serial = sweepWithThreads(model, 1);
  ASSERT_EQ(serial.models.size(), 7u);
  EXPECT_GT(serial.models[0].eigenvalues.size(), 4);  // height and pitch are free on the springs
  EXPECT_LT(compareSweeps(serial, sweepWithThreads(model, 2)), 1e-7);
  // Loaded into the registry by the caller, not named in the scenario.
  Scenario unlisted = listed;
  unlisted.plugins.clear();
  PluginRegistry registry = makeBuiltinRegistry();
  registry.loadLibrary(MOTOSTAB_EXAMPLE_PLUGIN, {"test", 0, 0, ""});
  const VehicleModel fromRegistry(unlisted, registry);
  EXPECT_LT(compareSweeps(serial, sweepWithThreads(fromRegistry, 2)), 1e-7);
}

// A plugin library's declared measured field is a parameter: listed with the scenario's registry
// (the built-in one does not know it), varied by diagnosis as `parameter:contact.stiffness_N_per_m`,
// and only while `contact.model` selects the plugin. The value is drawn.
TEST(Plugins, LibraryDeclaredFieldsAreParameters) {
  core::PortableRandom rng(20261129);
  const double k = rng.drawUniform(5e4, 5e5);
  const std::string file = scenarioWith(
      "fields", "contact: {model: example_vertical_spring, stiffness_N_per_m: " + io::formatShortest(k) + "}", MOTOSTAB_EXAMPLE_PLUGIN);
  const Scenario s = loadScenario(file);
  const YAML::Node tree = YAML::LoadFile(file);
  const auto find = [](const std::vector<scenario::ScalarParameter>& all, const std::string& path) {
    return std::find_if(all.begin(), all.end(), [&](const auto& p) { return p.path == path; }) != all.end();
  };
  const auto sections = listSectionFields(makeScenarioRegistry(s));
  const auto parameters = scenario::listScalarParameters(tree, sections);
  ASSERT_TRUE(find(parameters, "contact.stiffness_N_per_m"));
  for (const auto& p : parameters)
    if (p.path == "contact.stiffness_N_per_m") {
      EXPECT_EQ(p.value, k);
      EXPECT_TRUE(p.positive);
    }
  EXPECT_FALSE(find(scenario::listScalarParameters(tree, listSectionFields(makeBuiltinRegistry())), "contact.stiffness_N_per_m"));
  const auto candidates = diagnosis::listCandidates(tree, {}, nullptr, {}, sections);
  EXPECT_TRUE(std::any_of(candidates.begin(), candidates.end(),
                          [](const auto& c) { return c.name == "parameter:contact.stiffness_N_per_m"; }));
  // Another contact model selected: the plugin's keys do not apply.
  YAML::Node other = YAML::Clone(tree);
  other["contact"]["model"] = "rolling_no_slip";
  EXPECT_FALSE(find(scenario::listScalarParameters(other, sections), "contact.stiffness_N_per_m"));
  // Read through the declaration: its range is checked at the key.
  try {
    const VehicleModel bad(loadScenario(file, {"contact.stiffness_N_per_m=-" + io::formatShortest(k)}));
    ADD_FAILURE() << "a negative stiffness was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.getLocation().key, "contact.stiffness_N_per_m");
  }
}

TEST(Plugins, ModelExtensionsReachEverySweepWorker) {
  // A steer damper added by an extension (0.5 N m s/rad) changes the Whipple eigenvalues; both
  // workers of a threaded sweep must have it.
  const Scenario s = loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml");
  PluginRegistry registry = makeBuiltinRegistry();
  ModelExtension damper = [](BuildContext& ctx, const VehicleModel& m) {
    SimTK::Force::MobilityLinearDamper(ctx.forces, m.getFrontFrame(), SimTK::MobilizerUIndex(0), 0.5);
    return std::vector<vehicle::AuxiliaryState>{};
  };
  const VehicleModel damped(s, registry, {damper}), plain(s);
  const SweepResult serial = sweepWithThreads(damped, 1);
  EXPECT_GT(compareSweeps(serial, sweepWithThreads(plain, 1)), 1e-3);
  EXPECT_LT(compareSweeps(serial, sweepWithThreads(damped, 2)), 1e-7);
}

TEST(Plugins, ReplicaKeepsPluginsAndExtensions) {
  const Scenario s = loadScenario(
      scenarioWith("replica", "contact: {model: example_vertical_spring, stiffness_N_per_m: 1.0e5}", MOTOSTAB_EXAMPLE_PLUGIN));
  PluginRegistry registry = makeBuiltinRegistry();
  int calls = 0;
  ModelExtension extension = [&calls](BuildContext&, const VehicleModel&) {
    ++calls;
    return std::vector<vehicle::AuxiliaryState>{};
  };
  const VehicleModel model(s, registry, {extension});
  const auto replica = model.makeReplica();
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(replica->getNumQ(), model.getNumQ());
  EXPECT_EQ(replica->getScenario().contact.model, "example_vertical_spring");
}

TEST(Plugins, LibraryLoadsOncePerProcess) {
  const InputLocation where{"test", 0, 0, "plugins[0]"};
  PluginRegistry a = makeBuiltinRegistry(), b = makeBuiltinRegistry();
  a.loadLibrary(MOTOSTAB_EXAMPLE_PLUGIN, where);
  a.loadLibrary(MOTOSTAB_EXAMPLE_PLUGIN, where);  // again into the same registry: skipped, no duplicate error
  b.loadLibrary(MOTOSTAB_EXAMPLE_PLUGIN, where);
  void* handle = dlopen(MOTOSTAB_EXAMPLE_PLUGIN, RTLD_NOW | RTLD_NOLOAD);
  ASSERT_NE(handle, nullptr);
  auto calls = reinterpret_cast<int (*)()>(dlsym(handle, "motostab_example_entry_calls"));
  ASSERT_NE(calls, nullptr);
  EXPECT_EQ(calls(), 1);
  for (const PluginRegistry* r : {&a, &b}) {
    const auto names = r->getContactModelNames();
    EXPECT_EQ(std::count(names.begin(), names.end(), "example_vertical_spring"), 1);
  }
  dlclose(handle);  // drops only the reference NOLOAD took
}

TEST(Plugins, RegistrationIsAllOrNothing) {
  PluginRegistry registry = makeBuiltinRegistry();
  const auto before = registry.getContactModelNames();
  try {
    registry.loadLibrary(MOTOSTAB_PARTIAL_PLUGIN, {"scenario.yaml", 3, 10, "plugins[0]"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("scenario.yaml:3:10"), std::string::npos) << m;
    EXPECT_NE(m.find("'rolling_no_slip' is registered twice"), std::string::npos) << m;
  }
  EXPECT_EQ(registry.getContactModelNames(), before);  // "example_partial_first" was not kept
  EXPECT_TRUE(registry.getLibraries().empty());
}

TEST(Plugins, WrongApiVersionIsRefused) {
  PluginRegistry registry = makeBuiltinRegistry();
  const auto before = registry.getContactModelNames();
  try {
    registry.loadLibrary(MOTOSTAB_WRONG_VERSION_PLUGIN, {"scenario.yaml", 0, 0, "plugins[0]"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("plugin API version " + std::to_string(MOTOSTAB_PLUGIN_API_VERSION + 1)), std::string::npos) << m;
  }
  EXPECT_EQ(registry.getContactModelNames(), before);
}

TEST(Plugins, BareLibraryNameIsAnInputError) {
  const std::string file = scenarioWith("bare", "contact: {model: rolling_no_slip}", "libmotostab_example_vertical_spring_contact.so");
  try {
    loadScenario(file);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.getLocation().key, "plugins[0]");
    EXPECT_GT(e.getLocation().line, 0);
    EXPECT_NE(std::string(e.what()).find("bare name"), std::string::npos) << e.what();
  }
  PluginRegistry registry = makeBuiltinRegistry();
  EXPECT_THROW(registry.loadLibrary("libm.so.6", {"x", 0, 0, "plugins[0]"}), InputError);
}

TEST(Plugins, RelativeLibraryPathIsRelativeToTheScenario) {
  namespace fs = std::filesystem;
  const fs::path dir = makeTempDir("plugin_relative");
  fs::remove_all(dir);
  fs::create_directories(dir / "lib");
  fs::copy_file(MOTOSTAB_EXAMPLE_PLUGIN, dir / "lib" / "spring.so");
  const std::string file =
      scenarioWith("rel", "contact: {model: example_vertical_spring, stiffness_N_per_m: 1.0e5}", "lib/spring.so", dir);
  const Scenario s = loadScenario(file);  // the working directory is the source tree, not dir
  ASSERT_EQ(s.plugins.size(), 1u);
  EXPECT_EQ(fs::path(s.plugins[0]), dir / "lib" / "spring.so");
  EXPECT_NO_THROW(VehicleModel model(s));
}

// A library next to its scenario, both in the working folder (`plugins: [./lib.so]` in p.yaml, run as
// `motostab check p.yaml`): the resolved name keeps its "./" and loads (it was refused as a bare name).
TEST(Plugins, LibraryNextToAScenarioInTheWorkingFolder) {
  namespace fs = std::filesystem;
  const fs::path dir = makeTempDir("plugin_cwd");
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(MOTOSTAB_EXAMPLE_PLUGIN, dir / "libspring.so");
  const std::string file =
      scenarioWith("cwd", "contact: {model: example_vertical_spring, stiffness_N_per_m: 1.0e5}", "./libspring.so", dir);
  const fs::path before = fs::current_path();
  fs::current_path(dir);
  Scenario s;
  EXPECT_NO_THROW(s = loadScenario(fs::path(file).filename().string()));
  ASSERT_EQ(s.plugins.size(), 1u);
  EXPECT_EQ(s.plugins[0], "./libspring.so");
  EXPECT_NO_THROW(VehicleModel model(s));
  fs::current_path(before);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace motostab::plugins
