#pragma once
// Simbody bodies and pin spring-dampers from scenario specs, shared by the vehicle's subsystems.
#include "plugins/plugin_api.h"
#include "scenario/scenario.h"

namespace motostab {

inline SimTK::Vec3 toVec3(const Vec3d& v) { return SimTK::Vec3(v[0], v[1], v[2]); }

/// Rigid body with its origin at `origin_D` (design frame, m), axes parallel to the design frame.
SimTK::Body::Rigid makeBody(const BodySpec& body, const SimTK::Vec3& origin_D);

/// A linear torsional spring (N m/rad, free at q = 0) and damper (N m s/rad) on a one-DOF pin.
void addPinSpringDamper(BuildContext& context, const SimTK::MobilizedBody& pin, double stiffness, double damping);

}  // namespace motostab
