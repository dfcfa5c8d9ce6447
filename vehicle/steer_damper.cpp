#include "vehicle/steer_damper.h"

#include <cmath>

namespace motostab::vehicle {

using plugins::BuildContext;
using scenario::SteerDamperSpec;

namespace {

class SteerDamper : public SimTK::Force::Custom::Implementation {
 public:
  SteerDamper(const SimTK::MobilizedBody& front, const SteerDamperSpec& spec) : front_(front), spec_(spec) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector& mobilityForces) const override {
    const double rate = front_.getOneU(s, SimTK::MobilizerUIndex(0));
    front_.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), calcSteerDamperTorque(spec_, rate), mobilityForces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

 private:
  SimTK::MobilizedBody front_;
  SteerDamperSpec spec_;
};

}  // namespace

double calcSteerDamperTorque(const SteerDamperSpec& spec, double steerRate) {
  double t = -spec.damping * steerRate;
  if (spec.coulomb > 0) t -= spec.coulomb * std::tanh(steerRate / spec.coulombSmoothing);
  return t;
}

void addSteerDamper(BuildContext& ctx, const SimTK::MobilizedBody& frontFrame, const SteerDamperSpec& spec) {
  SimTK::Force::Custom(ctx.forces, new SteerDamper(frontFrame, spec));
}

}  // namespace motostab::vehicle
