#include "plugins/plugin_registry.h"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <stdexcept>

#include "scenario/scenario_fields.h"

namespace motostab::plugins {

using io::InputError;
using io::InputLocation;
using io::YamlMap;
using scenario::PluginSpec;
using scenario::SwingarmSpec;
using scenario::getSwingarmLoaderKeys;


namespace {
template <class Map>
std::vector<std::string> namesOf(const Map& m) {
  std::vector<std::string> names;
  for (const auto& kv : m) names.push_back(kv.first);
  return names;
}
std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// What one library's entry point registered, in order: replayed into every registry that loads it.
struct LibraryRegistrations : PluginRegistrar {
  std::vector<std::pair<std::string, ContactModelFactory>> contacts;
  std::vector<std::pair<std::string, SwingarmModelFactory>> swingarms;
  std::vector<std::pair<std::string, ExtensionModelFactory>> extensions;
  void addContactModel(const std::string& name, ContactModelFactory f) override { contacts.emplace_back(name, std::move(f)); }
  void addSwingarmModel(const std::string& name, SwingarmModelFactory f) override { swingarms.emplace_back(name, std::move(f)); }
  void addExtensionModel(const std::string& name, ExtensionModelFactory f) override { extensions.emplace_back(name, std::move(f)); }
  std::vector<io::SectionFields> fields;
  void addSectionFields(io::SectionFields f) override { fields.push_back(std::move(f)); }
};

// Opens `file` (canonical) and runs its entry point into a fresh record; the handle is never closed,
// since the factories' code lives in the library.
std::shared_ptr<const LibraryRegistrations> openLibrary(const std::string& file, const InputLocation& where) {
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw InputError(where, std::string("cannot load plugin library: ") + dlerror());
  using Version = int (*)();
  using Entry = void (*)(PluginRegistrar&);
  auto version = reinterpret_cast<Version>(dlsym(handle, "motostab_plugin_api_version"));
  auto entry = reinterpret_cast<Entry>(dlsym(handle, "motostab_register_plugins"));
  if (!version || !entry)
    throw InputError(where, "plugin library " + file + " has no MOTOSTAB_PLUGIN_ENTRY (motostab_plugin_api_version, "
                            "motostab_register_plugins)");
  if (version() != MOTOSTAB_PLUGIN_API_VERSION)
    throw InputError(where, "plugin library " + file + " was built for plugin API version " + std::to_string(version()) +
                                "; this motostab has version " + std::to_string(MOTOSTAB_PLUGIN_API_VERSION));
  auto record = std::make_shared<LibraryRegistrations>();
  try {
    entry(*record);
  } catch (const std::exception& e) {
    throw InputError(where, "plugin library " + file + " failed while registering: " + e.what());
  }
  return record;
}

// The process-wide record of each library, by canonical path: each is opened once per process.
std::shared_ptr<const LibraryRegistrations> getLibrary(const std::string& file, const InputLocation& where) {
  static std::mutex lock;
  static std::map<std::string, std::shared_ptr<const LibraryRegistrations>> opened;
  std::lock_guard<std::mutex> guard(lock);
  auto& slot = opened[file];
  if (!slot) {
    try {
      slot = openLibrary(file, where);
    } catch (...) {
      opened.erase(file);
      throw;
    }
  }
  return slot;
}

// The canonical path of a plugin library named in input; a bare file name is refused.
std::string resolveLibraryPath(const std::string& path, const InputLocation& where) {
  if (path.find('/') == std::string::npos)
    throw InputError(where, "plugin library '" + path + "' must be given by a path (e.g. ./" + path +
                                "), not a bare name searched on the system library path");
  std::error_code ec;
  const auto canonical = std::filesystem::canonical(path, ec);
  if (ec) throw InputError(where, "cannot load plugin library: " + path + ": " + ec.message());
  return canonical.string();
}
}  // namespace

void PluginRegistry::checkUnique(const std::string& name) const {
  bool extension = false;
  for (const auto& e : extensionModels_) extension = extension || e.first == name;
  if (contactModels_.count(name) || swingarmModels_.count(name) || extension)
    throw std::runtime_error("plugin name '" + name + "' is registered twice");
}

void PluginRegistry::addContactModel(const std::string& name, ContactModelFactory factory) {
  checkUnique(name);
  contactModels_[name] = std::move(factory);
}

void PluginRegistry::addSwingarmModel(const std::string& name, SwingarmModelFactory factory) {
  checkUnique(name);
  swingarmModels_[name] = std::move(factory);
}

std::vector<std::string> PluginRegistry::getContactModelNames() const { return namesOf(contactModels_); }
std::vector<std::string> PluginRegistry::getSwingarmModelNames() const { return namesOf(swingarmModels_); }
std::vector<std::string> PluginRegistry::getExtensionModelNames() const { return namesOf(extensionModels_); }

void PluginRegistry::addExtensionModel(const std::string& name, ExtensionModelFactory factory) {
  checkUnique(name);
  extensionModels_.emplace_back(name, std::move(factory));
}

void PluginRegistry::addSectionFields(io::SectionFields fields) {
  for (const io::SectionFields& f : sectionFields_)
    if (f.isSameSectionAs(fields))
      throw std::runtime_error("the fields of section '" + fields.path + "'" +
                               (f.whenPath.empty() ? "" : " for " + f.whenPath + " " + f.whenValue) + " are declared twice");
  sectionFields_.push_back(std::move(fields));
}

std::vector<io::SectionFields> listSectionFields(const PluginRegistry& registry) {
  std::vector<io::SectionFields> out = scenario::getScenarioFields();
  for (const io::SectionFields& f : registry.getSectionFields()) {
    // A plugin reading the rest of a loader's section (the swingarm models) adds its keys to it.
    auto same = std::find_if(out.begin(), out.end(), [&](const io::SectionFields& s) { return s.isSameSectionAs(f); });
    if (same == out.end()) out.push_back(f);
    else same->fields.insert(same->fields.end(), f.fields.begin(), f.fields.end());
  }
  return out;
}

VehicleLayout makeVehicleLayout(const scenario::Scenario& s) {
  VehicleLayout v;
  v.gravity = s.gravity;
  v.wheelbase = s.geometry.wheelbase;
  v.trail = s.geometry.trail;
  v.steerAxisTilt = s.geometry.steerAxisTilt;
  v.rearWheelRadius = s.rearWheel.radius;
  v.frontWheelRadius = s.frontWheel.radius;
  v.rearFrame = s.rearFrame;
  v.frontFrame = s.frontFrame;
  v.hasSwingarm = s.hasSwingarm;
  if (s.hasSwingarm) {
    v.swingarmPivot = s.swingarm.pivot;
    v.staticPivotMoment = scenario::calcStaticPivotMoment(s);
  }
  return v;
}

std::vector<std::unique_ptr<ExtensionModel>> PluginRegistry::createExtensionModels(const scenario::Scenario& s,
                                                                                   std::shared_ptr<io::InputStore> inputs) const {
  const std::vector<std::string> known = getExtensionModelNames();
  for (const PluginSpec& section : s.extensions)
    if (std::find(known.begin(), known.end(), section.model) == known.end())
      throw InputError(section.where,
          "unknown section '" + section.model + "': not a scenario section, nor a model extension (known: " +
              joinNames(known) + "; a plugin library listed under plugins: may register more)");
  const VehicleLayout vehicle = makeVehicleLayout(s);
  std::vector<std::unique_ptr<ExtensionModel>> out;
  for (const auto& [name, factory] : extensionModels_) {
    const PluginSpec* section = scenario::findExtension(s, name);
    if (!section) continue;
    YamlMap params(section->params, section->file, section->path, inputs);
    out.push_back(factory(params, vehicle));
    if (!out.back()) params.fail("", "the '" + name + "' plugin made no model of this section");
    params.finish();
  }
  return out;
}

std::unique_ptr<SwingarmModel> PluginRegistry::createSwingarmModel(const SwingarmSpec& spec,
                                                                  std::shared_ptr<io::InputStore> inputs) const {
  YamlMap params(spec.params, spec.file, "swingarm", std::move(inputs));
  const auto it = swingarmModels_.find(spec.compliance);
  if (it == swingarmModels_.end())
    params.fail("compliance", "unknown swingarm compliance plugin '" + spec.compliance + "' (known: " +
                                  joinNames(getSwingarmModelNames()) + ")");
  for (const auto& k : getSwingarmLoaderKeys()) params.markUsed(k);
  auto model = it->second(params);
  params.finish();
  return model;
}

std::unique_ptr<ContactModel> PluginRegistry::createContactModel(const PluginSpec& spec,
                                                                std::shared_ptr<io::InputStore> inputs) const {
  YamlMap params(spec.params, spec.file, spec.path, std::move(inputs));
  const auto it = contactModels_.find(spec.model);
  if (it == contactModels_.end()) {
    params.fail("model", "unknown contact plugin '" + spec.model + "' (known: " + joinNames(getContactModelNames()) + ")");
  }
  params.markUsed("model");
  auto model = it->second(params);
  params.finish();
  return model;
}

void PluginRegistry::loadScenarioLibraries(const scenario::Scenario& s) {
  for (size_t i = 0; i < s.plugins.size(); ++i)
    loadLibrary(s.plugins[i], {s.sourceFile, 0, 0, "plugins[" + std::to_string(i) + "]"});
}

void PluginRegistry::readScenarioSections(scenario::Scenario& s) {
  try {
    loadScenarioLibraries(s);
    createContactModel(s.contact, s.inputs);
    if (s.hasSwingarm) createSwingarmModel(s.swingarm, s.inputs);
    createExtensionModels(s, s.inputs);
  } catch (const InputError& e) {
    scenario::rethrowNamingOverride(e, s.overrides);
  }
  for (const io::InputWarning& w : s.inputs->getWarnings())
    s.warnings.push_back({scenario::ScenarioWarning::Check::PluginInput, w.where, w.message});
}

void PluginRegistry::loadLibrary(const std::string& path, const InputLocation& where) {
  const std::string file = resolveLibraryPath(path, where);
  for (const auto& l : libraries_)
    if (l == file) return;
  const auto record = getLibrary(file, where);
  // All or nothing: every name is checked (against this registry and within the library) first.
  PluginRegistry staged = *this;
  try {
    for (const auto& [name, f] : record->contacts) staged.addContactModel(name, f);
    for (const auto& [name, f] : record->swingarms) staged.addSwingarmModel(name, f);
    for (const auto& [name, f] : record->extensions) staged.addExtensionModel(name, f);
    for (const io::SectionFields& f : record->fields) staged.addSectionFields(f);
  } catch (const std::exception& e) {
    throw InputError(where, std::string(e.what()) + " (by " + file + ")");
  }
  staged.libraries_.push_back(file);
  *this = std::move(staged);
}

}  // namespace motostab::plugins
