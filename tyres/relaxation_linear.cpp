#include "tyres/relaxation_linear.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "tyres/rolling_no_slip.h"

namespace motostab {

using SimTK::SpatialVec;
using SimTK::State;
using SimTK::Vec3;

namespace {

// One tyre's keys. With a preset every key is optional (given ones override the preset's value).
LinearTyreParameters readTyre(YamlMap m, const LinearTyreParameters* preset) {
  LinearTyreParameters p = preset ? *preset : LinearTyreParameters{};
  auto read = [&](const char* key, double& v, double (YamlMap::*get)(const std::string&)) {
    if (!preset || m.has(key)) v = (m.*get)(key);
  };
  read("cornering_stiffness_per_rad", p.corneringStiffness, &YamlMap::getPositive);
  read("camber_stiffness_per_rad", p.camberStiffness, &YamlMap::getDouble);
  read("self_aligning_stiffness_m_per_rad", p.selfAligningStiffness, &YamlMap::getDouble);
  read("twisting_stiffness_m_per_rad", p.twistingStiffness, &YamlMap::getDouble);
  read("relaxation_length_m", p.relaxationLength, &YamlMap::getNonNegative);
  read("radial_stiffness_N_per_m", p.radialStiffness, &YamlMap::getPositive);
  read("radial_damping_Ns_per_m", p.radialDamping, &YamlMap::getNonNegative);
  read("longitudinal_stiffness", p.longitudinalStiffness, &YamlMap::getPositive);
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

  // Contact quantities of a state realized to Velocity; the lagged slip's derivative beside them.
  struct Quantities {
    Vec3 r_CP, F_G;
    double Fx = 0, Fy = 0, Fz = 0, Mz = 0, alpha = 0, kappa = 0, camber = 0, slipDot = 0;
  };
  Quantities calcQuantities(const State& s) const {
    Quantities out;
    const SimTK::Transform& X_GW = wheel_.getBodyTransform(s);
    const Vec3& w = wheel_.getBodyAngularVelocity(s);
    const Vec3& vC = wheel_.getBodyOriginVelocity(s);
    const TorusContact c = calcTorusContact(X_GW.R(), w, R_, rho_);
    const Vec3 n(0, 0, 1);
    const double deflection = -(X_GW.p()[2] + c.r_CP_G[2]);
    const double deflectionRate = -(vC[2] + c.rDot_CP_G[2]);
    out.Fz = deflection > 0 ? std::max(0.0, p_.radialStiffness * deflection + p_.radialDamping * deflectionRate) : 0.0;

    const Vec3 a = X_GW.R().y().asVec3();
    Vec3 eL = a % n;
    eL /= eL.norm();
    const Vec3 eT = n % eL;
    const Vec3 vP = vC + w % c.r_CP_G;
    const double vx = ~vC * eL;
    const double V = std::sqrt(vx * vx + kSlipSpeedFloor * kSlipSpeedFloor);
    out.kappa = -(~vP * eL) / V;
    out.alpha = -(~vP * eT) / V;
    out.camber = -std::asin(std::max(-1.0, std::min(1.0, ~a * n)));
    const double slipSteady = out.alpha + p_.camberStiffness / p_.corneringStiffness * out.camber;
    double slip = slipSteady;
    if (zIndex_.isValid()) {
      slip = forces_.getZ(s)[zIndex_];
      out.slipDot = V / p_.relaxationLength * (slipSteady - slip);
    }
    // The slip part of the lagged state drives the self-aligning moment too (alpha lagged as Fy).
    const double alphaLagged = slip - p_.camberStiffness / p_.corneringStiffness * out.camber;
    out.Fx = out.Fz * p_.longitudinalStiffness * out.kappa;
    out.Fy = out.Fz * p_.corneringStiffness * slip;
    out.Mz = out.Fz * (p_.selfAligningStiffness * alphaLagged + p_.twistingStiffness * out.camber);
    out.r_CP = c.r_CP_G;
    out.F_G = out.Fx * eL + out.Fy * eT + out.Fz * n;
    return out;
  }

  void calcForce(const State& s, SimTK::Vector_<SpatialVec>& bodyForces, SimTK::Vector_<Vec3>&,
                 SimTK::Vector&) const override {
    const Quantities q = calcQuantities(s);
    if (zIndex_.isValid()) forces_.updZDot(s)[zIndex_] = q.slipDot;
    bodyForces[wheel_.getMobilizedBodyIndex()] += SpatialVec(q.r_CP % q.F_G + q.Mz * Vec3(0, 0, 1), q.F_G);
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
  std::vector<std::string> getOutputNames(const WheelSite& w) const override {
    const std::string t = w.name == "front_wheel" ? "front_tyre_" : "rear_tyre_";
    return {t + "Fx_N", t + "Fy_N", t + "Fz_N", t + "Mz_Nm", t + "slip_angle_rad", t + "slip_ratio", t + "camber_rad"};
  }
  std::vector<double> calcOutputs(const SimTK::State& s, const WheelSite& w) const override {
    const auto q = forces_.at(w.name)->calcQuantities(s);
    return {q.Fx, q.Fy, q.Fz, q.Mz, q.alpha, q.kappa, q.camber};
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

LinearTyreParameters getRelaxationLinearPreset(const std::string& name) {
  if (name != "bicycle") throw std::invalid_argument("unknown relaxation_linear preset '" + name + "'");
  // docs/scenario-format.md, "Bicycle tyre preset", gives each value's source.
  LinearTyreParameters p;
  p.corneringStiffness = 15.0;      // Dressel (2013): 0.15-0.35 /deg normalised, mean about 0.25 /deg
  p.camberStiffness = 0.9;          // Dell'Orto et al. (2024): 0.63-0.94 /rad; Dressel (2013) 0.43-0.86 /rad
  p.selfAligningStiffness = -0.24;  // pneumatic trail about 16 mm times k_alpha (Dell'Orto et al. 2024)
  p.twistingStiffness = 0.012;      // estimate, no published bicycle value found (see docs)
  p.relaxationLength = 0.1;         // Hjort & Niska (2018): earlier study about 0.1 m, their estimate 0.2-0.3 m
  p.radialStiffness = 1.0e5;        // Rothhaemel (2023): 31-147 N/mm, set by the inflation pressure
  p.radialDamping = 100;            // estimate (the linear modes barely depend on it)
  p.longitudinalStiffness = 20;     // estimate, motorcycle order (Cossalter 2006 ch. 2)
  return p;
}

std::vector<std::string> getRelaxationLinearPresetNames() { return {"bicycle"}; }

void registerRelaxationLinear(PluginRegistrar& registry) {
  registry.addContactModel("relaxation_linear", [](YamlMap& m) -> std::unique_ptr<ContactModel> {
    if (!m.has("preset")) return std::make_unique<RelaxationLinear>(readTyre(m.getMap("front"), nullptr), readTyre(m.getMap("rear"), nullptr));
    const std::string name = m.getString("preset");
    const auto names = getRelaxationLinearPresetNames();
    if (std::find(names.begin(), names.end(), name) == names.end()) m.fail("preset", "unknown preset '" + name + "' (known: bicycle)");
    const LinearTyreParameters preset = getRelaxationLinearPreset(name);
    auto side = [&](const char* key) {
      if (!m.has(key)) return preset;
      return readTyre(m.getMap(key), &preset);
    };
    return std::make_unique<RelaxationLinear>(side("front"), side("rear"));
  });
}

}  // namespace motostab
