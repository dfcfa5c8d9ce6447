#include "extensions/fork_compliance.h"

#include <cmath>
#include <ostream>

#include "multibody/pin_joint.h"
#include "multibody/pin_spring_damper.h"
#include "plugins/rigid_body.h"
#include "scenario/scenario.h"

namespace motostab::extensions {

using scenario::BodySpec;

namespace {

class ForkCompliance : public plugins::ExtensionModel {
 public:
  ForkCompliance(const ForkComplianceParams& p, const plugins::VehicleLayout& v)
      : p_(p), p_DP_(calcForkHingePoint(p, v)), n_b_(calcForkBendingAxis(v)),
        n_s_(-std::sin(v.steerAxisTilt), 0, std::cos(v.steerAxisTilt)) {}
  void adjustFrames(plugins::FrameMasses& frames) const override {
    frames.frontFrame = scenario::calcBodyRemainder(frames.frontFrame, p_.carrier);
  }
  plugins::FrontHubCarrier addFrontHubCarrier(plugins::BuildContext& ctx, const plugins::VehicleFrames& frames) override {
    const SimTK::Vec3 p_FP = p_DP_ - frames.p_DF;  // hinge point from the hub (body frames share axes)
    plugins::FrontHubCarrier out;
    SimTK::MobilizedBody front = frames.frontFrame;
    SimTK::MobilizedBody::Pin carrier = multibody::addPinAtDesignPose(
        front, SimTK::Transform(), plugins::makeRigidBody(p_.carrier, frames.p_DF), p_FP, n_b_);
    multibody::addPinSpringDamper(ctx.forces, carrier, p_.bending.stiffness, p_.bending.damping);
    out.coordinates.push_back({"fork_bending", plugins::StateRole::ForkBending, carrier});
    out.carrier = carrier;
    if (p_.hasTorsion) {
      SimTK::MobilizedBody::Pin link =
          multibody::addPinAtDesignPose(carrier, SimTK::Transform(), SimTK::Body::Massless(), p_FP, n_s_);
      multibody::addPinSpringDamper(ctx.forces, link, p_.torsion.stiffness, p_.torsion.damping);
      out.coordinates.push_back({"fork_torsion", plugins::StateRole::ForkTorsion, link});
      out.carrier = link;
    }
    return out;
  }
  std::vector<plugins::ExtensionBody> getBodies() const override {
    return {{plugins::ExtensionBody::Frame::Front, {"fork_carrier", p_.carrier}}};
  }
  void describe(std::ostream& os) const override {
    os << "  fork compliance       bending " << p_.bending.stiffness << " N m/rad, " << p_.bending.damping
       << " N m s/rad, axis " << p_.axisDistance << " m up the steer axis, carrier " << p_.carrier.mass << " kg";
    if (p_.hasTorsion) os << "; torsion " << p_.torsion.stiffness << " N m/rad, " << p_.torsion.damping << " N m s/rad";
    os << "\n";
  }

 private:
  ForkComplianceParams p_;
  SimTK::Vec3 p_DP_, n_b_, n_s_;
};

}  // namespace

double calcDefaultForkAxisDistance(const plugins::VehicleLayout& v) {
  return 2 * v.frontWheelRadius / std::cos(v.steerAxisTilt);
}

BodySpec calcDefaultForkCarrier(const plugins::VehicleLayout& v, double fraction) {
  BodySpec c;
  const BodySpec& H = v.frontFrame;
  c.mass = fraction * H.mass;
  c.com = H.com;
  const scenario::InertiaSpec& I = H.inertia;
  c.inertia = {fraction * I.xx, fraction * I.yy, fraction * I.zz, fraction * I.xy, fraction * I.xz, fraction * I.yz};
  return c;
}

SimTK::Vec3 calcForkHingePoint(const ForkComplianceParams& p, const plugins::VehicleLayout& v) {
  const double lambda = v.steerAxisTilt, d = p.axisDistance;
  return SimTK::Vec3(v.wheelbase + v.trail, 0, 0) + d * SimTK::Vec3(-std::sin(lambda), 0, std::cos(lambda));
}

SimTK::Vec3 calcForkBendingAxis(const plugins::VehicleLayout& v) {
  const double lambda = v.steerAxisTilt;
  return SimTK::Vec3(std::cos(lambda), 0, std::sin(lambda));
}

ForkComplianceParams readForkCompliance(io::YamlMap& m, const plugins::VehicleLayout& v) {
  ForkComplianceParams f;
  f.bending = readSpringDamper(m);
  f.axisDistance = m.has("axis_distance_along_steer_m") ? m.getDouble("axis_distance_along_steer_m")
                                                        : calcDefaultForkAxisDistance(v);
  if (m.has("carrier") && m.has("carrier_mass_fraction"))
    m.fail("carrier_mass_fraction", "give only one of carrier and carrier_mass_fraction");
  std::string carrierKey = "carrier_mass_fraction";
  if (m.has("carrier")) {
    io::YamlMap c = m.getMap("carrier");
    f.carrier = scenario::readBodyKeys(c);
    c.finish();
    carrierKey = "carrier";
  } else {
    f.carrierFraction = m.has(carrierKey) ? m.getPositive(carrierKey) : kDefaultForkCarrierFraction;
    if (f.carrierFraction >= 1) m.fail(carrierKey, "must be below 1");
    f.carrier = calcDefaultForkCarrier(v, f.carrierFraction);
  }
  checkRemainder(m, carrierKey, v.frontFrame, f.carrier, "front_frame");
  if (m.has("torsion")) {
    io::YamlMap t = m.getMap("torsion");
    f.hasTorsion = true;
    f.torsion = readSpringDamper(t);
    t.finish();
  }
  return f;
}

std::unique_ptr<plugins::ExtensionModel> makeForkCompliance(const ForkComplianceParams& p, const plugins::VehicleLayout& v) {
  return std::make_unique<ForkCompliance>(p, v);
}

void registerForkCompliance(plugins::PluginRegistrar& registry) {
  registry.addExtensionModel("fork_compliance", [](io::YamlMap& m, const plugins::VehicleLayout& v) {
    return makeForkCompliance(readForkCompliance(m, v), v);
  });
}

}  // namespace motostab::extensions
