#pragma once
// The rider's arms on the handlebar (`rider_arms`): a steer impedance between the front frame and the
// rear frame about the steer axis. With delta the steer angle and delta' its rate (front frame
// relative to rear frame), the torque on the front frame about the steer axis (its reaction on the
// rear frame) is
//   T = -k_a delta - c_a delta'                                         (N m)
// and the arms' inertia J_a about the steer axis rides with the front frame: two grip masses, d either
// side of the steer axis at the height of the front frame's centre of mass, J_a / d^2 in all, moved
// from the rear frame (which holds the whole rider) to the front frame, so the totals are unchanged.
// This is the hands-on steer model of Sharp (1994) "Vibrational modes of motorcycles and their design
// parameter sensitivities", IMechE Vehicle NVH and Refinement (front-frame steer inertia 0.71 -> 0.91
// kg m^2, k = 50 N m/rad, c = 6 N m s/rad with hands on against 1 N m s/rad hands off) and the arms'
// part of the passive steering impedance identified by Cossalter, Doria, Lot, Massaro (2011), "The
// effect of rider's passive steering impedance on motorcycle stability: identification and analysis",
// Meccanica 46:279-292. The arms act on the rear frame even when `rider_lean` gives the upper body a
// joint of its own (the two-stage handlebar-torso-frame chain of Massaro & Cole is not modelled).
#include <memory>

#include "plugins/plugin_api.h"

namespace motostab::extensions {

/// The section `rider_arms: {inertia_kgm2, stiffness_Nm_per_rad, damping_Nms_per_rad, grip_half_width_m?}`.
struct RiderArmsParams {
  double inertia = 0;            ///< J_a, added steer inertia about the steer axis, kg m^2 (> 0)
  double stiffness = 0;          ///< k_a, N m/rad (>= 0)
  double damping = 0;            ///< c_a, N m s/rad (>= 0)
  double gripHalfWidth = 0.25;   ///< d, m (> 0): grip distance from the steer axis
};

/// The section's declared fields.
const io::SectionFields& getRiderArmsFields();

/// Reads and checks the section: the rear frame of `vehicle` must be able to give up the grip masses
/// (the caller finishes `m`).
RiderArmsParams readRiderArms(io::YamlMap& m, const plugins::VehicleLayout& vehicle);

/// The grip masses in D: J_a / d^2 at the steer-axis point nearest the front frame's centre of mass
/// (inertia m d^2 about the x and z axes: two masses at +/- d along y).
scenario::BodySpec calcGripMasses(const RiderArmsParams& params, const plugins::VehicleLayout& vehicle);

/// The arms' torque T (N m) at steer angle `steer` (rad) and rate `steerRate` (rad/s), as above.
double calcRiderArmsTorque(const RiderArmsParams& params, double steer, double steerRate);

/// The extension with these parameters on `vehicle` (typed constructor).
std::unique_ptr<plugins::ExtensionModel> makeRiderArms(const RiderArmsParams& params, const plugins::VehicleLayout& vehicle);

/// Registers `rider_arms`.
void registerRiderArms(plugins::PluginRegistrar& registry);

}  // namespace motostab::extensions
