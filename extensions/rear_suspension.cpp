#include "extensions/rear_suspension.h"

#include <ostream>

#include "multibody/pin_joint.h"
#include "multibody/pin_spring_damper.h"

namespace motostab::extensions {

namespace {

class RearSuspension : public plugins::ExtensionModel {
 public:
  explicit RearSuspension(const RearSuspensionParams& p) : p_(p) {}
  plugins::BodyCarrier addSwingarmCarrier(plugins::BuildContext& ctx, const plugins::VehicleFrames& frames,
                                          const SimTK::Vec3& p_DP) override {
    SimTK::MobilizedBody rear = frames.rearFrame;
    SimTK::MobilizedBody::Pin link = multibody::addPinAtDesignPose(rear, SimTK::Transform(p_DP - frames.p_DR),
                                                                   SimTK::Body::Massless(), SimTK::Vec3(0), SimTK::Vec3(0, 1, 0));
    multibody::addPinSpringDamper(ctx.forces, link, p_.stiffness, p_.damping, -p_.staticPivotMoment / p_.stiffness);
    return {link, {{"suspension_pitch", plugins::StateRole::Suspension, link}}};
  }
  void describe(std::ostream& os) const override {
    const double l2 = p_.lever * p_.lever;
    os << "  rear suspension       " << p_.stiffness << " N m/rad, " << p_.damping << " N m s/rad about the pivot (at the wheel "
       << p_.stiffness / l2 << " N/m, " << p_.damping / l2 << " N s/m; lever " << p_.lever << " m); static pivot moment "
       << p_.staticPivotMoment << " N m\n";
  }

 private:
  RearSuspensionParams p_;
};

// One quantity given about the pivot (field `pivot`) or referred to the wheel (field `wheel`,
// converted with lever^2); exactly one of the two keys.
double readPivotOrWheel(io::YamlMap& m, const io::Field& pivot, const io::Field& wheel, double lever) {
  if (m.has(pivot.key) && m.has(wheel.key)) m.fail(wheel.key, "give only one of " + pivot.key + " and " + wheel.key);
  if (!m.has(pivot.key) && !m.has(wheel.key)) m.failMissing(wheel.key, pivot.key);
  return m.has(pivot.key) ? io::readNumber(m, pivot) : io::readNumber(m, wheel) * lever * lever;
}

}  // namespace

const io::SectionFields& getRearSuspensionFields() {
  using io::Field;
  using io::Range;
  static const io::SectionFields f{
      "swingarm.suspension",
      {Field::number("wheel_rate_N_per_m", "N/m", Range::Positive,
                     "k_wheel, vertical force at the tyre contact per vertical hub travel relative to the rear frame "
                     "(SAE J670); or `stiffness_Nm_per_rad`")
           .optional(),
       Field::number("stiffness_Nm_per_rad", "N m/rad", Range::Positive, "k_theta about the pivot, instead of `wheel_rate_N_per_m`")
           .optional(),
       Field::number("damping_Ns_per_m", "N s/m", Range::NonNegative, "c_wheel, referred to the wheel; or `damping_Nms_per_rad`")
           .optional(),
       Field::number("damping_Nms_per_rad", "N m s/rad", Range::NonNegative, "c_theta about the pivot, instead of `damping_Ns_per_m`")
           .optional()}};
  return f;
}

double calcSuspensionLever(const plugins::VehicleLayout& v) { return v.swingarmPivot[0]; }

RearSuspensionParams readRearSuspension(io::YamlMap& m, const plugins::VehicleLayout& v) {
  if (!v.hasSwingarm) m.fail("", "a rear suspension turns a swingarm about its pivot: the scenario has no swingarm");
  RearSuspensionParams p;
  p.lever = calcSuspensionLever(v);
  p.staticPivotMoment = v.staticPivotMoment;
  const io::SectionFields& f = getRearSuspensionFields();
  p.stiffness = readPivotOrWheel(m, f.get("stiffness_Nm_per_rad"), f.get("wheel_rate_N_per_m"), p.lever);
  p.damping = readPivotOrWheel(m, f.get("damping_Nms_per_rad"), f.get("damping_Ns_per_m"), p.lever);
  return p;
}

std::unique_ptr<plugins::ExtensionModel> makeRearSuspension(const RearSuspensionParams& p) {
  return std::make_unique<RearSuspension>(p);
}

void registerRearSuspension(plugins::PluginRegistrar& registry) {
  registry.addSectionFields(getRearSuspensionFields());
  registry.addExtensionModel("swingarm.suspension", [](io::YamlMap& m, const plugins::VehicleLayout& v) {
    return makeRearSuspension(readRearSuspension(m, v));
  });
}

}  // namespace motostab::extensions
