// An example third-party plugin: a contact model `example_vertical_spring` that only supports the
// wheels vertically (a linear spring under the wheel centre). Build it as a shared library and list
// it in a scenario: `plugins: [path/to/libmotostab_example_plugin.so]` (see docs/plugins.md).
#include "io/field.h"
#include "plugins/plugin_api.h"

namespace {

class VerticalSpring : public SimTK::Force::Custom::Implementation {
 public:
  VerticalSpring(const SimTK::MobilizedBody& wheel, double radius, double stiffness)
      : wheel_(wheel), radius_(radius), k_(stiffness) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector&) const override {
    const double deflection = radius_ - wheel_.getBodyOriginLocation(s)[2];
    if (deflection > 0) wheel_.applyBodyForce(s, SimTK::SpatialVec(SimTK::Vec3(0), SimTK::Vec3(0, 0, k_ * deflection)), bodyForces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

 private:
  SimTK::MobilizedBody wheel_;
  double radius_, k_;
};

class VerticalSpringContact : public motostab::plugins::ContactModel {
 public:
  explicit VerticalSpringContact(double k) : k_(k) {}
  void addWheel(motostab::plugins::BuildContext& ctx, const motostab::plugins::WheelSite& w) override {
    SimTK::Force::Custom(ctx.forces, new VerticalSpring(w.wheel, w.radius, k_));
  }
  // The spring stands straight under the wheel centre whatever the camber: so does the contact point
  // (the trims take it from here, not from a torus).
  motostab::plugins::ContactPoint calcContactPoint(const motostab::plugins::WheelSite& w, const SimTK::Rotation&,
                                                   const SimTK::Vec3&) const override {
    return {SimTK::Vec3(0, 0, -w.radius), SimTK::Vec3(0)};
  }

 private:
  double k_;
};

}  // namespace

namespace {
int entryCalls = 0;

// The plugin's keys of the `contact` section, declared once: read through here, listed by diagnosis
// (a measured field is a parameter it may fit) and by the Python module's `parameters()`.
const motostab::io::SectionFields& getFields() {
  using motostab::io::Field;
  static const motostab::io::SectionFields fields{
      "contact",
      {Field::number("stiffness_N_per_m", "N/m", motostab::io::Range::Positive, "vertical stiffness under each wheel")
           .measures(motostab::io::Quantity::Other)},
      "contact.model",
      "example_vertical_spring"};
  return fields;
}
}  // namespace

/// How often the entry point ran in this process (tests check that a library loads once).
extern "C" int motostab_example_entry_calls() { return entryCalls; }

MOTOSTAB_PLUGIN_ENTRY {
  ++entryCalls;
  registry.addSectionFields(getFields());
  registry.addContactModel("example_vertical_spring", [](motostab::io::YamlMap& params) -> std::unique_ptr<motostab::plugins::ContactModel> {
    return std::make_unique<VerticalSpringContact>(motostab::io::readNumber(params, getFields().get("stiffness_N_per_m")));
  });
}
