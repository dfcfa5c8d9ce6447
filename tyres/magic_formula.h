#pragma once
// Magic Formula steady-state tyre force laws: the common interface (TyreForceLaw), where their
// coefficients come from (tyres/coefficient_source.h), and MF 6.1/6.2 (Pacejka 2012,
// "Tire and Vehicle Dynamics", 3rd ed., sec. 4.3.2, eqs. 4.E1-4.E78, without turn slip). The
// motorcycle variant is in tyres/motorcycle_magic_formula.h. docs/tyres.md lists every equation.
//
// Axes and signs are Pacejka's ISO-W ones: x forward in the ground plane, y left, z up; slip ratio
// kappa = -V_sx/|V_cx|; slip angle alpha with tan(alpha) = V_cy/|V_cx| (a wheel sliding left has
// alpha > 0, and Fy = K_ya alpha with K_ya < 0); camber (inclination) gamma > 0 when the wheel's
// top leans right (towards -y). Forces in N, moments in N m about x, y, z at the contact point.
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tyres/coefficient_source.h"
#include "tyres/tir_file.h"

namespace motostab::tyres {

/// Operating point of a tyre (ISO-W signs, above).
struct TyreSlip {
  double Fz = 0;     ///< normal load, N (>= 0)
  double kappa = 0;  ///< longitudinal slip ratio
  double alpha = 0;  ///< slip angle, rad
  double gamma = 0;  ///< camber (inclination) angle, rad
  double Vx = 0;     ///< forward speed of the wheel centre, m/s (rolling resistance)
};

/// Steady-state forces and moments at the contact point (ISO-W axes).
struct TyreForces {
  double Fx = 0, Fy = 0, Mx = 0, My = 0, Mz = 0;
};

/// A steady-state tyre force law with its small-slip stiffnesses in closed form.
class TyreForceLaw {
 public:
  virtual ~TyreForceLaw() = default;
  virtual TyreForces calcForces(const TyreSlip& slip) const = 0;
  /// dFy/dalpha at kappa = alpha = gamma = 0 (N/rad, ISO sign: negative for a usual tyre).
  virtual double calcCorneringStiffness(double Fz) const = 0;
  /// dFy/dgamma at kappa = alpha = gamma = 0 (N/rad, ISO sign).
  virtual double calcCamberStiffness(double Fz) const = 0;
  /// dFx/dkappa at kappa = alpha = gamma = 0 (N).
  virtual double calcLongitudinalStiffness(double Fz) const = 0;
  /// Lateral relaxation length (m) at load Fz (N), camber gamma (rad) and forward speed Vx (m/s); NaN
  /// if the law has none.
  virtual double calcRelaxationLength(double Fz, double gamma, double Vx) const = 0;
  /// Longitudinal relaxation length (m) at load Fz (N); NaN if the law has none. Reported only (the
  /// contact does not lag the slip ratio).
  virtual double calcLongitudinalRelaxationLength(double) const { return std::numeric_limits<double>::quiet_NaN(); }
  /// Nominal load F_z0' (N) and unloaded radius R0 (m).
  virtual double getNominalLoad() const = 0;
  virtual double getUnloadedRadius() const = 0;
  /// Crown (cross-section) radius the law's moments use (m); NaN if the law uses none.
  virtual double getCrownRadius() const { return std::numeric_limits<double>::quiet_NaN(); }
  /// The speed of the measurements the coefficients were fitted at (MF 6.x LONGVL, m/s); NaN if none.
  virtual double getReferenceSpeed() const { return std::numeric_limits<double>::quiet_NaN(); }
};

/// The Magic Formula variants.
enum class MagicFormulaVariant { MF61, MF62, Motorcycle };
/// "mf61", "mf62", "motorcycle"; nothing for other names.
std::optional<MagicFormulaVariant> parseMagicFormulaVariant(const std::string& name);
/// The scaling factors (L...) a variant's equations use.
const std::vector<std::string>& getScalingNames(MagicFormulaVariant v);
/// Why a scaling factor's value is refused ("" if it is not): every factor is finite and >= 0 (0 turns
/// its term off), and those that divide or set a slope or a friction level are > 0 (LFZO, LMUX, LMUY,
/// LCX, LCY, LKX, LKY, LSGAL, LSGKP). docs/tyres.md, "What is refused".
std::string findScalingProblem(const std::string& name, double value);

/// How the motorcycle variant reads the equations of Sharp, Evangelou & Limebeer (2004), which are
/// written with a slip `a` and a camber `g` that both push the tyre to +y (docs/tyres.md, "The
/// motorcycle conventions"). The law is odd in (a, g) jointly except for the combined-slip factor's
/// RBY3 shift, so the axes decide only on which side of zero slip that term acts.
enum class MotorcyclePaperAxes {
  ZDown,  ///< y right, z down: a = alpha_ISO, g = gamma_ISO, and Fy, Mz change sign (MBSim, TUMFTM)
  ZUp     ///< y left, z up: a = -alpha_ISO, g = -gamma_ISO, forces as they are
};
/// The slip variable of the motorcycle equations: the slip angle in rad (MBSim, TUMFTM) or its tangent
/// (as MF 6.x); cos(alpha) is 1/sqrt(1 + a^2) in both.
enum class MotorcycleSlipVariable { Angle, Tangent };
struct MotorcycleConventions {
  MotorcyclePaperAxes axes = MotorcyclePaperAxes::ZDown;
  MotorcycleSlipVariable slip = MotorcycleSlipVariable::Angle;
};
/// "z_down", "z_up" / "angle", "tangent"; nothing for other names.
std::optional<MotorcyclePaperAxes> parseMotorcyclePaperAxes(const std::string& name);
std::optional<MotorcycleSlipVariable> parseMotorcycleSlipVariable(const std::string& name);

/// Reads the coefficients a variant needs from `source` (InputError for a missing one or a value of the
/// wrong sign, at the coefficient) and builds the force law; then checks it over its input range
/// (findForceLawProblem) and refuses a law that is not finite or is degenerate there (InputError at the
/// coefficient set). Inflation pressure (Pa): `pressure` if given, else INFLPRES, else NOMPRES.
std::unique_ptr<TyreForceLaw> makeTyreForceLaw(MagicFormulaVariant v, const CoefficientSource& source,
                                               std::optional<double> pressure = std::nullopt,
                                               const MotorcycleConventions& motorcycle = {});

/// The input range over which makeTyreForceLaw checks a law (docs/tyres.md, "What is refused"): loads
/// 0 to kCheckedLoadFactor FNOMIN, slip angles to +/-89 degrees, camber to +/-60 degrees, slip ratios
/// -1 to 1, speeds 0 to 60 m/s.
constexpr double kCheckedLoadFactor = 3;
/// The shortest relaxation length, m (a tenth of a millimetre; bicycle and motorcycle tyres have
/// 0.01-0.3 m): a tyre's relaxation_length_m is 0 (no lag) or at least this, and a law's own length is
/// at least this. The relaxation root -V/sigma of a shorter one swamps every other root.
constexpr double kMinRelaxationLength = 1e-4;
/// Why a Magic Formula law cannot be used ("" if it can), checked on a coarse grid of that range: a
/// force or moment that is not finite; a cornering stiffness that does not push against the slip or a
/// slip stiffness that is not positive at a positive load; a side force or a longitudinal force that
/// does not oppose a 5 degree slip angle or a 0.1 slip ratio at zero camber; an own relaxation length
/// (if the law has one) that is not finite and at least kMinRelaxationLength from 5 % of FNOMIN up.
std::string findForceLawProblem(const TyreForceLaw& law);

}  // namespace motostab::tyres
