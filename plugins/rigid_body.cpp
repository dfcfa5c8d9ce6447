#include "plugins/rigid_body.h"

namespace motostab::plugins {

SimTK::Body::Rigid makeRigidBody(const scenario::BodySpec& b, const SimTK::Vec3& origin_D) {
  const SimTK::Vec3 com_B = toVec3(b.com) - origin_D;
  const SimTK::Inertia I_com(SimTK::Vec3(b.inertia.xx, b.inertia.yy, b.inertia.zz),
                             SimTK::Vec3(b.inertia.xy, b.inertia.xz, b.inertia.yz));
  return SimTK::Body::Rigid(SimTK::MassProperties(b.mass, com_B, I_com.shiftFromMassCenter(-com_B, b.mass)));
}

}  // namespace motostab::plugins
