#include "tyres/tyre_contact.h"

#include <algorithm>
#include <cmath>


namespace motostab::tyres {

using plugins::BuildContext;
using plugins::ContactPoint;
using plugins::calcTorusContact;
using plugins::WheelSite;


using SimTK::SpatialVec;
using SimTK::State;
using SimTK::Vec3;

TyreKinematics calcTyreKinematics(const State& s, const SimTK::MobilizedBody& wheel, double R, double rho,
                                  const RadialLaw& radial) {
  TyreKinematics k;
  const SimTK::Transform& X_GW = wheel.getBodyTransform(s);
  const Vec3& w = wheel.getBodyAngularVelocity(s);
  const Vec3& vC = wheel.getBodyOriginVelocity(s);
  const ContactPoint c = calcTorusContact(X_GW.R(), w, R, rho);
  const Vec3 n(0, 0, 1);
  const double deflection = -(X_GW.p()[2] + c.r_CP_G[2]);
  const double deflectionRate = -(vC[2] + c.rDot_CP_G[2]);
  k.Fz = deflection > 0 ? std::max(0.0, radial.stiffness * deflection + radial.damping * deflectionRate) : 0.0;

  const Vec3 a = X_GW.R().y().asVec3();
  k.e_l = a % n;
  k.e_l /= k.e_l.norm();
  k.e_t = n % k.e_l;
  const Vec3 vP = vC + w % c.r_CP_G;
  k.forwardSpeed = ~vC * k.e_l;
  k.V = std::sqrt(k.forwardSpeed * k.forwardSpeed + kSlipSpeedFloor * kSlipSpeedFloor);
  k.kappa = -(~vP * k.e_l) / k.V;
  k.alpha = -(~vP * k.e_t) / k.V;
  k.camber = -std::asin(std::max(-1.0, std::min(1.0, ~a * n)));
  k.r_CP_G = c.r_CP_G;
  return k;
}

LaggedSlip calcLaggedSlip(double steadySlip, double alpha, bool lagged, double z, double V, double sigma) {
  LaggedSlip out;
  out.slip = steadySlip;
  if (lagged) {
    out.slip = z;
    out.slipDot = V / sigma * (steadySlip - z);
  }
  out.alphaLagged = alpha + (out.slip - steadySlip);
  return out;
}

TyreForceElement::TyreForceElement(SimTK::GeneralForceSubsystem& forces, const WheelSite& w, const RadialLaw& radial,
                                   bool lagged)
    : forces_(forces), wheel_(w.wheel), R_(w.radius), rho_(w.crownRadius), radial_(radial), lagged_(lagged) {}

void TyreForceElement::realizeTopology(State& s) const {
  if (lagged_) zIndex_ = forces_.allocateZ(s, SimTK::Vector(1, 0.0));
}

TyreForceElement::Quantities TyreForceElement::calcQuantities(const State& s) const {
  Quantities q;
  q.kin = calcTyreKinematics(s, wheel_, R_, rho_, radial_);
  const double z = zIndex_.isValid() ? forces_.getZ(s)[zIndex_] : 0.0;
  q.f = calcTyreForces(q.kin, z, q.slipDot);
  q.f.Fz = q.kin.Fz;
  return q;
}

void TyreForceElement::calcForce(const State& s, SimTK::Vector_<SpatialVec>& bodyForces, SimTK::Vector_<Vec3>&,
                                 SimTK::Vector&) const {
  const Quantities q = calcQuantities(s);
  if (zIndex_.isValid()) forces_.updZDot(s)[zIndex_] = q.slipDot;
  const Vec3 n(0, 0, 1);
  const Vec3 F_G = q.f.Fx * q.kin.e_l + q.f.Fy * q.kin.e_t + q.f.Fz * n;
  const Vec3 M_G = q.f.Mx * q.kin.e_l + q.f.My * q.kin.e_t + q.f.Mz * n;
  bodyForces[wheel_.getMobilizedBodyIndex()] += SpatialVec(q.kin.r_CP_G % F_G + M_G, F_G);
}

bool TyreForceElement::applyRoadStep(State& s, double offset) const {
  if (!zIndex_.isValid()) return false;
  wheel_.getMatterSubsystem().getSystem().realize(s, SimTK::Stage::Velocity);  // the load sets sigma
  const double sigma = calcRelaxationLength(calcTyreKinematics(s, wheel_, R_, rho_, radial_));
  forces_.updZ(s)[zIndex_] += offset / sigma;
  return true;
}

SimTK::Real TyreForceElement::calcPotentialEnergy(const State& s) const {
  const SimTK::Transform& X_GW = wheel_.getBodyTransform(s);
  const double d = -(X_GW.p()[2] + calcTorusContact(X_GW.R(), Vec3(0), R_, rho_).r_CP_G[2]);
  return d > 0 ? 0.5 * radial_.stiffness * d * d : 0.0;
}

namespace {
std::string tyrePrefix(const WheelSite& w) { return w.side == plugins::WheelSide::Front ? "front_tyre_" : "rear_tyre_"; }
}  // namespace

void TyreContactModel::addWheel(BuildContext& ctx, const WheelSite& w) {
  TyreForceElement* force = makeForceElement(ctx, w);
  SimTK::Force::Custom(ctx.forces, force);  // the subsystem owns the force
  forces_[w.name] = force;
}

std::vector<std::string> TyreContactModel::getOutputNames(const WheelSite& w) const {
  const std::string t = tyrePrefix(w);
  std::vector<std::string> names{t + "Fx_N",           t + "Fy_N",       t + "Fz_N",     t + "Mz_Nm",
                                 t + "slip_angle_rad", t + "slip_ratio", t + "camber_rad"};
  if (reportsMoments_) {
    names.push_back(t + "Mx_Nm");
    names.push_back(t + "My_Nm");
  }
  return names;
}

std::vector<double> TyreContactModel::calcOutputs(const State& s, const WheelSite& w) const {
  const auto q = forces_.at(w.name)->calcQuantities(s);
  std::vector<double> out{q.f.Fx, q.f.Fy, q.f.Fz, q.f.Mz, q.kin.alpha, q.kin.kappa, q.kin.camber};
  if (reportsMoments_) {
    out.push_back(q.f.Mx);
    out.push_back(q.f.My);
  }
  return out;
}

bool TyreContactModel::applyLateralRoadStep(State& s, const WheelSite& w, double offset) const {
  const auto it = forces_.find(w.name);
  return it != forces_.end() && it->second->applyRoadStep(s, offset);
}

std::vector<plugins::AuxiliaryState> TyreContactModel::getStates(const WheelSite& w) const {
  if (!isLagged(w)) return {};
  return {{tyrePrefix(w) + "lagged_slip", plugins::StateRole::TyreLag, w.side}};
}

}  // namespace motostab::tyres
