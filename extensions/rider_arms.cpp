#include "extensions/rider_arms.h"

#include <Eigen/Dense>

#include <cmath>
#include <ostream>

#include "extensions/extension_input.h"
#include "extensions/steer_torque.h"

namespace motostab::extensions {

using scenario::BodySpec;

namespace {

class RiderArms : public plugins::ExtensionModel {
 public:
  RiderArms(const RiderArmsParams& p, const BodySpec& grips) : p_(p), grips_(grips) {}
  void adjustFrames(plugins::FrameMasses& frames) const override {
    frames.rearFrame = scenario::calcBodyRemainder(frames.rearFrame, grips_);
    frames.frontFrame = scenario::composeBodies({frames.frontFrame, grips_});
  }
  void addForces(plugins::BuildContext& ctx, const plugins::VehicleFrames& frames) override {
    const RiderArmsParams p = p_;
    addSteerTorque(
        ctx, frames.frontFrame, [p](double steer, double rate) { return calcRiderArmsTorque(p, steer, rate); },
        [p](double steer) { return 0.5 * p.stiffness * steer * steer; });
  }
  void describe(std::ostream& os) const override {
    os << "  rider arms            " << p_.inertia << " kg m^2 on the steer axis (grips " << grips_.mass << " kg, "
       << p_.gripHalfWidth << " m from it), " << p_.stiffness << " N m/rad, " << p_.damping << " N m s/rad\n";
  }

 private:
  RiderArmsParams p_;
  BodySpec grips_;
};

}  // namespace

BodySpec calcGripMasses(const RiderArmsParams& a, const plugins::VehicleLayout& v) {
  // The steer axis through its ground point (w + c, 0, 0) along n = (-sin lambda, 0, cos lambda); the
  // grips at the point of it nearest the front frame's CoM, +/- d along y (distance d from the axis).
  const double lambda = v.steerAxisTilt;
  const Eigen::Vector3d p0(v.wheelbase + v.trail, 0, 0), n(-std::sin(lambda), 0, std::cos(lambda));
  const Eigen::Vector3d g = p0 + n * n.dot(Eigen::Vector3d(v.frontFrame.com[0], 0, v.frontFrame.com[2]) - p0);
  const double d = a.gripHalfWidth, mass = a.inertia / (d * d);  // two grips of mass/2 each at distance d
  BodySpec b;
  b.mass = mass;
  b.com = {g(0), 0, g(2)};
  b.inertia = {mass * d * d, 0, mass * d * d, 0, 0, 0};  // about any axis in the x-z plane: m d^2
  return b;
}

const io::SectionFields& getRiderArmsFields() {
  using io::Field;
  using io::Quantity;
  using io::Range;
  static const io::SectionFields f{
      "rider_arms",
      {Field::number("inertia_kgm2", "kg m^2", Range::Positive,
                     "J_a, added steer inertia about the steer axis (Sharp 1994: 0.20 kg m^2)")
           .measures(Quantity::Inertia),
       Field::number("stiffness_Nm_per_rad", "N m/rad", Range::NonNegative, "k_a (Sharp 1994: 50 N m/rad)")
           .measures(Quantity::Other),
       Field::number("damping_Nms_per_rad", "N m s/rad", Range::NonNegative,
                     "c_a (Sharp 1994: 6 N m s/rad hands on against 1 hands off)")
           .measures(Quantity::Other),
       Field::number("grip_half_width_m", "m", Range::Positive, "d, the grips' distance from the steer axis")
           .withDefault(RiderArmsParams().gripHalfWidth)
           .measures(Quantity::Length)}};
  return f;
}

RiderArmsParams readRiderArms(io::YamlMap& m, const plugins::VehicleLayout& v) {
  const io::SectionFields& f = getRiderArmsFields();
  RiderArmsParams a;
  a.inertia = io::readNumber(m, f.get("inertia_kgm2"));
  a.stiffness = io::readNumber(m, f.get("stiffness_Nm_per_rad"));
  a.damping = io::readNumber(m, f.get("damping_Nms_per_rad"));
  a.gripHalfWidth = io::readNumber(m, f.get("grip_half_width_m"));
  checkRemainder(m, "inertia_kgm2", v.rearFrame, calcGripMasses(a, v), "rear_frame");
  return a;
}

double calcRiderArmsTorque(const RiderArmsParams& p, double steer, double steerRate) {
  return -p.stiffness * steer - p.damping * steerRate;
}

std::unique_ptr<plugins::ExtensionModel> makeRiderArms(const RiderArmsParams& p, const plugins::VehicleLayout& v) {
  return std::make_unique<RiderArms>(p, calcGripMasses(p, v));
}

void registerRiderArms(plugins::PluginRegistrar& registry) {
  registry.addSectionFields(getRiderArmsFields());
  registry.addExtensionModel("rider_arms", [](io::YamlMap& m, const plugins::VehicleLayout& v) {
    return makeRiderArms(readRiderArms(m, v), v);
  });
}

}  // namespace motostab::extensions
