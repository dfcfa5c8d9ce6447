#include "extensions/rider_lean.h"

#include <ostream>

#include "extensions/extension_input.h"
#include "multibody/pin_joint.h"
#include "multibody/pin_spring_damper.h"
#include "plugins/rigid_body.h"
#include "scenario/scenario.h"
#include "scenario/scenario_fields.h"

namespace motostab::extensions {

namespace {

class RiderLean : public plugins::ExtensionModel {
 public:
  explicit RiderLean(const RiderLeanParams& p) : p_(p) {}
  void adjustFrames(plugins::FrameMasses& frames) const override {
    frames.rearFrame = scenario::calcBodyRemainder(frames.rearFrame, p_.body);
  }
  std::vector<plugins::NamedMobilizer> addRearBodies(plugins::BuildContext& ctx, const plugins::VehicleFrames& frames) override {
    const SimTK::Vec3 p_DH(0, 0, p_.hingeHeight);  // hinge point in D; the upper body's origin
    SimTK::MobilizedBody rear = frames.rearFrame;
    SimTK::MobilizedBody::Pin upper = multibody::addPinAtDesignPose(rear, SimTK::Transform(p_DH - frames.p_DR),
                                                                    plugins::makeRigidBody(p_.body, p_DH), SimTK::Vec3(0),
                                                                    SimTK::Vec3(1, 0, 0));
    multibody::addPinSpringDamper(ctx.forces, upper, p_.stiffness, p_.damping);
    return {{"rider_lean", plugins::StateRole::RiderLean, upper}};
  }
  std::vector<plugins::ExtensionBody> getBodies() const override {
    return {{plugins::ExtensionBody::Frame::Rear, {"rider_upper_body", p_.body}}};
  }
  void describe(std::ostream& os) const override {
    os << "  rider lean            upper body " << p_.body.mass << " kg, hinge at " << p_.hingeHeight << " m, " << p_.stiffness
       << " N m/rad, " << p_.damping << " N m s/rad\n";
  }

 private:
  RiderLeanParams p_;
};

}  // namespace

const io::SectionFields& getRiderLeanFields() {
  using io::Field;
  using io::Quantity;
  using io::Range;
  static const io::SectionFields f = [] {
    io::SectionFields s{"rider_lean",
                        {Field::number("hinge_height_m", "m", Range::Positive,
                                       "h, height of the hinge axis above the ground (hip / saddle)")
                             .measures(Quantity::Length)}};
    for (const Field& b : scenario::makeBodyFields("", "upper body (in D)").fields)
      s.fields.push_back(b.key == "com_m" ? b.inPlaneOfSymmetry() : b);
    for (const Field& k : getSpringDamperFields().fields) s.fields.push_back(k.measures(Quantity::Other));
    return s;
  }();
  return f;
}

RiderLeanParams readRiderLean(io::YamlMap& m, const plugins::VehicleLayout& v) {
  RiderLeanParams r;
  r.hingeHeight = io::readNumber(m, getRiderLeanFields().get("hinge_height_m"));
  r.body = scenario::readBodyKeys(m);
  const SpringDamper k = readSpringDamper(m);
  r.stiffness = k.stiffness;
  r.damping = k.damping;
  if (r.body.com[1] != 0) m.fail("com_m", "the upper body's centre of mass must lie in the plane of symmetry (y = 0)");
  checkRemainder(m, "mass_kg", v.rearFrame, r.body, "rear_frame");
  return r;
}

std::unique_ptr<plugins::ExtensionModel> makeRiderLean(const RiderLeanParams& p) { return std::make_unique<RiderLean>(p); }

void registerRiderLean(plugins::PluginRegistrar& registry) {
  registry.addSectionFields(getRiderLeanFields());
  registry.addExtensionModel("rider_lean", [](io::YamlMap& m, const plugins::VehicleLayout& v) {
    return makeRiderLean(readRiderLean(m, v));
  });
}

}  // namespace motostab::extensions
