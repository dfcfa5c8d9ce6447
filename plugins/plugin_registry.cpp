#include <dlfcn.h>

#include <stdexcept>

#include "plugins/plugin_api.h"

namespace motostab {

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
}  // namespace

void PluginRegistry::checkUnique(const std::string& name) const {
  if (contactModels_.count(name) || swingarmModels_.count(name))
    throw std::runtime_error("plugin name '" + name + "' is registered twice" +
                             (loadingLibrary_.empty() ? "" : " (by " + loadingLibrary_ + ")"));
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

std::unique_ptr<SwingarmModel> PluginRegistry::createSwingarmModel(const SwingarmSpec& spec) const {
  YamlMap params(spec.params, spec.file, "swingarm");
  const auto it = swingarmModels_.find(spec.compliance);
  if (it == swingarmModels_.end())
    params.fail("compliance", "unknown swingarm compliance plugin '" + spec.compliance + "' (known: " +
                                  joinNames(getSwingarmModelNames()) + ")");
  for (const auto& k : getSwingarmLoaderKeys()) params.markUsed(k);
  auto model = it->second(params);
  params.finish();
  return model;
}

std::unique_ptr<ContactModel> PluginRegistry::createContactModel(const PluginSpec& spec) const {
  YamlMap params(spec.params, spec.file, spec.path);
  const auto it = contactModels_.find(spec.model);
  if (it == contactModels_.end()) {
    params.fail("model", "unknown contact plugin '" + spec.model + "' (known: " + joinNames(getContactModelNames()) + ")");
  }
  params.markUsed("model");
  auto model = it->second(params);
  params.finish();
  return model;
}

SimTK::MobilizedBody::Pin addPinAtDesignPose(SimTK::MobilizedBody& parent, const SimTK::Transform& X_PC0,
                                             const SimTK::Body& body, const SimTK::Vec3& p_C, const SimTK::Vec3& n_C) {
  const SimTK::Transform X_CM(SimTK::Rotation(SimTK::UnitVec3(n_C), SimTK::ZAxis), p_C);
  return SimTK::MobilizedBody::Pin(parent, X_PC0 * X_CM, body, X_CM);
}

void PluginRegistry::loadLibrary(const std::string& path, const InputLocation& where) {
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw InputError(where, std::string("cannot load plugin library: ") + dlerror());
  using Entry = void (*)(PluginRegistry&);
  auto entry = reinterpret_cast<Entry>(dlsym(handle, "motostab_register_plugins"));
  if (!entry) throw InputError(where, "plugin library " + path + " has no motostab_register_plugins entry point");
  loadingLibrary_ = path;
  try {
    entry(*this);
  } catch (const std::exception& e) {
    loadingLibrary_.clear();
    throw InputError(where, e.what());
  }
  loadingLibrary_.clear();
}

}  // namespace motostab
