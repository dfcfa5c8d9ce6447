#include <dlfcn.h>

#include <stdexcept>

#include "plugins/plugin_api.h"

namespace motostab {

void PluginRegistry::addContactModel(const std::string& name, ContactModelFactory factory) {
  if (contactModels_.count(name)) {
    throw std::runtime_error("plugin name '" + name + "' is registered twice" +
                             (loadingLibrary_.empty() ? "" : " (by " + loadingLibrary_ + ")"));
  }
  contactModels_[name] = std::move(factory);
}

std::vector<std::string> PluginRegistry::getContactModelNames() const {
  std::vector<std::string> names;
  for (const auto& kv : contactModels_) names.push_back(kv.first);
  return names;
}

std::unique_ptr<ContactModel> PluginRegistry::createContactModel(const PluginSpec& spec) const {
  YamlMap params(spec.params, spec.file, spec.path);
  const auto it = contactModels_.find(spec.model);
  if (it == contactModels_.end()) {
    std::string known;
    for (const auto& n : getContactModelNames()) known += (known.empty() ? "" : ", ") + n;
    params.fail("model", "unknown contact plugin '" + spec.model + "' (known: " + known + ")");
  }
  params.markUsed("model");
  auto model = it->second(params);
  params.finish();
  return model;
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
