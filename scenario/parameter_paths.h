#pragma once
// Scalar scenario parameters addressed by the key paths that `--set` takes: `geometry.trail_m`,
// `rear_frame.com_m[2]`, `front_frame.inertia_kgm2.xz`. Diagnosis (wrong-parameter candidates) and
// uncertainty studies (sampled parameters) both enumerate and change parameters through these paths.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace motostab::scenario {

/// What a parameter measures, from its key's unit suffix (_m, _kg, _kgm2, _deg).
enum class ParameterKind { Length, Mass, Inertia, Angle, Other };

struct ScalarParameter {
  std::string path;     ///< key path as --set takes it
  double value = 0;     ///< in the key's own unit (degrees for _deg keys)
  ParameterKind kind = ParameterKind::Other;
  /// Typical magnitude for relative uncertainties: |value|, except for inertia entries, where it is
  /// the largest principal-axis (diagonal) entry of the same tensor (a zero product of inertia still
  /// has a scale), in the key's unit.
  double scale = 0;
};

/// Every scalar of the vehicle's measured description present in a scenario tree: geometry, the whole
/// vehicle (`total`), the rear and front frames (mass, each CoM coordinate, each inertia entry), both wheels, the
/// swingarm's pivot and mass properties, and when present the leaning rider's hinge height, upper
/// body, lean stiffness and damping (`rider_lean`) and an explicit fork hub carrier
/// (`fork_compliance.carrier`), the rider's arms (`rider_arms`), and a steer controller's gains, gain factor, delay and `below_mps`
/// (`steer_controller`). Order: as in the scenario format.
std::vector<ScalarParameter> listScalarParameters(const YAML::Node& scenarioTree);

/// The number at any key path of a tree (also plugin sections, e.g.
/// `swingarm.torsion.stiffness_Nm_per_rad`). InputError naming the path if it is absent or not a
/// finite number.
double getScalarParameter(const YAML::Node& tree, const std::string& path);

/// The kind of a key path from its unit suffix.
ParameterKind getParameterKind(const std::string& path);

/// "path=value" with 17 significant digits (round-trips the double), for loadScenario overrides.
std::string formatOverride(const std::string& path, double value);

/// Standard deviation assumed for a parameter whose uncertainty the scenario does not state, in the
/// key's unit: 10 mm for lengths and positions, 10 % of `scale` for masses, inertias and other
/// quantities, 1 degree for angles.
double getDefaultSigma(const ScalarParameter& parameter);

}  // namespace motostab::scenario
