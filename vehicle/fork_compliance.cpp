#include "vehicle/fork_compliance.h"

#include <cmath>

#include "multibody/pin_joint.h"
#include "plugins/pin_spring_damper.h"
#include "vehicle/body_builder.h"

namespace motostab::vehicle {

using multibody::addPinAtDesignPose;
using plugins::BuildContext;
using plugins::addPinSpringDamper;
using scenario::ForkComplianceSpec;
using scenario::Scenario;


SimTK::Vec3 calcForkHingePoint(const Scenario& s) {
  const double lambda = s.geometry.steerAxisTilt, d = s.forkCompliance.axisDistance;
  return SimTK::Vec3(s.geometry.wheelbase + s.geometry.trail, 0, 0) +
         d * SimTK::Vec3(-std::sin(lambda), 0, std::cos(lambda));
}

SimTK::Vec3 calcForkBendingAxis(const Scenario& s) {
  const double lambda = s.geometry.steerAxisTilt;
  return SimTK::Vec3(std::cos(lambda), 0, std::sin(lambda));
}

ForkAssembly addForkCompliance(BuildContext& ctx, SimTK::MobilizedBody& frontFrame, const SimTK::Vec3& p_DF,
                               const Scenario& s) {
  const ForkComplianceSpec& f = s.forkCompliance;
  const SimTK::Vec3 p_FP = calcForkHingePoint(s) - p_DF;  // hinge point from the hub (body frames share axes)
  ForkAssembly out;
  SimTK::MobilizedBody::Pin carrier =
      addPinAtDesignPose(frontFrame, SimTK::Transform(), makeBody(f.carrier, p_DF), p_FP, calcForkBendingAxis(s));
  addPinSpringDamper(ctx.forces, carrier, f.stiffness, f.damping);
  out.coordinates.push_back({"fork_bending", plugins::StateRole::ForkBending, carrier});
  out.hubCarrier = carrier;
  if (f.hasTorsion) {
    const double lambda = s.geometry.steerAxisTilt;
    SimTK::MobilizedBody::Pin link = addPinAtDesignPose(carrier, SimTK::Transform(), SimTK::Body::Massless(), p_FP,
                                                        SimTK::Vec3(-std::sin(lambda), 0, std::cos(lambda)));
    addPinSpringDamper(ctx.forces, link, f.torsionStiffness, f.torsionDamping);
    out.coordinates.push_back({"fork_torsion", plugins::StateRole::ForkTorsion, link});
    out.hubCarrier = link;
  }
  return out;
}

}  // namespace motostab::vehicle
