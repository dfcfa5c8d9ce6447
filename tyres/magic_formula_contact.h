#pragma once
// Contact plugin `magic_formula`: Magic Formula tyres (MF 6.1/6.2 from a .tir file, or the
// motorcycle variant, tyres/motorcycle_magic_formula.h) on the shared tyre contact of
// tyres/tyre_contact.h: contact point on the toroidal carcass, radial load law, slips, and the
// first-order relaxation of the side force.
//
// With s the lagged equivalent slip (the z state, rad), K_ya and K_yg the law's cornering and camber
// stiffnesses at zero slip (tyres/magic_formula.h) and phi the camber:
//   relaxation          sigma/V s' + s = alpha + (K_yg/K_ya) phi   (relaxation_linear's equivalent slip,
//                       k_phi/k_alpha = K_yg/K_ya), sigma from the scenario or the law at the current
//                       load, camber and speed (MF 6.x: |K_ya/C_y|, or PTY1, PTY2; motorcycle:
//                       K_ya (c1 + c2 V + c3 V^2))
//   lagged slip angle   alpha_l = s - (K_yg/K_ya) phi
//   forces              Fx, Fy, Mz, Mx, My of the law at (kappa, alpha_l, phi, Fz): one evaluation; in
//                       steady state s = alpha + (K_yg/K_ya) phi, alpha_l = alpha, the law's own forces
// K_ya, K_yg and sigma take the load floored at 5% of FNOMIN (finite when a wheel unloads).
// In straight running (zero slips and camber) this linearises to relaxation_linear with
// k_alpha = -K_ya/Fz, k_phi = -K_yg/Fz, k_mz = dMz/dalpha /Fz, k_mt = dMz/dphi /Fz and
// k_kappa = K_xk/Fz at the trim load, provided the law has no force or moment at zero slip
// (no shifts, no rolling resistance, no Mz from Fx): tests/tyres/magic_formula_contact_test.cpp.
//
// Scenario: a map per tyre under `front` and `rear`, keys in tyres/magic_formula_tyre.h. A law with a
// crown radius (motorcycle: CROWN_RADIUS) must sit on a wheel of that crown_radius_m.
#include <memory>

#include "plugins/plugin_api.h"
#include "tyres/magic_formula_tyre.h"

namespace motostab::tyres {

/// The `magic_formula` contact model of two typed tyres, apart from the scenario reader (whose factory
/// builds each with readMagicFormulaTyre). A tyre's law comes from makeTyreForceLaw of a coefficient
/// source (a .tir file, or makeMapSource for coefficients given in code); its relaxation length is NaN
/// (the law's), 0 (no lag) or at least kMinRelaxationLength, m.
std::unique_ptr<plugins::ContactModel> makeMagicFormulaContact(MagicFormulaTyre front, MagicFormulaTyre rear);

/// Registers `magic_formula`.
void registerMagicFormula(plugins::PluginRegistrar& registry);

}  // namespace motostab::tyres
