#include "extensions/aerodynamics.h"

#include <ostream>

#include "plugins/rigid_body.h"

namespace motostab::extensions {

namespace {

class AerodynamicDrag : public SimTK::Force::Custom::Implementation {
 public:
  AerodynamicDrag(const SimTK::MobilizedBody& body, double halfRhoCdA, const SimTK::Vec3& p_RC)
      : body_(body), k_(halfRhoCdA), p_RC_(p_RC) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector&) const override {
    const SimTK::Vec3 v = body_.findStationVelocityInGround(s, p_RC_);
    body_.applyForceToBodyPoint(s, p_RC_, -k_ * v.norm() * v, bodyForces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

 private:
  SimTK::MobilizedBody body_;
  double k_;
  SimTK::Vec3 p_RC_;
};

class Aerodynamics : public plugins::ExtensionModel {
 public:
  explicit Aerodynamics(const AerodynamicsParams& p) : p_(p) {}
  void addForces(plugins::BuildContext& ctx, const plugins::VehicleFrames& frames) override {
    const SimTK::Vec3 p_RC = plugins::toVec3(p_.centreOfPressure) - frames.p_DR;
    SimTK::Force::Custom(ctx.forces, new AerodynamicDrag(frames.rearFrame, 0.5 * p_.airDensity * p_.dragArea, p_RC));
  }
  void describe(std::ostream& os) const override {
    const auto& c = p_.centreOfPressure;
    os << "  aerodynamic drag      CdA " << p_.dragArea << " m^2, air " << p_.airDensity << " kg/m^3, centre of pressure ["
       << c[0] << ", " << c[1] << ", " << c[2] << "] m\n";
  }

 private:
  AerodynamicsParams p_;
};

}  // namespace

const io::SectionFields& getAerodynamicsFields() {
  using io::Field;
  using io::Range;
  static const io::SectionFields f{
      "aerodynamics",
      {Field::number("drag_area_m2", "m^2", Range::NonNegative, "CdA, drag coefficient times frontal area"),
       Field::number("air_density_kgpm3", "kg/m^3", Range::Positive, "rho, air density"),
       Field::of(io::Shape::Vector3, "centre_of_pressure_m", "m", "", "centre of pressure in D, on the rear frame")}};
  return f;
}

AerodynamicsParams readAerodynamics(io::YamlMap& m) {
  const io::SectionFields& f = getAerodynamicsFields();
  AerodynamicsParams a;
  a.dragArea = io::readNumber(m, f.get("drag_area_m2"));
  a.airDensity = io::readNumber(m, f.get("air_density_kgpm3"));
  a.centreOfPressure = io::readVector3(m, f.get("centre_of_pressure_m"));
  return a;
}

std::unique_ptr<plugins::ExtensionModel> makeAerodynamics(const AerodynamicsParams& p) {
  return std::make_unique<Aerodynamics>(p);
}

void registerAerodynamics(plugins::PluginRegistrar& registry) {
  registry.addSectionFields(getAerodynamicsFields());
  registry.addExtensionModel("aerodynamics", [](io::YamlMap& m, const plugins::VehicleLayout&) {
    return makeAerodynamics(readAerodynamics(m));
  });
}

}  // namespace motostab::extensions
