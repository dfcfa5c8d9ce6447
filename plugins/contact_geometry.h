#pragma once
// Wheel-ground contact geometry as the plugin API gives it (ContactModel::calcContactPoint): the point
// where a wheel meets the flat ground z = 0, from the wheel centre, and its rate. The toroidal wheel
// here is the default every built-in contact model uses; a plugin with another tyre shape gives its own.
#include "Simbody.h"

namespace motostab::plugins {

/// A wheel's contact point with the ground plane z = 0.
struct ContactPoint {
  SimTK::Vec3 r_CP_G;     ///< wheel centre C to contact point P, ground frame, m
  SimTK::Vec3 rDot_CP_G;  ///< time derivative of r_CP_G (not a material derivative), m/s
};

/// Contact point of a torus (seed: toroidal tyre kinematics): a wheel with centre orientation R_GW
/// (spin axis W.y), outer radius R (m), crown radius rho (m; 0 = knife edge) and angular velocity
/// w_GW_G (rad/s). With a = spin axis in ground, n = +z: d = -(n - (n.a)a)/|n - (n.a)a| points from the
/// centre to the lowest point of the wheel plane; the contact point is P = C + (R - rho) d - rho n.
ContactPoint calcTorusContact(const SimTK::Rotation& R_GW, const SimTK::Vec3& w_GW_G, double R, double rho);

}  // namespace motostab::plugins
