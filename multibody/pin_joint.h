#pragma once
// Simbody joint helpers shared by the vehicle (vehicle/) and the plugins that add bodies to it
// (swingarm/compliance/). They sit in this small library below plugins/ so that plugins can use
// them without an upward include; they need Simbody only.
#include "Simbody.h"

namespace motostab::multibody {

/// A revolute joint about axis n_C (unit, child-body frame) through point p_C (child frame), with
/// q = 0 at the design pose, where the child body frame sits at X_PC0 in the parent body frame.
SimTK::MobilizedBody::Pin addPinAtDesignPose(SimTK::MobilizedBody& parent, const SimTK::Transform& X_PC0,
                                             const SimTK::Body& body, const SimTK::Vec3& p_C, const SimTK::Vec3& n_C);

}  // namespace motostab::multibody
