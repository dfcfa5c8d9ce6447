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
#include "plugins/plugin_api.h"
#include "tyres/tyre_contact.h"

namespace motostab::tyres {

/// Per-tyre parameters (per unit load where stated).
struct LinearTyreParameters {
  double corneringStiffness = 0;    ///< k_alpha, 1/rad
  double camberStiffness = 0;       ///< k_phi, 1/rad
  double selfAligningStiffness = 0; ///< k_mz, m/rad
  double twistingStiffness = 0;     ///< k_mt, m/rad
  double relaxationLength = 0;      ///< sigma, m
  double radialStiffness = 0;       ///< k_r, N/m
  double radialDamping = 0;         ///< c_r, N s/m
  double longitudinalStiffness = 0; ///< k_kappa, per unit load
};

/// A named parameter set for both tyres (per unit load where stated). `bicycle`: measured bicycle
/// tyres (Dressel & Rahman 2012, Dressel 2013, VTI 2020; docs/scenario-format.md). Unknown names throw
/// std::logic_error.
LinearTyreParameters getRelaxationLinearPreset(const std::string& name);
std::vector<std::string> getRelaxationLinearPresetNames();

/// Registers `relaxation_linear` (parameters under `front` and `rear`, or `preset: NAME` with
/// optional `front`/`rear` maps whose keys override the preset's values).
void registerRelaxationLinear(plugins::PluginRegistrar& registry);

}  // namespace motostab::tyres
