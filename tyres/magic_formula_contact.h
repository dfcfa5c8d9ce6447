#pragma once
// Contact plugin `magic_formula`: Magic Formula tyres (MF 6.1/6.2 from a .tir file, or the
// motorcycle variant, tyres/motorcycle_magic_formula.h) on the shared tyre contact of
// tyres/tyre_contact.h: contact point on the toroidal carcass, radial load law, slips, and the
// first-order relaxation of the side force.
//
// With s the lagged equivalent slip (the z state, rad) and C(Fz) = -K_ya(Fz) > 0 the law's
// cornering stiffness at zero camber (N/rad):
//   steady equivalent slip  s_ss = Fy_MF(kappa, alpha, phi, Fz)/C(Fz)   (alpha for a linear law plus
//                           its camber part, as relaxation_linear's alpha + (k_phi/k_alpha) phi)
//   relaxation              sigma/V s' + s = s_ss, sigma from the scenario or the law (MF 6.1: PTY1,
//                           PTY2 at the current load and camber)
//   side force              Fy = C(Fz) s
// In s_ss and sigma the load is floored at 5% of FNOMIN (finite rates when a wheel unloads; below
// that load the steady side force is C(Fz)/C(floor) of the law's, and it vanishes with the load).
//   Fx, Mz, Mx, My          the law at the lagged slip angle alpha_l = alpha + (s - s_ss)
// In straight running (zero slips and camber) this linearises to relaxation_linear with
// k_alpha = C/Fz, k_phi = dFy/dphi /Fz, k_mz = dMz/dalpha /Fz, k_mt = dMz/dphi /Fz and
// k_kappa = K_xk/Fz at the trim load, provided the law has no force or moment at zero slip
// (no shifts, no rolling resistance, no Mz from Fx): tests/tyres/magic_formula_contact_test.cpp.
//
// Scenario (per tyre, `front` and `rear`):
//   tir: FILE | coefficients: {NAME: value, ...}   the coefficients (names of the .tir keys)
//   variant: mf61 | mf62 | motorcycle              default: the file's FITTYP (required inline)
//   scaling: {LKY: 1.1, ...}                       scaling factors overriding the file's (default 1)
//   relaxation_length_m                            optional for MF 6.x (0: no lag), required for motorcycle
//   radial_stiffness_N_per_m, radial_damping_Ns_per_m   default VERTICAL_STIFFNESS, VERTICAL_DAMPING
//   pressure_Pa                                    default INFLPRES, else NOMPRES (MF 6.x)
#include "plugins/plugin_api.h"

namespace motostab {

/// Registers `magic_formula`.
void registerMagicFormula(PluginRegistrar& registry);

}  // namespace motostab
