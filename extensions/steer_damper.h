#pragma once
// Steering damper (`steer_damper`): a rotary damper between the front frame and the rear
// frame about the steer axis. With delta' the steer rate (rad/s, front frame relative to rear frame),
// the torque on the front frame about the steer axis (its reaction on the rear frame) is
//   T = -c delta' - f tanh(delta' / omega_s)                     (N m)
// c viscous damping (N m s/rad), f Coulomb friction (N m), omega_s the smoothing rate (rad/s): the
// friction reaches tanh(1) = 76 % of f at delta' = omega_s and 99.9 % at 4 omega_s.
// Linearised about straight running (delta' = 0) the friction is a viscous damper of f/omega_s: the
// linear models (linearize, sweep) see c + f/omega_s. A dry damper is therefore best studied in the
// time domain (simulate); sweeps of dampers with friction show the locked-steer limit as f/omega_s grows.
// Viscous steering dampers in the literature: Meijaard et al. (2007) sec. 4 (c added to the steer
// entry of C), Cossalter (2006) sec. 8.5, Sharp & Limebeer (2001) (c about 6.8 N m s/rad on a sports bike).
#include <memory>

#include "plugins/plugin_api.h"

namespace motostab::extensions {

/// The section `steer_damper: {damping_Nms_per_rad, coulomb_Nm?, coulomb_smoothing_rad_per_s?}`.
struct SteerDamperParams {
  double damping = 0;            ///< c, N m s/rad (>= 0)
  double coulomb = 0;            ///< f, N m (>= 0): smoothed Coulomb friction
  double coulombSmoothing = 0.1; ///< omega_s, rad/s (> 0): steer rate at which tanh reaches 76 % of f
};

/// The section's declared fields.
const io::SectionFields& getSteerDamperFields();

/// Reads and checks the section (the caller finishes `m`).
SteerDamperParams readSteerDamper(io::YamlMap& m);

/// The damper torque T (N m) at steer rate `steerRate` (rad/s), as above.
double calcSteerDamperTorque(const SteerDamperParams& params, double steerRate);

/// The extension with these parameters (typed constructor; tests build it without YAML).
std::unique_ptr<plugins::ExtensionModel> makeSteerDamper(const SteerDamperParams& params);

/// Registers `steer_damper`.
void registerSteerDamper(plugins::PluginRegistrar& registry);

}  // namespace motostab::extensions
