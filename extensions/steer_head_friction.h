#pragma once
// Steer-head friction (`steer_head_friction`): dry friction in the steering head bearings, from their
// preload and seals, opposing the steer rate,
//   T = -T_f tanh(delta' / omega_s)                                (N m)
// on the front frame about the steer axis (its reaction on the rear frame); T_f (N m) the breakaway
// torque measured at the handlebar with the front wheel off the ground, omega_s (rad/s) the smoothing
// rate (T reaches 76 % of T_f at delta' = omega_s). Tapered-roller steering heads of motorcycles
// measure about 0.2-1 N m when correctly adjusted and several N m when overtightened (Cossalter 2006,
// "Motorcycle Dynamics", sec. 8.5, on friction in the steering head and its damping of wobble).
// Linearised at delta' = 0 it is a viscous damper of T_f/omega_s (as a steer damper's Coulomb part).
// This file is also the worked example of a model extension (docs/plugins.md): its own parameters,
// reader, typed constructor and registration, and one line in plugins/builtin.cpp.
#include <memory>

#include "plugins/plugin_api.h"

namespace motostab::extensions {

/// The section `steer_head_friction: {torque_Nm, smoothing_rad_per_s?}`.
struct SteerHeadFrictionParams {
  double torque = 0;      ///< T_f, N m (>= 0)
  double smoothing = 0.1; ///< omega_s, rad/s (> 0)
};

/// The section's declared fields.
const io::SectionFields& getSteerHeadFrictionFields();

/// Reads and checks the section (the caller finishes `m`).
SteerHeadFrictionParams readSteerHeadFriction(io::YamlMap& m);

/// The friction torque T (N m) at steer rate `steerRate` (rad/s), as above.
double calcSteerHeadFrictionTorque(const SteerHeadFrictionParams& params, double steerRate);

/// The extension with these parameters (typed constructor).
std::unique_ptr<plugins::ExtensionModel> makeSteerHeadFriction(const SteerHeadFrictionParams& params);

/// Registers `steer_head_friction`.
void registerSteerHeadFriction(plugins::PluginRegistrar& registry);

}  // namespace motostab::extensions
