#pragma once
// Candidates named after physics a user recognises (diagnosis/candidates.h lists the others):
// - `tyre_crown`: both wheels' toroidal crown radius (one parameter, front and rear equal), from
//   kDefaultCrownRadius_m (half a typical bicycle tyre's width: the scenario format has no tyre width
//   to start from); off at 0 (knife-edge wheels), a bound: the likelihood ratio uses the 50:50 mixture.
//   Only for scenarios whose wheels are knife-edged (crown_radius_m 0 or absent).
// - `steer_friction`: steer-head bearing friction as an equivalent viscous damping. A Coulomb torque
//   T_f on a steer oscillation of amplitude A and frequency w dissipates per cycle what a viscous
//   damper c_eq = 4 T_f / (pi A w) does (Den Hartog 1956, Mechanical Vibrations, 4th ed., sect. 8.2);
//   a linear model sees only c_eq, so the fitted parameter is c_eq (the steer_damper key), reported as
//   friction. It is the steer damper's look-alike: the report names both when the data cannot tell them
//   apart. Only for scenarios without a steer damper.
#include <yaml-cpp/yaml.h>

#include <vector>

#include "diagnosis/candidates.h"

namespace motostab::diagnosis {

/// Crown radius tyre_crown starts from without a tyre width, m: half a 30 mm bicycle tyre.
constexpr double kDefaultCrownRadius_m = 0.015;

/// Appends tyre_crown and steer_friction where the scenario admits them.
void addPhysicalCandidates(const YAML::Node& scenarioTree, std::vector<Candidate>& out);

}  // namespace motostab::diagnosis
