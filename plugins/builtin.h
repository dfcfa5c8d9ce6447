#pragma once
// The registry with every built-in plugin (tyres/, swingarm/compliance/, extensions/). It is its own library,
// motostab_builtin_plugins, above those plugin libraries, so plugins/ itself never links them.
#include "plugins/plugin_registry.h"

namespace motostab::plugins {

/// The registry with every built-in plugin registered: the contact models rolling_no_slip,
/// relaxation_linear and magic_formula, the swingarm models rigid, bending, torsion, twist and bending+torsion,
/// and the model extensions aerodynamics, steer_damper, rider_arms, steer_controller, rider_lean,
/// fork_compliance and steer_head_friction (in that order).
PluginRegistry makeBuiltinRegistry();

/// The built-in registry with the plugin libraries a scenario lists loaded (PluginRegistry::loadScenarioLibraries):
/// the plugins that scenario's sections can name, and their declared fields. InputError at `plugins[i]`
/// (naming the --set that gave it).
PluginRegistry makeScenarioRegistry(const scenario::Scenario& s);

}  // namespace motostab::plugins
