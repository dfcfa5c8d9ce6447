#include "tyres/rolling_no_slip.h"

#include "Simbody.h"

namespace motostab::tyres {

using io::YamlMap;
using plugins::BuildContext;
using plugins::ContactPoint;
using plugins::calcTorusContact;
using plugins::ContactModel;
using plugins::PluginRegistrar;
using plugins::WheelSite;


using SimTK::Array_;
using SimTK::ConstrainedBodyIndex;
using SimTK::ConstrainedQIndex;
using SimTK::ConstrainedUIndex;
using SimTK::Real;
using SimTK::SpatialVec;
using SimTK::State;
using SimTK::Transform;
using SimTK::Vec3;

namespace {

// One holonomic equation (contact height) and two nonholonomic ones (no slip along ground x, y).
// All three are components of the velocity of the wheel's material point at the contact: its
// normal component is exactly the time derivative of the contact height (envelope theorem).
class RollingConstraint : public SimTK::Constraint::Custom::Implementation {
 public:
  RollingConstraint(SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& wheel, double R, double rho)
      : Implementation(matter, 1, 2, 0), radius_(R), crown_(rho) {
    wheel_ = addConstrainedBody(wheel);
    ground_ = addConstrainedBody(matter.Ground());
  }
  Implementation* clone() const override { return new RollingConstraint(*this); }

  void calcPositionErrors(const State&, const Array_<Transform, ConstrainedBodyIndex>& X_AB,
                          const Array_<Real, ConstrainedQIndex>&, Array_<Real>& perr) const override {
    const Transform& X_GW = X_AB[wheel_];
    perr[0] = X_GW.p()[2] + contact(X_GW.R(), Vec3(0)).r_CP_G[2];
  }

  void calcPositionDotErrors(const State& s, const Array_<SpatialVec, ConstrainedBodyIndex>& V_AB,
                             const Array_<Real, ConstrainedQIndex>&, Array_<Real>& pverr) const override {
    pverr[0] = contactPointVelocity(s, V_AB[wheel_])[2];
  }

  void calcPositionDotDotErrors(const State& s, const Array_<SpatialVec, ConstrainedBodyIndex>& A_AB,
                                const Array_<Real, ConstrainedQIndex>&, Array_<Real>& paerr) const override {
    paerr[0] = contactPointAcceleration(s, A_AB[wheel_])[2];
  }

  void addInPositionConstraintForces(const State& s, const Array_<Real>& multipliers,
                                     Array_<SpatialVec, ConstrainedBodyIndex>& bodyForcesInA,
                                     Array_<Real, ConstrainedQIndex>&) const override {
    applyContactForce(s, Vec3(0, 0, multipliers[0]), bodyForcesInA);
  }

  void calcVelocityErrors(const State& s, const Array_<SpatialVec, ConstrainedBodyIndex>& V_AB,
                          const Array_<Real, ConstrainedUIndex>&, Array_<Real>& verr) const override {
    const Vec3 v = contactPointVelocity(s, V_AB[wheel_]);
    verr[0] = v[0];
    verr[1] = v[1];
  }

  void calcVelocityDotErrors(const State& s, const Array_<SpatialVec, ConstrainedBodyIndex>& A_AB,
                             const Array_<Real, ConstrainedUIndex>&, Array_<Real>& vaerr) const override {
    const Vec3 a = contactPointAcceleration(s, A_AB[wheel_]);
    vaerr[0] = a[0];
    vaerr[1] = a[1];
  }

  void addInVelocityConstraintForces(const State& s, const Array_<Real>& multipliers,
                                     Array_<SpatialVec, ConstrainedBodyIndex>& bodyForcesInA,
                                     Array_<Real, ConstrainedUIndex>&) const override {
    applyContactForce(s, Vec3(multipliers[0], multipliers[1], 0), bodyForcesInA);
  }

 private:
  ContactPoint contact(const SimTK::Rotation& R_GW, const Vec3& w) const {
    return calcTorusContact(R_GW, w, radius_, crown_);
  }
  Vec3 r_CP(const State& s) const {
    return contact(getBodyRotationFromState(s, wheel_), Vec3(0)).r_CP_G;
  }
  // Velocity of the wheel's material point at the contact: v_C + w x r_CP.
  Vec3 contactPointVelocity(const State& s, const SpatialVec& V_GW) const {
    return V_GW[1] + V_GW[0] % r_CP(s);
  }
  // Its time derivative: a_C + alpha x r_CP + w x d/dt(r_CP).
  Vec3 contactPointAcceleration(const State& s, const SpatialVec& A_GW) const {
    const Vec3& w = getBodyAngularVelocityFromState(s, wheel_);
    const ContactPoint c = contact(getBodyRotationFromState(s, wheel_), w);
    return A_GW[1] + A_GW[0] % c.r_CP_G + w % c.rDot_CP_G;
  }
  // Constraint force f_G at the contact point of the wheel; the reaction on Ground does no work.
  void applyContactForce(const State& s, const Vec3& f_G, Array_<SpatialVec, ConstrainedBodyIndex>& F) const {
    const SimTK::Rotation& R_GW = getBodyRotationFromState(s, wheel_);
    const Vec3 r = contact(R_GW, Vec3(0)).r_CP_G;
    F[wheel_] += SpatialVec(r % f_G, f_G);
  }

  double radius_, crown_;
  ConstrainedBodyIndex wheel_, ground_;
};

class RollingNoSlip : public ContactModel {
 public:
  void addWheel(BuildContext& ctx, const WheelSite& w) override {
    SimTK::Constraint::Custom(new RollingConstraint(ctx.matter, w.wheel, w.radius, w.crownRadius));
  }
};

}  // namespace

void registerRollingNoSlip(PluginRegistrar& registry) {
  registry.addContactModel("rolling_no_slip", [](YamlMap&) { return std::make_unique<RollingNoSlip>(); });
}

}  // namespace motostab::tyres
