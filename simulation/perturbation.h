#pragma once
// Perturbations of a simulation: their command-line syntax, parsing and time histories.
#include <string>
#include <vector>

#include "plugins/state_role.h"

namespace motostab::simulation {

enum class PerturbationKind {
  SteerTorque,   ///< torque pulse between front and rear frames, N m
  LateralForce,  ///< force pulse along ground y at a body's centre of mass, N
  RollRate,      ///< initial roll-rate offset, rad/s
  SteerRate,     ///< initial steer-rate offset, rad/s
  RoadStep       ///< lateral road-displacement step under one wheel, m (force-based tyres only)
};

enum class PulseShape { Rectangular, HalfSine };

/// One perturbation. Syntax (parsePerturbation):
///   steer-torque:AMPLITUDE_Nm:START_s:DURATION_s[:halfsine|:rect]
///   lateral-force:BODY:AMPLITUDE_N:START_s:DURATION_s[:halfsine|:rect]   BODY = rear_frame, front_frame,
///                                                                      rear_wheel, front_wheel
///   roll-rate:VALUE_rad_per_s
///   steer-rate:VALUE_rad_per_s
///   road-step:WHEEL:OFFSET_m:START_s                                    WHEEL = rear_wheel, front_wheel
struct Perturbation {
  PerturbationKind kind = PerturbationKind::SteerTorque;
  double amplitude = 0;  ///< N m, N, rad/s, rad/s or m (by kind)
  double start = 0;      ///< s (pulses, road step)
  double duration = 0;   ///< s (pulses)
  PulseShape shape = PulseShape::Rectangular;
  std::string body;      ///< lateral-force body or road-step wheel, as written
  plugins::WheelSide wheel = plugins::WheelSide::None;  ///< the road-step wheel
  std::string spec;      ///< the text it was parsed from, for messages

  bool isPulse() const { return kind == PerturbationKind::SteerTorque || kind == PerturbationKind::LateralForce; }
  /// Pulse value at time t (s) while the pulse is switched on, in amplitude units: the amplitude
  /// (rectangular) or amplitude sin(pi (t - start) / duration) (half sine).
  double calcPulseValue(double t) const;
  /// Times (s) where the pulse switches on and off; empty for non-pulses.
  std::vector<double> getSwitchTimes() const;
};

/// Parses one --perturb SPEC. Throws InputError (key "--perturb") quoting the spec and the expected syntax.
Perturbation parsePerturbation(const std::string& spec);

/// The syntax summary used in help texts and error messages.
std::string getPerturbationSyntax();

/// Time (s) from which the response is free: the end of the last force pulse, 0 without pulses.
double getFreeResponseStart(const std::vector<Perturbation>& perturbations);

}  // namespace motostab::simulation
