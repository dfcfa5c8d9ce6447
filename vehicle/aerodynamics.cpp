#include "vehicle/aerodynamics.h"

namespace motostab::vehicle {

using plugins::BuildContext;
using scenario::AerodynamicsSpec;

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

}  // namespace

void addAerodynamicDrag(BuildContext& ctx, const SimTK::MobilizedBody& rearFrame, const AerodynamicsSpec& spec,
                        const SimTK::Vec3& p_RC) {
  SimTK::Force::Custom(ctx.forces, new AerodynamicDrag(rearFrame, 0.5 * spec.airDensity * spec.dragArea, p_RC));
}

}  // namespace motostab::vehicle
