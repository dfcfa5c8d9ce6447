#include "extensions/fork_compliance.h"

#include <cmath>
#include <ostream>

#include "extensions/extension_input.h"
#include "multibody/pin_joint.h"
#include "multibody/pin_spring_damper.h"
#include "plugins/rigid_body.h"
#include "scenario/scenario.h"
#include "scenario/scenario_fields.h"

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
  plugins::BodyCarrier addFrontHubCarrier(plugins::BuildContext& ctx, const plugins::VehicleFrames& frames) override {
    const SimTK::Vec3 p_FP = p_DP_ - frames.p_DF;  // hinge point from the hub (body frames share axes)
    plugins::BodyCarrier out;
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

const std::vector<io::SectionFields>& getForkComplianceFields() {
  using io::Field;
  using io::Quantity;
  using io::Range;
  using io::Shape;
  static const std::vector<io::SectionFields> f = [] {
    io::SectionFields fork{"fork_compliance", {}};
    const io::SectionFields& k = getSpringDamperFields();
    for (const auto& [key, meaning] : {std::pair<std::string, std::string>{"stiffness_Nm_per_rad", "k_b, bending stiffness about n_b"},
                                       {"damping_Nms_per_rad", "c_b, bending damping"}}) {
      Field f = k.get(key);
      f.meaning = meaning;
      fork.fields.push_back(f);
    }
    fork.fields.push_back(Field::number("axis_distance_along_steer_m", "m", Range::Any,
                                        "d, along the steer axis from its ground point; absent: the fork crown estimate "
                                        "2 r_F / cos lambda (the steer-axis point at the height of the tyre's top)")
                              .optional());
    fork.fields.push_back(Field::number("carrier_mass_fraction", "", Range::Fraction,
                                        "the carrier as this fraction of the front frame (of its mass at its CoM, and of its "
                                        "inertia; an estimate for lower legs, axle and brake); instead of `carrier`")
                              .withDefault(kDefaultForkCarrierFraction));
    fork.fields.push_back(Field::of(Shape::Other, "carrier", "", "",
                                    "the carrier's own mass properties `{mass_kg, com_m, inertia_kgm2}` in D, instead of "
                                    "`carrier_mass_fraction`")
                              .optional());
    fork.fields.push_back(Field::of(Shape::Other, "torsion", "", "",
                                    "`{stiffness_Nm_per_rad, damping_Nms_per_rad}`: a massless link in series between "
                                    "carrier and wheel turning about the steer-axis direction through P")
                              .optional());
    io::SectionFields carrier = scenario::makeBodyFields("fork_compliance.carrier", "fork's hub carrier (lower legs, axle, brake) in D");
    io::SectionFields torsion{"fork_compliance.torsion", k.fields};
    return std::vector<io::SectionFields>{fork, carrier, torsion};
  }();
  return f;
}

ForkComplianceParams readForkCompliance(io::YamlMap& m, const plugins::VehicleLayout& v) {
  const io::SectionFields& fields = getForkComplianceFields().front();
  ForkComplianceParams f;
  f.bending = readSpringDamper(m);
  f.axisDistance = m.has("axis_distance_along_steer_m") ? io::readNumber(m, fields.get("axis_distance_along_steer_m"))
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
    f.carrierFraction = io::readNumber(m, fields.get(carrierKey));
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
  for (const io::SectionFields& f : getForkComplianceFields()) registry.addSectionFields(f);
  registry.addExtensionModel("fork_compliance", [](io::YamlMap& m, const plugins::VehicleLayout& v) {
    return makeForkCompliance(readForkCompliance(m, v), v);
  });
}

}  // namespace motostab::extensions
