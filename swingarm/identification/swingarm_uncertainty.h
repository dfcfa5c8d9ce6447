#pragma once
// The identified swingarm's standard errors as a scenario `uncertainty:` section, keyed by the
// paths the compliance plugins read (swingarm.<bending|torsion|twist>.{arm_m, beta_deg,
// stiffness_Nm_per_rad, damping_Nms_per_rad}); `motostab identify swingarm` writes it as
// swingarm_uncertainty.yaml, to be appended to a scenario (docs/uncertainty.md).
#include <string>

#include "swingarm/identification/decomposition.h"

namespace motostab::swingarm::identification {

/// YAML text "uncertainty:\n  swingarm.bending.stiffness_Nm_per_rad: s\n ..." of every finite,
/// positive standard error of the three lumped models (units of the keys: m, deg, Nm/rad, Nms/rad).
std::string formatSwingarmUncertainty(const SwingarmIdentification& id);

}  // namespace motostab::swingarm::identification
