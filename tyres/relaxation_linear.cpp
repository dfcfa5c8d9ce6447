#include "tyres/relaxation_linear.h"

#include <map>

#include "tyres/rolling_no_slip.h"

namespace motostab {

using SimTK::SpatialVec;
using SimTK::State;
using SimTK::Vec3;

namespace {

LinearTyreParameters readTyre(YamlMap m) {
  LinearTyreParameters p;
  p.corneringStiffness = m.getPositive("cornering_stiffness_per_rad");
  p.camberStiffness = m.getDouble("camber_stiffness_per_rad");
  p.selfAligningStiffness = m.getDouble("self_aligning_stiffness_m_per_rad");
  p.twistingStiffness = m.getDouble("twisting_stiffness_m_per_rad");
  p.relaxationLength = m.getNonNegative("relaxation_length_m");
  p.radialStiffness = m.getPositive("radial_stiffness_N_per_m");
  p.radialDamping = m.getNonNegative("radial_damping_Ns_per_m");
  p.longitudinalStiffness = m.getPositive("longitudinal_stiffness");
  m.finish();
  return p;
}

class LinearTyreForce : public SimTK::Force::Custom::Implementation {
 public:
  LinearTyreForce(SimTK::GeneralForceSubsystem& forces, const WheelSite& w, const LinearTyreParameters& p)
      : forces_(forces), wheel_(w.wheel), R_(w.radius), rho_(w.crownRadius), p_(p) {}

  void realizeTopology(State& s) const override {
    if (p_.relaxationLength > 0) zIndex_ = forces_.allocateZ(s, SimTK::Vector(1, 0.0));
  }

  void calcForce(const State& s, SimTK::Vector_<SpatialVec>& bodyForces, SimTK::Vector_<Vec3>&,
                 SimTK::Vector&) const override {
    const SimTK::Transform& X_GW = wheel_.getBodyTransform(s);
    const Vec3& w = wheel_.getBodyAngularVelocity(s);
    const Vec3& vC = wheel_.getBodyOriginVelocity(s);
    const TorusContact c = calcTorusContact(X_GW.R(), w, R_, rho_);
    const Vec3 n(0, 0, 1);
    const double deflection = -(X_GW.p()[2] + c.r_CP_G[2]);
    const double deflectionRate = -(vC[2] + c.rDot_CP_G[2]);
    const double Fz = deflection > 0 ? std::max(0.0, p_.radialStiffness * deflection + p_.radialDamping * deflectionRate) : 0.0;

    const Vec3 a = X_GW.R().y().asVec3();
    Vec3 eL = a % n;
    eL /= eL.norm();
    const Vec3 eT = n % eL;
    const Vec3 vP = vC + w % c.r_CP_G;
    const double vx = ~vC * eL;
    const double V = std::sqrt(vx * vx + kSlipSpeedFloor * kSlipSpeedFloor);
    const double kappa = -(~vP * eL) / V, alpha = -(~vP * eT) / V;
    const double phi = -std::asin(std::max(-1.0, std::min(1.0, ~a * n)));
    const double slipSteady = alpha + p_.camberStiffness / p_.corneringStiffness * phi;
    double slip = slipSteady;
    if (zIndex_.isValid()) {
      slip = forces_.getZ(s)[zIndex_];
      forces_.updZDot(s)[zIndex_] = V / p_.relaxationLength * (slipSteady - slip);
    }
    const double mu = p_.corneringStiffness * slip;
    const Vec3 F = Fz * (p_.longitudinalStiffness * kappa * eL + mu * eT) + Fz * n;
    // The slip part of the lagged state drives the self-aligning moment too (alpha lagged as Fy).
    const double alphaLagged = slip - p_.camberStiffness / p_.corneringStiffness * phi;
    const double Mz = Fz * (p_.selfAligningStiffness * alphaLagged + p_.twistingStiffness * phi);
    bodyForces[wheel_.getMobilizedBodyIndex()] += SpatialVec(c.r_CP_G % F + Mz * n, F);
  }

  // The lagged slip is the carcass's lateral deflection over the relaxation length (stretched
  // string): a road that moves by `offset` under the contact moves the patch with it.
  bool applyRoadStep(State& s, double offset) const {
    if (!zIndex_.isValid()) return false;
    forces_.updZ(s)[zIndex_] += offset / p_.relaxationLength;
    return true;
  }

  SimTK::Real calcPotentialEnergy(const State& s) const override {
    const SimTK::Transform& X_GW = wheel_.getBodyTransform(s);
    const double d = -(X_GW.p()[2] + calcTorusContact(X_GW.R(), Vec3(0), R_, rho_).r_CP_G[2]);
    return d > 0 ? 0.5 * p_.radialStiffness * d * d : 0.0;
  }

 private:
  SimTK::GeneralForceSubsystem& forces_;
  SimTK::MobilizedBody wheel_;
  double R_, rho_;
  LinearTyreParameters p_;
  mutable SimTK::ZIndex zIndex_;
};

class RelaxationLinear : public ContactModel {
 public:
  RelaxationLinear(const LinearTyreParameters& front, const LinearTyreParameters& rear) : front_(front), rear_(rear) {}
  void addWheel(BuildContext& ctx, const WheelSite& w) override {
    auto* force = new LinearTyreForce(ctx.forces, w, paramsFor(w));
    SimTK::Force::Custom(ctx.forces, force);  // the subsystem owns the force
    forces_[w.name] = force;
  }
  bool applyLateralRoadStep(SimTK::State& s, const WheelSite& w, double offset) const override {
    const auto it = forces_.find(w.name);
    return it != forces_.end() && it->second->applyRoadStep(s, offset);
  }
  std::vector<std::string> getStateNames(const WheelSite& w) const override {
    if (paramsFor(w).relaxationLength <= 0) return {};
    return {(w.name == "front_wheel" ? std::string("front") : std::string("rear")) + "_tyre_lagged_slip"};
  }

 private:
  const LinearTyreParameters& paramsFor(const WheelSite& w) const { return w.name == "front_wheel" ? front_ : rear_; }
  LinearTyreParameters front_, rear_;
  std::map<std::string, const LinearTyreForce*> forces_;
};

}  // namespace

void registerRelaxationLinear(PluginRegistry& registry) {
  registry.addContactModel("relaxation_linear", [](YamlMap& m) -> std::unique_ptr<ContactModel> {
    return std::make_unique<RelaxationLinear>(readTyre(m.getMap("front")), readTyre(m.getMap("rear")));
  });
}

}  // namespace motostab
