#include "extensions/steer_head_friction.h"

#include <ostream>

#include "extensions/steer_torque.h"

namespace motostab::extensions {

namespace {

class SteerHeadFriction : public plugins::ExtensionModel {
 public:
  explicit SteerHeadFriction(const SteerHeadFrictionParams& p) : p_(p) {}
  void addForces(plugins::BuildContext& ctx, const plugins::VehicleFrames& frames) override {
    const SteerHeadFrictionParams p = p_;
    addSteerTorque(ctx, frames.frontFrame, [p](double, double rate) { return calcSteerHeadFrictionTorque(p, rate); });
  }
  void describe(std::ostream& os) const override {
    os << "  steer-head friction   " << p_.torque << " N m (smoothing " << p_.smoothing << " rad/s; linearised "
       << p_.torque / p_.smoothing << " N m s/rad)\n";
  }

 private:
  SteerHeadFrictionParams p_;
};

}  // namespace

const io::SectionFields& getSteerHeadFrictionFields() {
  using io::Field;
  using io::Range;
  static const io::SectionFields f{
      "steer_head_friction",
      {Field::number("torque_Nm", "N m", Range::NonNegative,
                     "T_f, the breakaway torque at the handlebar, front wheel off the ground"),
       Field::number("smoothing_rad_per_s", "rad/s", Range::Positive,
                     "omega_s, steer rate at which the friction reaches 76 % of T_f")
           .withDefault(SteerHeadFrictionParams().smoothing)}};
  return f;
}

SteerHeadFrictionParams readSteerHeadFriction(io::YamlMap& m) {
  const io::SectionFields& f = getSteerHeadFrictionFields();
  SteerHeadFrictionParams p;
  p.torque = io::readNumber(m, f.get("torque_Nm"));
  p.smoothing = io::readNumber(m, f.get("smoothing_rad_per_s"));
  return p;
}

double calcSteerHeadFrictionTorque(const SteerHeadFrictionParams& p, double steerRate) {
  return calcSmoothedFrictionTorque(p.torque, p.smoothing, steerRate);
}

std::unique_ptr<plugins::ExtensionModel> makeSteerHeadFriction(const SteerHeadFrictionParams& p) {
  return std::make_unique<SteerHeadFriction>(p);
}

void registerSteerHeadFriction(plugins::PluginRegistrar& registry) {
  registry.addSectionFields(getSteerHeadFrictionFields());
  registry.addExtensionModel("steer_head_friction", [](io::YamlMap& m, const plugins::VehicleLayout&) {
    return makeSteerHeadFriction(readSteerHeadFriction(m));
  });
}

}  // namespace motostab::extensions
