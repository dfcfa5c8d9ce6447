#pragma once
// What every slipping tyre plugin shares (relaxation_linear, magic_formula): the contact point on
// the toroidal carcass, the normal load, the slips and camber, the first-order relaxation of the
// lateral force (one z state per tyre, the lagged equivalent slip angle), and how the contact
// forces are applied to the wheel and reported. A plugin supplies only its force law.
//
// Conventions (ground z up; wheel spin axis a = wheel body y; e_l = a x n forward, e_t = n x e_l):
//   contact point   P = C + r_CP (calcTorusContact: the point moves round the carcass with camber)
//   normal load     Fz = max(0, k_r d + c_r d'),  d = -P_z the carcass deflection
//   slip            kappa = -(v_P . e_l)/V,  alpha = -(v_P . e_t)/V,  V = sqrt((v_C . e_l)^2 + v_eps^2)
//   camber          phi = -asin(a . n)         (a wheel leaning right has phi < 0)
//   relaxation      sigma/V s' + s = s_ss,  s_ss the steady equivalent slip (rad) of the force law;
//                   the lagged slip angle is alpha_l = alpha + (s - s_ss) (the part of the lag that
//                   belongs to the side slip, so that s = alpha_l + camber part, as in the
//                   stretched-string model, Pacejka 2012 sec. 7.2)
// Forces act at P along (e_l, e_t, n) and moments about (e_l, e_t, n): Fx, Fy, Fz, Mx, My, Mz.
// In these axes the slips are those of Pacejka's ISO-W axes except for the signs of the slip angle
// and the camber: alpha_ISO = -alpha, gamma_ISO = -phi (docs/tyres.md).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "plugins/plugin_api.h"

namespace motostab::tyres {

/// Slip regularisation speed v_eps (m/s): keeps slips finite at standstill.
constexpr double kSlipSpeedFloor = 0.1;

/// Contact kinematics of one wheel in a state realized to Velocity.
struct TyreKinematics {
  SimTK::Vec3 r_CP_G;       ///< wheel centre to contact point, ground frame, m
  SimTK::Vec3 e_l, e_t;     ///< contact axes: forward and left in the ground plane (unit)
  double Fz = 0;            ///< normal load, N
  double alpha = 0;         ///< slip angle, rad (project sign, see above)
  double kappa = 0;         ///< longitudinal slip ratio
  double camber = 0;        ///< camber angle phi, rad (project sign)
  double V = 0;             ///< regularised forward speed of the wheel centre, m/s
  double forwardSpeed = 0;  ///< v_C . e_l, m/s
};

/// Radial (vertical) carcass law: stiffness (N/m) and damping (N s/m).
struct RadialLaw {
  double stiffness = 0;
  double damping = 0;
};

/// Contact kinematics (header equations) of a wheel of outer radius R and crown radius rho (m).
TyreKinematics calcTyreKinematics(const SimTK::State& s, const SimTK::MobilizedBody& wheel, double R, double rho,
                                  const RadialLaw& radial);

/// The relaxation of the lateral slip: with a relaxation length sigma > 0 (m) the lagged slip is the
/// state `z` and its rate V/sigma (s_ss - z); with sigma = 0 it is s_ss itself, rate 0.
struct LaggedSlip {
  double slip = 0;          ///< lagged equivalent slip s, rad
  double slipDot = 0;       ///< ds/dt, rad/s
  double alphaLagged = 0;   ///< lagged slip angle alpha + (s - s_ss), rad
};
LaggedSlip calcLaggedSlip(double steadySlip, double alpha, bool lagged, double z, double V, double sigma);

/// Forces (N) and moments (N m) on the wheel at the contact point, contact axes (header).
struct TyreContactForces {
  double Fx = 0, Fy = 0, Fz = 0, Mx = 0, My = 0, Mz = 0;
};

/// A tyre force element: owns the lagged-slip z state (when the tyre relaxes) and applies the force
/// law a plugin defines in calcTyreForces.
class TyreForceElement : public SimTK::Force::Custom::Implementation {
 public:
  TyreForceElement(SimTK::GeneralForceSubsystem& forces, const plugins::WheelSite& w, const RadialLaw& radial, bool lagged);

  /// Everything a state realized to Velocity gives: kinematics, forces, and the lagged slip's rate.
  struct Quantities {
    TyreKinematics kin;
    TyreContactForces f;
    double slipDot = 0;
  };
  Quantities calcQuantities(const SimTK::State& s) const;

  void realizeTopology(SimTK::State& s) const override;
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector&) const override;
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;

  /// The lagged slip is the carcass's lateral deflection over the relaxation length (stretched
  /// string): a road that moves by `offset` (m) under the contact moves the patch with it.
  bool applyRoadStep(SimTK::State& s, double offset) const;

 protected:
  /// The force law: contact forces from the kinematics and the lagged slip state z (unused when the
  /// tyre does not relax), and the lagged slip's rate.
  virtual TyreContactForces calcTyreForces(const TyreKinematics& kin, double z, double& slipDot) const = 0;
  /// Lateral relaxation length (m) at the contact's load and camber.
  virtual double calcRelaxationLength(const TyreKinematics& kin) const = 0;

 private:
  SimTK::GeneralForceSubsystem& forces_;
  SimTK::MobilizedBody wheel_;
  double R_, rho_;
  RadialLaw radial_;
  bool lagged_;
  mutable SimTK::ZIndex zIndex_;
};

/// The ContactModel side shared by the tyre plugins: one force element per wheel, its z state (name
/// and role), the road step, and the outputs front_tyre_Fx_N ... (extended by Mx, My when
/// `reportsMoments`).
class TyreContactModel : public plugins::ContactModel {
 public:
  explicit TyreContactModel(bool reportsMoments) : reportsMoments_(reportsMoments) {}
  void addWheel(plugins::BuildContext& ctx, const plugins::WheelSite& w) override;
  std::vector<std::string> getOutputNames(const plugins::WheelSite& w) const override;
  std::vector<double> calcOutputs(const SimTK::State& s, const plugins::WheelSite& w) const override;
  bool applyLateralRoadStep(SimTK::State& s, const plugins::WheelSite& w, double offset) const override;
  std::vector<plugins::AuxiliaryState> getStates(const plugins::WheelSite& w) const override;

 protected:
  /// A new force element for a wheel (the subsystem takes ownership).
  virtual TyreForceElement* makeForceElement(plugins::BuildContext& ctx, const plugins::WheelSite& w) const = 0;
  /// Whether the wheel's tyre relaxes (has a lagged-slip state).
  virtual bool isLagged(const plugins::WheelSite& w) const = 0;

 private:
  bool reportsMoments_;
  std::map<std::string, const TyreForceElement*> forces_;
};

}  // namespace motostab::tyres
