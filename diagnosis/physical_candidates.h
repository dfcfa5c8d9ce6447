#pragma once
// Candidates named after physics a user recognises (diagnosis/candidates.h lists the others):
// - `tyre_crown`: both wheels' toroidal crown radius (one parameter, front and rear equal), from
//   kDefaultCrownRadius_m (half a typical bicycle tyre's width: the scenario format has no tyre width
//   to start from); off at 0 (knife-edge wheels), a bound: the likelihood ratio uses the 50:50 mixture.
//   Only for scenarios whose wheels are knife-edged (crown_radius_m 0 or absent).
// No steer-head friction candidate: linearised about straight running, a Coulomb torque f (smoothed
// over a rate omega_s, vehicle/steer_damper.h) is the viscous damper c = f / omega_s, and a real dry
// friction's equivalent damping c_eq = 4 f / (pi A w) depends on the steer amplitude A and frequency w
// (Den Hartog 1956, Mechanical Vibrations, 4th ed., sect. 8.2), which linear eigenvalue and free-response
// fits do not carry. Such a candidate would be the steer damper under another name, indistinguishable by
// construction; the steer damper's c is reported instead, and docs/diagnosis.md says how to read it as
// friction (f = pi A w c / 4 at the measured amplitude).
#include <yaml-cpp/yaml.h>

#include <vector>

#include "diagnosis/candidates.h"

namespace motostab::diagnosis {

/// Crown radius tyre_crown starts from without a tyre width, m: half a 30 mm bicycle tyre.
constexpr double kDefaultCrownRadius_m = 0.015;

/// Appends tyre_crown where the scenario admits it.
void addPhysicalCandidates(const YAML::Node& scenarioTree, std::vector<Candidate>& out);

}  // namespace motostab::diagnosis
