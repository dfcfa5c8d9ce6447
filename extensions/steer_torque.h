#pragma once
// A torque about the steer axis between the front frame and the rear frame, a function of the steer
// angle delta (rad) and rate delta' (rad/s) relative to the rear frame: T(delta, delta') (N m) on the
// front frame, its reaction on the rear frame. The force element of the steer damper, the rider's
// arms and steer-head friction.
#include <functional>

#include "plugins/plugin_api.h"

namespace motostab::extensions {

/// T(delta, delta'), N m.
using SteerTorqueLaw = std::function<double(double steer, double steerRate)>;
/// V(delta), J: the potential energy of a law with a spring part (none: zero).
using SteerPotential = std::function<double(double steer)>;

/// Smoothed dry friction opposing the steer rate: -f tanh(delta'/omega_s) (N m), f >= 0 (N m) the
/// friction torque, omega_s > 0 (rad/s) the rate at which it reaches tanh(1) = 76 % of f.
double calcSmoothedFrictionTorque(double friction, double smoothing, double steerRate);

/// Adds the element to the steer mobilizer of `frontFrame` (a one-DOF Pin: q the steer angle, u its rate).
void addSteerTorque(plugins::BuildContext& context, const SimTK::MobilizedBody& frontFrame, SteerTorqueLaw torque,
                    SteerPotential potential = nullptr);

}  // namespace motostab::extensions
