// A deliberately bad plugin: it registers a name that is already built in.
#include "plugins/plugin_api.h"

MOTOSTAB_PLUGIN_ENTRY {
  registry.addContactModel("rolling_no_slip", [](motostab::io::YamlMap&) -> std::unique_ptr<motostab::plugins::ContactModel> { return nullptr; });
}
