// A deliberately bad plugin: it registers a new name, then one that is already built in. Loading it
// must leave neither name registered (registration is all-or-nothing).
#include "plugins/plugin_api.h"

MOTOSTAB_PLUGIN_ENTRY {
  auto none = [](motostab::io::YamlMap&) -> std::unique_ptr<motostab::plugins::ContactModel> { return nullptr; };
  registry.addContactModel("example_partial_first", none);
  registry.addContactModel("rolling_no_slip", none);
}
