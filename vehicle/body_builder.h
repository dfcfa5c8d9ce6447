#pragma once
// Simbody bodies from scenario specs, shared by the vehicle's subsystems.
#include "plugins/plugin_api.h"
#include "scenario/scenario.h"

namespace motostab::vehicle {

inline SimTK::Vec3 toVec3(const scenario::Vec3d& v) { return SimTK::Vec3(v[0], v[1], v[2]); }

/// Rigid body with its origin at `origin_D` (design frame, m), axes parallel to the design frame.
SimTK::Body::Rigid makeBody(const scenario::BodySpec& body, const SimTK::Vec3& origin_D);

}  // namespace motostab::vehicle
