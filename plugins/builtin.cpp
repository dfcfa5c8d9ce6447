#include "plugins/builtin.h"

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
  return registry;
}

}  // namespace motostab::plugins
