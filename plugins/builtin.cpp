#include "plugins/builtin.h"

#include "extensions/aerodynamics.h"
#include "extensions/fork_compliance.h"
#include "extensions/rear_suspension.h"
#include "extensions/rider_arms.h"
#include "extensions/rider_lean.h"
#include "extensions/steer_controller.h"
#include "extensions/steer_damper.h"
#include "extensions/steer_head_friction.h"
#include "swingarm/compliance/swingarm_compliance.h"
#include "tyres/magic_formula_contact.h"
#include "tyres/relaxation_linear.h"
#include "tyres/rolling_no_slip.h"

namespace motostab::plugins {

using swingarm::registerSwingarmModels;
using tyres::registerMagicFormula;
using tyres::registerRelaxationLinear;
using tyres::registerRollingNoSlip;


PluginRegistry makeBuiltinRegistry() {
  PluginRegistry registry;
  registerRollingNoSlip(registry);
  registerRelaxationLinear(registry);
  registerMagicFormula(registry);
  registerSwingarmModels(registry);
  // Model extensions: their assembly stages run in this order (plugin_api.h ExtensionModel). The rear
  // suspension first: `scenario check` lists it under the swingarm. The rider's arms move their grips before the upper body and the fork's carrier take their mass out; the forces
  // follow in this order too.
  extensions::registerRearSuspension(registry);
  extensions::registerAerodynamics(registry);
  extensions::registerSteerDamper(registry);
  extensions::registerRiderArms(registry);
  extensions::registerSteerController(registry);
  extensions::registerRiderLean(registry);
  extensions::registerForkCompliance(registry);
  extensions::registerSteerHeadFriction(registry);
  return registry;
}

PluginRegistry makeScenarioRegistry(const scenario::Scenario& s) {
  PluginRegistry registry = makeBuiltinRegistry();
  try {
    registry.loadScenarioLibraries(s);
  } catch (const io::InputError& e) {
    scenario::rethrowNamingOverride(e, s.overrides);
  }
  return registry;
}

}  // namespace motostab::plugins
