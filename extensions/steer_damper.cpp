#include "extensions/steer_damper.h"

#include <ostream>

#include "extensions/steer_torque.h"

namespace motostab::extensions {

namespace {

class SteerDamper : public plugins::ExtensionModel {
 public:
  explicit SteerDamper(const SteerDamperParams& p) : p_(p) {}
  void addForces(plugins::BuildContext& ctx, const plugins::VehicleFrames& frames) override {
    const SteerDamperParams p = p_;
    addSteerTorque(ctx, frames.frontFrame, [p](double, double rate) { return calcSteerDamperTorque(p, rate); });
  }
  void describe(std::ostream& os) const override {
    os << "  steer damper          " << p_.damping << " N m s/rad, Coulomb " << p_.coulomb << " N m (smoothing "
       << p_.coulombSmoothing << " rad/s; linearised " << p_.damping + p_.coulomb / p_.coulombSmoothing << " N m s/rad)\n";
  }

 private:
  SteerDamperParams p_;
};

}  // namespace

const io::SectionFields& getSteerDamperFields() {
  using io::Field;
  using io::Range;
  static const io::SectionFields f{
      "steer_damper",
      {Field::number("damping_Nms_per_rad", "N m s/rad", Range::NonNegative,
                     "c, viscous damping (Meijaard et al. 2007 sec. 4: c added to the steer entry of C)"),
       Field::number("coulomb_Nm", "N m", Range::NonNegative, "f, Coulomb friction, smoothed by tanh").withDefault(0),
       Field::number("coulomb_smoothing_rad_per_s", "rad/s", Range::Positive,
                     "omega_s, steer rate at which the friction reaches tanh(1) = 76 % of f (99.9 % at 4 omega_s)")
           .withDefault(SteerDamperParams().coulombSmoothing)}};
  return f;
}

SteerDamperParams readSteerDamper(io::YamlMap& m) {
  const io::SectionFields& f = getSteerDamperFields();
  SteerDamperParams d;
  d.damping = io::readNumber(m, f.get("damping_Nms_per_rad"));
  d.coulomb = io::readNumber(m, f.get("coulomb_Nm"));
  d.coulombSmoothing = io::readNumber(m, f.get("coulomb_smoothing_rad_per_s"));
  return d;
}

double calcSteerDamperTorque(const SteerDamperParams& p, double steerRate) {
  double t = -p.damping * steerRate;
  if (p.coulomb > 0) t += calcSmoothedFrictionTorque(p.coulomb, p.coulombSmoothing, steerRate);
  return t;
}

std::unique_ptr<plugins::ExtensionModel> makeSteerDamper(const SteerDamperParams& p) {
  return std::make_unique<SteerDamper>(p);
}

void registerSteerDamper(plugins::PluginRegistrar& registry) {
  registry.addSectionFields(getSteerDamperFields());
  registry.addExtensionModel("steer_damper", [](io::YamlMap& m, const plugins::VehicleLayout&) {
    return makeSteerDamper(readSteerDamper(m));
  });
}

}  // namespace motostab::extensions
