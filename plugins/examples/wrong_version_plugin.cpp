// A deliberately bad plugin: built for another plugin API version (its entry points written out by
// hand instead of MOTOSTAB_PLUGIN_ENTRY). Loading it must be refused before it registers anything.
#include "plugins/plugin_api.h"

extern "C" int motostab_plugin_api_version() { return MOTOSTAB_PLUGIN_API_VERSION + 1; }
extern "C" void motostab_register_plugins(motostab::plugins::PluginRegistrar& registry) {
  registry.addContactModel("example_wrong_version", [](motostab::io::YamlMap&) -> std::unique_ptr<motostab::plugins::ContactModel> {
    return nullptr;
  });
}
