#pragma once
// Contact plugin `rolling_no_slip`: a toroidal wheel rolling without slip on flat ground (the
// Whipple bicycle's contact, Meijaard et al. 2007, sec. 2). Crown radius 0 is the knife edge.
#include "plugins/plugin_api.h"

namespace motostab::tyres {

/// Registers `rolling_no_slip` (no parameters).
void registerRollingNoSlip(plugins::PluginRegistrar& registry);

}  // namespace motostab::tyres
