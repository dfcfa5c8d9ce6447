#pragma once
// Decomposition of the twist stiffness into bending and torsion (seed eq. 5-17) and lumped damping
// (seed eq. 18-25), with first-order uncertainty propagation; the swingarm.yaml fragment.
#include <filesystem>
#include <string>

#include "swingarm/identification/hammer_frf.h"
#include "swingarm/identification/static_laser.h"

namespace motostab::swingarm::identification {

/// Bending and torsion stiffness from seed eq. 7 and 10, Nm/rad. Unknowns u_b = a_b/k_b, u_t = a_t/k_t:
///   a_b u_b + a_t u_t = a_tw^2 / k_tw                        (eq. 7)
///   u_b sin(beta_b - beta) + u_t sin(beta_t - beta) = 0     (eq. 10, cross-multiplied)
/// Arms in m, angles in deg. Throws io::ResultError (measured axes without a result) if the system is singular or gives k <= 0.
struct BendingTorsionStiffness {
  double kB = 0, kT = 0;
};
BendingTorsionStiffness calcBendingTorsionStiffness(double aTw, double kTw, double betaDeg, double aB,
                                                    double betaBDeg, double aT, double betaTDeg);

/// Stiffness reduced to the twist axis, seed eq. 11-15: k' = (a_tw / a)^2 k.
double calcReducedStiffness(double k, double arm, double aTw);

/// Series combination, seed eq. 16-17: k_tw = 1 / (1/k'_b + 1/k'_t).
double calcSeriesStiffness(double kReducedB, double kReducedT);

/// Damping of a 1-DOF mode, seed eq. 20: c = k zeta / (pi f), Nms/rad (zeta viscous; f Hz; k Nm/rad).
double calcModalDamping(double k, double zeta, double frequencyHz);

/// Twist-axis damping by energy equivalence, seed eq. 25:
///   c_tw = c_b (a_b k_tw / (k_b a_tw))^2 + c_t (a_t k_tw / (k_t a_tw))^2.
double calcTwistDamping(double cB, double cT, double aB, double kB, double aT, double kT, double aTw, double kTw);

/// A value with its standard error.
struct Estimate {
  double value = 0, stderr_ = 0;
};

/// One lumped model (bending, torsion or twist) as written to swingarm.yaml.
struct LumpedModel {
  Estimate arm, betaDeg;               ///< m, deg
  Eigen::Vector2d point = Eigen::Vector2d::Zero(), direction = Eigen::Vector2d::UnitX();  ///< (x, z)
  Estimate stiffness, damping;         ///< Nm/rad, Nms/rad
  Estimate reducedStiffness;           ///< about the twist axis (eq. 14-15), Nm/rad
  Estimate frequencyHz, dampingRatio;  ///< modal values (bending, torsion)
};

/// The whole chain's result.
struct SwingarmIdentification {
  LumpedModel bending, torsion, twist;
  double eq17RelativeResidual = 0;   ///< (1/k_tw - 1/k'_b - 1/k'_t) * k_tw, dimensionless
  double eq8RelativeResidual = 0;    ///< |theta_tw e - theta_b e_b - theta_t e_t| / theta_tw (consistency)
};

/// Decomposes the static result with the bending and torsion modes of the FRF result (seed eq. 7, 10,
/// 14-15, 20, 25). Inputs are treated as independent for the uncertainty (k_lat, a_tw, beta; f, zeta,
/// arm, beta of each mode). Throws std::runtime_error if a bending or torsion mode axis is missing.
SwingarmIdentification identifySwingarm(const StaticResult& stat, const FrfResult& frf);

/// The swingarm.yaml fragment (schema in docs/swingarm-identification.md).
std::string formatSwingarmYaml(const SwingarmIdentification& id, const std::string& staticFile,
                               const std::string& frfFile, const PlatePoint& forcePoint);

}  // namespace motostab::swingarm::identification
