#pragma once
// One Magic Formula tyre as a scenario gives it, under `contact: {model: magic_formula, front: {...},
// rear: {...}}`: the force law (a .tir file or inline coefficients), the scenario's relaxation length,
// the radial law, and where it was given. The `magic_formula` contact plugin
// (tyres/magic_formula_contact.h) builds its force elements from it; `motostab tyre SCENARIO` draws it.
//
// Keys (docs/scenario-format.md, docs/tyres.md):
//   tir: FILE | coefficients: {NAME: value, ...}   the coefficients (names of the .tir keys)
//   variant: mf61 | mf62 | motorcycle              default: the file's FITTYP (required inline)
//   paper_axes: z_down | z_up                      motorcycle only; default z_down (MBSim, TUMFTM)
//   slip_variable: angle | tangent                 motorcycle only; default angle (MBSim, TUMFTM)
//   scaling: {LKY: 1.1, ...}                       scaling factors overriding the file's (default 1)
//   relaxation_length_m                            optional (0: no lag); required when the law has none
//   radial_stiffness_N_per_m, radial_damping_Ns_per_m   default VERTICAL_STIFFNESS, VERTICAL_DAMPING
//   pressure_Pa                                    default INFLPRES, else NOMPRES (MF 6.x)
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "io/field.h"
#include "io/input_error.h"
#include "io/yaml_map.h"
#include "tyres/magic_formula.h"
#include "tyres/tyre_contact.h"

namespace motostab::tyres {

struct MagicFormulaTyre {
  std::shared_ptr<const TyreForceLaw> law;
  MagicFormulaVariant variant = MagicFormulaVariant::MF61;
  MotorcycleConventions conventions;  ///< the motorcycle variant's reading of the paper
  double relaxationLength = std::numeric_limits<double>::quiet_NaN();  ///< m; NaN: the law's
  RadialLaw radial;
  io::InputLocation where;  ///< the tyre's scenario map, for errors found when the wheel is known
  bool isLagged() const { return std::isnan(relaxationLength) || relaxationLength > 0; }
};

/// Reads one tyre's map (keys above). Every problem, including a force law that findForceLawProblem
/// refuses, is an InputError at the key or the coefficient that causes it. Unused nonzero coefficients
/// of a .tir file are reported on std::cerr.
MagicFormulaTyre readMagicFormulaTyre(io::YamlMap m);

/// The declared keys of one Magic Formula tyre (its path "", placed at `contact.front` and
/// `contact.rear` by the contact plugin): the coefficient source, variant, scaling, pressure, relaxation,
/// radial law and the motorcycle variant's conventions.
const io::SectionFields& getMagicFormulaTyreFields();

/// A law whose moments use a crown radius (the motorcycle one) must sit on a wheel of that crown:
/// InputError at the tyre's map naming `wheel`.crown_radius_m (m) otherwise.
void checkCrownRadius(const MagicFormulaTyre& tyre, const std::string& wheel, double crownRadius);

}  // namespace motostab::tyres
