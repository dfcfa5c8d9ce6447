#include "extensions/steer_torque.h"

#include <cmath>

namespace motostab::extensions {

namespace {

class SteerTorque : public SimTK::Force::Custom::Implementation {
 public:
  SteerTorque(const SimTK::MobilizedBody& front, SteerTorqueLaw torque, SteerPotential potential)
      : front_(front), torque_(std::move(torque)), potential_(std::move(potential)) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector& mobilityForces) const override {
    const double steer = front_.getOneQ(s, SimTK::MobilizerQIndex(0));
    const double rate = front_.getOneU(s, SimTK::MobilizerUIndex(0));
    front_.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), torque_(steer, rate), mobilityForces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    return potential_ ? potential_(front_.getOneQ(s, SimTK::MobilizerQIndex(0))) : 0.0;
  }

 private:
  SimTK::MobilizedBody front_;
  SteerTorqueLaw torque_;
  SteerPotential potential_;
};

}  // namespace

double calcSmoothedFrictionTorque(double friction, double smoothing, double steerRate) {
  return -friction * std::tanh(steerRate / smoothing);
}

void addSteerTorque(plugins::BuildContext& ctx, const SimTK::MobilizedBody& frontFrame, SteerTorqueLaw torque,
                    SteerPotential potential) {
  SimTK::Force::Custom(ctx.forces, new SteerTorque(frontFrame, std::move(torque), std::move(potential)));
}

}  // namespace motostab::extensions
