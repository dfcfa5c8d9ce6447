#pragma once
// The motorcycle Magic Formula of Sharp, Evangelou & Limebeer (2004), "Advances in the modelling of
// motorcycle dynamics", Multibody System Dynamics 12:251-283, sec. 4, and S. Evangelou (2004), PhD
// thesis, Imperial College London, ch. 9 (after de Vries & Pacejka 1998 and Pacejka 2012 ch. 11).
// Camber is large and its thrust dominant, so camber enters the side force through its own Magic
// Formula term instead of MF 6.1's shifts, and the camber coefficients share names with MF 6.1 but not
// meanings (docs/tyres.md lists both). The equations are written in the paper's signs: a slip `a` and a
// camber `g` (rad, not sin g) that both push the tyre to +y. The law's inputs and outputs are ISO-W like
// every TyreForceLaw (tyres/magic_formula.h); MotorcycleConventions says how the paper's a, g, Fy and
// Mz map to them (default, as MBSim and TUMFTM: a = alpha_ISO in rad, g = gamma_ISO, Fy_ISO = -Fy,
// Mz_ISO = -Mz). Rc = CROWN_RADIUS.
//
//   dfz = (Fz - Fz0)/Fz0,  Fz0 = FNOMIN LFZO
//   Fx0 = Dx sin(Cx atan(Bx k - Ex (Bx k - atan(Bx k)))),  Cx = PCX1,  Dx = (PDX1 + PDX2 dfz) LMUX Fz,
//         Kx = Fz (PKX1 + PKX2 dfz) exp(PKX3 dfz) LKX,  Bx = Kx/(Cx Dx),
//         Ex = (PEX1 + PEX2 dfz + PEX3 dfz^2)(1 - PEX4 sgn k)
//   Fy0 = Dy sin(Cy atan(By a - Ey (By a - atan(By a))) + Cg atan(Bg g - Eg (Bg g - atan(Bg g)))),
//         Dy = PDY1 exp(PDY2 dfz)/(1 + PDY3 g^2) LMUY Fz,  Cy = PCY1,  Cg = PCY2,  Eg = PEY5,
//         Ey = PEY1 + PEY2 g^2 + PEY4 g sgn a,
//         Kya = PKY1 Fz0 sin(PKY2 atan(Fz/((PKY3 + PKY4 g^2) Fz0)))/(1 + PKY5 g^2) LKY,  By = Kya/(Cy Dy),
//         Kyg = (PKY6 + PKY7 dfz) Fz LKYC,  Bg = Kyg/(Cg Dy)
//   combined: Fx = Fx0 cos(RCX1 atan(RBX1 cos(atan(RBX2 k)) a)),
//             Fy = Fy0 cos(RCY1 atan(RBY1 cos(atan(RBY2 (a - RBY3))) k)) = Gyk Fy0
//   Mz = -t Gyk Fy0(a, g = 0) + Mzr,  t = Dt cos(Ct atan(Bt a_teq - Et (Bt a_teq - atan(Bt a_teq)))) cos a,
//         cos a = 1/sqrt(1 + a^2),  a_teq = sqrt(a^2 + (Kx k/Kya0)^2) sgn a  (Kya0 = Kya at g = 0),
//         Bt = (QBZ1 + QBZ2 dfz)(1 + QBZ5 |g| + QBZ6 g^2),  Ct = QCZ1,
//         Dt = Fz (Rc/Fz0)(QDZ1 + QDZ2 dfz)(1 + QDZ3 |g| + QDZ4 g^2) LTR,
//         Et = (QEZ1 + QEZ2 dfz + QEZ3 dfz^2)(1 + QEZ5 g (2/pi) atan(Bt Ct a)),
//         Mzr = Dr cos(atan(Br a_req)),  a_r = a + (QHZ3 + QHZ4 dfz) g,  a_req = sqrt(a_r^2 + (Kx k/Kya0)^2) sgn a_r,
//         Br = QBZ9 + QBZ10 By0 Cy (By0 at g = 0),
//         Dr = Fz Rc ((QDZ8 + QDZ9 dfz) g + (QDZ10 + QDZ11 dfz) g |g|) LRES cos a
//   optional, 0 when absent: PDY2, PDY3 (in both public implementations; not in the paper's tyre sets)
//   and QEZ3 (Evangelou's Table 9.3; in neither public implementation)
//   relaxation: sigma = Kya (RELAX_C1 + RELAX_C2 V + RELAX_C3 V^2) (Evangelou 2004 Table 9.5), optional
//   Mx = My = 0 (the toroidal contact point carries the overturning geometry; no rolling resistance).
#include <memory>
#include <string>
#include <vector>

#include "tyres/magic_formula.h"

namespace motostab::tyres {

/// The scaling factors the motorcycle equations use (LFZO, LMUX, LKX, LMUY, LKY, LKYC, LTR, LRES).
const std::vector<std::string>& getMotorcycleScalingNames();

/// Reads the motorcycle coefficients (names as above, FNOMIN, UNLOADED_RADIUS, CROWN_RADIUS, and
/// optionally all of RELAX_C1-3) from `source` and checks their signs (InputError at the coefficient,
/// docs/tyres.md "What is refused"). Without RELAX_C1-3 calcRelaxationLength returns NaN.
std::unique_ptr<TyreForceLaw> makeMotorcycleMagicFormula(const CoefficientSource& source,
                                                         const MotorcycleConventions& conventions = {});

}  // namespace motostab::tyres
