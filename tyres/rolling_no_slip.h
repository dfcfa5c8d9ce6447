#pragma once
// Contact plugin `rolling_no_slip`: a toroidal wheel rolling without slip on flat ground (the
// Whipple bicycle's contact, Meijaard et al. 2007, sec. 2). Crown radius 0 is the knife edge.
#include "plugins/plugin_api.h"

namespace motostab::tyres {

/// Contact geometry of a torus on the ground plane z = 0 (seed: toroidal tyre kinematics).
/// With a = spin axis in ground, n = +z: d = -(n - (n.a)a)/|n - (n.a)a| points from the centre to
/// the lowest point of the wheel plane; the contact point is P = C + (R - rho) d - rho n.
struct TorusContact {
  SimTK::Vec3 r_CP_G;     ///< centre to contact point, ground frame, m
  SimTK::Vec3 rDot_CP_G;  ///< time derivative of r_CP_G (not a material derivative), m/s
};

/// Contact point of a wheel with centre orientation R_GW (spin axis W.y), outer radius R (m),
/// crown radius rho (m), and angular velocity w_GW_G (rad/s).
TorusContact calcTorusContact(const SimTK::Rotation& R_GW, const SimTK::Vec3& w_GW_G, double R, double rho);

/// Registers `rolling_no_slip` (no parameters).
void registerRollingNoSlip(plugins::PluginRegistrar& registry);

}  // namespace motostab::tyres
