#pragma once
// The registry with every built-in plugin (tyres/, swingarm/compliance/). It is its own library,
// motostab_builtin_plugins, above those plugin libraries, so plugins/ itself never links them.
#include "plugins/plugin_registry.h"

namespace motostab::plugins {

/// The registry with every built-in plugin registered: the contact models rolling_no_slip,
/// relaxation_linear and magic_formula, and the swingarm models rigid, bending, torsion, twist and bending+torsion.
PluginRegistry makeBuiltinRegistry();

}  // namespace motostab::plugins
