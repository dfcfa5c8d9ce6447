#include "vehicle/rider_arms.h"

namespace motostab::vehicle {

using plugins::BuildContext;
using scenario::RiderArmsSpec;

namespace {

class RiderArms : public SimTK::Force::Custom::Implementation {
 public:
  RiderArms(const SimTK::MobilizedBody& front, const RiderArmsSpec& spec) : front_(front), spec_(spec) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector& mobilityForces) const override {
    const double steer = front_.getOneQ(s, SimTK::MobilizerQIndex(0));
    const double rate = front_.getOneU(s, SimTK::MobilizerUIndex(0));
    front_.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), calcRiderArmsTorque(spec_, steer, rate), mobilityForces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    const double steer = front_.getOneQ(s, SimTK::MobilizerQIndex(0));
    return 0.5 * spec_.stiffness * steer * steer;
  }

 private:
  SimTK::MobilizedBody front_;
  RiderArmsSpec spec_;
};

}  // namespace

double calcRiderArmsTorque(const RiderArmsSpec& spec, double steer, double steerRate) {
  return -spec.stiffness * steer - spec.damping * steerRate;
}

void addRiderArms(BuildContext& ctx, const SimTK::MobilizedBody& frontFrame, const RiderArmsSpec& spec) {
  SimTK::Force::Custom(ctx.forces, new RiderArms(frontFrame, spec));
}

}  // namespace motostab::vehicle
