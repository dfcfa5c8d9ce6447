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

SteerDamperParams readSteerDamper(io::YamlMap& m) {
  SteerDamperParams d;
  d.damping = m.getNonNegative("damping_Nms_per_rad");
  if (m.has("coulomb_Nm")) d.coulomb = m.getNonNegative("coulomb_Nm");
  if (m.has("coulomb_smoothing_rad_per_s")) d.coulombSmoothing = m.getPositive("coulomb_smoothing_rad_per_s");
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
  registry.addExtensionModel("steer_damper", [](io::YamlMap& m, const plugins::VehicleLayout&) {
    return makeSteerDamper(readSteerDamper(m));
  });
}

}  // namespace motostab::extensions
