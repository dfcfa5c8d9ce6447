#include "multibody/pin_spring_damper.h"

namespace motostab::multibody {
namespace {

class PinSpringDamper : public SimTK::Force::Custom::Implementation {
 public:
  PinSpringDamper(const SimTK::MobilizedBody& pin, double k, double c, double q0) : pin_(pin), k_(k), c_(c), q0_(q0) {}
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector& mobilityForces) const override {
    const double q = pin_.getOneQ(s, SimTK::MobilizerQIndex(0)), u = pin_.getOneU(s, SimTK::MobilizerUIndex(0));
    pin_.applyOneMobilityForce(s, SimTK::MobilizerUIndex(0), -k_ * (q - q0_) - c_ * u, mobilityForces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    const double dq = pin_.getOneQ(s, SimTK::MobilizerQIndex(0)) - q0_;
    return 0.5 * k_ * dq * dq;
  }

 private:
  SimTK::MobilizedBody pin_;
  double k_, c_, q0_;
};

}  // namespace

void addPinSpringDamper(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& pin, double stiffness,
                        double damping, double freeAngle) {
  SimTK::Force::Custom(forces, new PinSpringDamper(pin, stiffness, damping, freeAngle));
}

}  // namespace motostab::multibody
