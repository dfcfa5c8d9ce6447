#include "multibody/pin_joint.h"

namespace motostab::multibody {

SimTK::MobilizedBody::Pin addPinAtDesignPose(SimTK::MobilizedBody& parent, const SimTK::Transform& X_PC0,
                                             const SimTK::Body& body, const SimTK::Vec3& p_C, const SimTK::Vec3& n_C) {
  const SimTK::Transform X_CM(SimTK::Rotation(SimTK::UnitVec3(n_C), SimTK::ZAxis), p_C);
  return SimTK::MobilizedBody::Pin(parent, X_PC0 * X_CM, body, X_CM);
}

}  // namespace motostab::multibody
