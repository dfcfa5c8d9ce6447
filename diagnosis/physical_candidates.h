#pragma once
// Candidates named after physics a user recognises (diagnosis/candidates.h lists the others):
// - `tyre_crown`: both wheels' toroidal crown radius (one parameter, front and rear equal), from
//   kDefaultCrownRadius_m (half a typical bicycle tyre's width: the scenario format has no tyre width
//   to start from); off at 0 (knife-edge wheels), a bound: the likelihood ratio uses the 50:50 mixture.
//   Only for scenarios whose wheels are knife-edged (crown_radius_m 0 or absent).
// - `steer_friction` (made in candidates.cpp beside steer_damper): dry friction in the steer head, a
//   Coulomb torque T_f (N m) opposing the steer rate, free in [0, ...), off at the bound 0. A linear
//   model cannot carry it, so it is applied as its describing-function equivalent viscous damping at
//   the steer-rate amplitude Omega (rad/s) of the measured oscillation:
//     c_eq = 4 T_f / (pi Omega)                                         (N m s/rad)    (eq. 1)
//   Over one cycle of delta' = Omega cos(w t) (steer amplitude A = Omega / w) the friction dissipates
//   4 T_f A and a viscous damper c pi w A^2 = pi c Omega A; equal for c = c_eq (Den Hartog 1956,
//   Mechanical Vibrations, 4th ed., sect. 8.2; Gelb & Vander Velde 1968, Multiple-Input Describing
//   Functions, ch. 2: the relay's describing function 4 T_f / (pi Omega)). c_eq is added to the
//   scenario's steer damper coefficient, or makes a damper where the scenario has none. Omega comes
//   from the data (diagnosis/steer_rate_amplitude.h); without one the candidate is not offered. In a
//   linear model steer_friction and steer_damper predict identically for the same c: the data cannot
//   tell friction from viscous damping (only the amplitude dependence of c_eq could, which is not
//   modelled), and the diagnosis reports them as indistinguishable, each with its own value.
#include <yaml-cpp/yaml.h>

#include <vector>

#include "diagnosis/candidates.h"

namespace motostab::diagnosis {

/// Crown radius tyre_crown starts from without a tyre width, m: half a 30 mm bicycle tyre.
constexpr double kDefaultCrownRadius_m = 0.015;

/// c_eq / T_f = 4 / (pi Omega) of eq. 1, s/rad; `steerRateAmplitude` Omega > 0 in rad/s.
double calcFrictionDampingFactor(double steerRateAmplitude);

/// Appends tyre_crown where the scenario admits it.
void addPhysicalCandidates(const YAML::Node& scenarioTree, std::vector<Candidate>& out);

}  // namespace motostab::diagnosis
