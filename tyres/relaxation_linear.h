#pragma once
// Tyre plugin `relaxation_linear`: a toroidal tyre on flat ground with linear force laws per unit
// load and a first-order relaxation of the lateral force (seed sec. 4, Table 6).
//
// Contact point, normal load, slips, camber and relaxation are the shared ones of tyres/tyre_contact.h.
//   lateral force   Fy = Fz k_alpha s,  sigma/V s' + s = alpha + (k_phi/k_alpha) phi, so Fy lags
//                   Fz (k_alpha alpha + k_phi phi); the z state s is the lagged equivalent slip angle (rad)
//   longitudinal    Fx = Fz k_kappa kappa
//   moments         Mz = Fz (k_mz alpha_l + k_mt phi) about n at P (self-aligning and twisting; alpha_l
//                   the lagged slip angle)
// With Table 6's signs (k_mz < 0, k_mt > 0) the self-aligning moment turns the wheel towards its
// velocity and the twisting moment towards the lean, as in Cossalter (2006) ch. 2. A relaxation
// length of 0 means no lag and no state.
//
// The relaxation length is a constant sigma, or the carcass's: sigma = C_Fa / k_y(V) with the cornering
// stiffness C_Fa = Fz k_alpha (N/rad) at the instantaneous load and the lateral carcass stiffness k_y
// (N/m) of the stretched-string model (Pacejka 2012 sec. 7.2), whose compliance grows with the forward
// speed V as in Sharp, Evangelou & Limebeer (2004) sec. 4 (Evangelou 2004 Table 9.5):
//   1/k_y(V) = (1 + b1 V + b2 V^2) / k_y0.
#include <memory>
#include <string>
#include <utility>

#include "plugins/plugin_api.h"
#include "tyres/magic_formula.h"
#include "tyres/tyre_contact.h"

namespace motostab::tyres {

/// Per-tyre parameters (per unit load where stated).
struct LinearTyreParameters {
  double corneringStiffness = 0;    ///< k_alpha, 1/rad
  double camberStiffness = 0;       ///< k_phi, 1/rad
  double selfAligningStiffness = 0; ///< k_mz, m/rad
  double twistingStiffness = 0;     ///< k_mt, m/rad
  double relaxationLength = 0;      ///< sigma, m (constant; 0 when lateralCarcassStiffness gives it)
  double radialStiffness = 0;       ///< k_r, N/m
  double radialDamping = 0;         ///< c_r, N s/m
  double longitudinalStiffness = 0; ///< k_kappa, per unit load
  double lateralCarcassStiffness = 0;  ///< k_y0, N/m, at standstill; 0: the constant relaxationLength
  double carcassSpeedCoefficient = 0;  ///< b1, s/m, of the lateral compliance 1/k_y (header)
  double carcassSpeedCoefficient2 = 0; ///< b2, s^2/m^2, of the lateral compliance 1/k_y (header)
  io::InputLocation carcassWhere;      ///< the stiffness key, for errors found when the wheel's load is known
};

/// Whether the tyre's side force relaxes (a relaxation length or a lateral carcass stiffness).
bool isLagged(const LinearTyreParameters& p);

/// The carcass compliance factor k_y0/k_y(V) = 1 + b1 V + b2 V^2 (header), V = |speed| (m/s) taken at
/// most scenario::SpeedRange::kMaxSpeed, the range over which the reader checks it positive.
double calcCarcassComplianceFactor(const LinearTyreParameters& p, double speed);

/// Relaxation length (m) at normal load Fz (N) and forward speed (m/s): the constant relaxationLength,
/// or with a carcass stiffness sigma = Fz k_alpha (1 + b1 V + b2 V^2) / k_y0 (header).
double calcRelaxationLength(const LinearTyreParameters& p, double Fz, double speed);

/// One tyre as a YAML flow map of the keys readRelaxationLinearTyres reads (17 significant digits:
/// read back it gives the same parameters).
std::string formatLinearTyre(const LinearTyreParameters& p);

/// A named parameter set for both tyres (per unit load where stated). `bicycle`: measured bicycle
/// tyres (Dressel & Rahman 2012, Dressel 2013, VTI 2020; docs/scenario-format.md). Unknown names throw
/// std::logic_error.
LinearTyreParameters getRelaxationLinearPreset(const std::string& name);
std::vector<std::string> getRelaxationLinearPresetNames();

/// Reads a `relaxation_linear` contact section (`model` already read): the front and rear tyres,
/// under `front` and `rear`, or `preset: NAME` with optional `front`/`rear` maps whose keys override
/// the preset's values. Refused (InputError at the key): a cornering, longitudinal or radial stiffness
/// that is not positive, a negative camber stiffness (camber thrust pushes towards the lean), a positive
/// self-aligning stiffness (a negative pneumatic trail), a negative relaxation length or damping;
/// both or neither of relaxation_length_m and lateral_carcass_stiffness_N_per_m (over a preset, the
/// one given replaces the preset's); carcass speed coefficients without a carcass stiffness, or that make
/// 1 + b1 V + b2 V^2 zero or negative at a speed from 0 to scenario::SpeedRange::kMaxSpeed.
std::pair<LinearTyreParameters, LinearTyreParameters> readRelaxationLinearTyres(io::YamlMap& contact);

/// The header's force law in steady state (no lag), in the ISO-W signs of tyres/magic_formula.h, for
/// `motostab tyre`: Fx = Fz k_kappa kappa, Fy = Fz (k_alpha a + k_phi phi), Mz = Fz (k_mz a + k_mt phi),
/// Mx = My = 0, with a = -tan(alpha_ISO) and phi = -gamma_ISO. Its relaxation length is
/// calcRelaxationLength's; it has no nominal load and no radius of its own (NaN).
std::unique_ptr<TyreForceLaw> makeLinearTyreForceLaw(const LinearTyreParameters& p);

/// The `relaxation_linear` contact model of two typed tyres, apart from the scenario reader (whose
/// factory builds it from readRelaxationLinearTyres): the values are not checked again, so give ones
/// the reader accepts.
std::unique_ptr<plugins::ContactModel> makeRelaxationLinear(const LinearTyreParameters& front,
                                                            const LinearTyreParameters& rear);

/// Registers `relaxation_linear` (readRelaxationLinearTyres).
void registerRelaxationLinear(plugins::PluginRegistrar& registry);

/// The declared keys of `contact` (model, preset, front, rear), `contact.front` and `contact.rear` (one
/// tyre each), for `contact.model: relaxation_linear`.
const std::vector<io::SectionFields>& getRelaxationLinearFields();

}  // namespace motostab::tyres
