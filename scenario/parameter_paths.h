#pragma once
// Scalar scenario parameters addressed by the key paths that `--set` takes: `geometry.trail_m`,
// `rear_frame.com_m[2]`, `front_frame.inertia_kgm2.xz`. Diagnosis (wrong-parameter candidates) and
// uncertainty studies (sampled parameters) both enumerate and change parameters through these paths.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "io/field.h"

namespace motostab::scenario {

/// What a parameter measures: its field's declared quantity.
using ParameterKind = io::Quantity;

struct ScalarParameter {
  std::string path;     ///< key path as --set takes it
  double value = 0;     ///< in the key's own unit (degrees for _deg keys)
  ParameterKind kind = ParameterKind::Other;
  /// Typical magnitude for relative uncertainties: |value|, except for inertia entries, where it is
  /// the largest principal-axis (diagonal) entry of the same tensor (a zero product of inertia still
  /// has a scale), in the key's unit.
  double scale = 0;
  /// A fit keeps its sign: its field admits positive values only or keeps its sign (io::Field::keepsSign;
  /// an inertia tensor's diagonal entries).
  bool positive = false;
};

/// Every scalar of the vehicle's measured description present in a scenario tree: the measured fields
/// of `sections` (io::Field::measured; the loader's own sections, scenario/scenario_fields.h, and the
/// plugins' declared ones), a vector field as its three entries (`com_m[2]`), an inertia tensor as its
/// six (`inertia_kgm2.xz`). Order: the sections', then their fields' declaration order.
std::vector<ScalarParameter> listScalarParameters(const YAML::Node& scenarioTree, const std::vector<io::SectionFields>& sections);

/// The number at any key path of a tree (also plugin sections, e.g.
/// `swingarm.torsion.stiffness_Nm_per_rad`). InputError naming the path if it is absent or not a
/// finite number.
double getScalarParameter(const YAML::Node& tree, const std::string& path);

/// "path=value" with 17 significant digits (round-trips the double), for loadScenario overrides.
std::string formatOverride(const std::string& path, double value);

/// Standard deviation assumed for a parameter whose uncertainty the scenario does not state, in the
/// key's unit: 10 mm for lengths and positions, 10 % of `scale` for masses, inertias and other
/// quantities, 1 degree for angles.
double getDefaultSigma(const ScalarParameter& parameter);

}  // namespace motostab::scenario
