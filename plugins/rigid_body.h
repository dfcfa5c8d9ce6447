#pragma once
// Simbody bodies from the mass properties of scenario/body_spec.h, for the vehicle and the plugins
// that build bodies of their own.
#include "Simbody.h"

#include "scenario/body_spec.h"

namespace motostab::plugins {

inline SimTK::Vec3 toVec3(const scenario::Vec3d& v) { return SimTK::Vec3(v[0], v[1], v[2]); }

/// Rigid body with its origin at `origin_D` (design frame, m), axes parallel to the design frame.
SimTK::Body::Rigid makeRigidBody(const scenario::BodySpec& body, const SimTK::Vec3& origin_D);

}  // namespace motostab::plugins
