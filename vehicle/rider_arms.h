#pragma once
// The rider's arms on the handlebar (`rider_arms`): a steer impedance between the front frame and the
// rear frame about the steer axis. With delta the steer angle and delta' its rate (front frame
// relative to rear frame), the torque on the front frame about the steer axis (its reaction on the
// rear frame) is
//   T = -k_a delta - c_a delta'                                         (N m)
// and the arms' inertia J_a about the steer axis rides with the front frame (scenario.h RiderArmsSpec:
// two grip masses moved there from the rider, so the totals are unchanged). This is the hands-on
// steer model of Sharp (1994) (front-frame steer inertia 0.71 -> 0.91 kg m^2, k = 50 N m/rad,
// c = 6 N m s/rad with hands on against 1 N m s/rad hands off) and the arms' part of the passive
// steering impedance identified by Cossalter, Doria, Lot, Massaro (2011), Meccanica 46:279-292. The
// arms act on the rear frame even when `rider_lean` gives the upper body a joint of its own (the
// two-stage handlebar-torso-frame chain of Massaro & Cole is not modelled).
#include "plugins/plugin_api.h"
#include "scenario/scenario.h"

namespace motostab::vehicle {

/// Adds the spring-damper to the steer mobilizer of `frontFrame` (a one-DOF Pin: q the steer angle,
/// u its rate, both relative to the rear frame).
void addRiderArms(plugins::BuildContext& context, const SimTK::MobilizedBody& frontFrame, const scenario::RiderArmsSpec& spec);

/// The arms' torque T (N m) at steer angle `steer` (rad) and rate `steerRate` (rad/s), as above.
double calcRiderArmsTorque(const scenario::RiderArmsSpec& spec, double steer, double steerRate);

}  // namespace motostab::vehicle
