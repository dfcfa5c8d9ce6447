#include "vehicle/rider_lean.h"

#include "multibody/pin_joint.h"
#include "plugins/pin_spring_damper.h"
#include "vehicle/body_builder.h"

namespace motostab::vehicle {

using multibody::addPinAtDesignPose;
using plugins::BuildContext;
using plugins::addPinSpringDamper;
using scenario::RiderLeanSpec;


plugins::NamedMobilizer addRiderLean(BuildContext& ctx, SimTK::MobilizedBody& rearFrame, const SimTK::Vec3& p_DR,
                                     const RiderLeanSpec& spec) {
  const SimTK::Vec3 p_DH(0, 0, spec.hingeHeight);  // hinge point in D; the upper body's origin
  SimTK::MobilizedBody::Pin upper = addPinAtDesignPose(rearFrame, SimTK::Transform(p_DH - p_DR),
                                                       makeBody(spec.body, p_DH), SimTK::Vec3(0), SimTK::Vec3(1, 0, 0));
  addPinSpringDamper(ctx.forces, upper, spec.stiffness, spec.damping);
  return {"rider_lean", plugins::StateRole::RiderLean, upper};
}

}  // namespace motostab::vehicle
