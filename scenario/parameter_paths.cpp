#include "scenario/parameter_paths.h"

#include <cmath>
#include <utility>
#include <vector>

#include "io/input_error.h"
#include "io/number.h"
#include "io/yaml_map.h"

namespace motostab::scenario {

using io::InputError;
using io::findKeyPath;

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool readFinite(const YAML::Node& n, double& v) {
  return n && n.IsScalar() && YAML::convert<double>::decode(n, v) && std::isfinite(v);
}

// Appends the numeric leaves under `node` (maps and sequences), named from `path`.
void collect(const YAML::Node& node, const std::string& path, std::vector<ScalarParameter>& out) {
  if (node.IsMap()) {
    for (const auto& kv : node) collect(kv.second, path + "." + kv.first.as<std::string>(), out);
  } else if (node.IsSequence()) {
    for (size_t i = 0; i < node.size(); ++i) collect(node[i], path + "[" + std::to_string(i) + "]", out);
  } else {
    double v = 0;
    if (!readFinite(node, v)) return;
    out.push_back({path, v, getParameterKind(path), std::abs(v)});
  }
}

// Inertia entries take the tensor's largest diagonal entry as their scale.
void setInertiaScales(std::vector<ScalarParameter>& params) {
  for (auto& p : params) {
    if (p.kind != ParameterKind::Inertia) continue;
    const size_t dot = p.path.rfind('.');
    const std::string tensor = p.path.substr(0, dot);
    if (!endsWith(tensor, "inertia_kgm2")) continue;
    for (const auto& q : params)
      if (q.path == tensor + ".xx" || q.path == tensor + ".yy" || q.path == tensor + ".zz")
        p.scale = std::max(p.scale, std::abs(q.value));
  }
}

}  // namespace

ParameterKind getParameterKind(const std::string& path) {
  std::string key = path.substr(path.rfind('.') == std::string::npos ? 0 : path.rfind('.') + 1);
  if (path.find("inertia_kgm2.") != std::string::npos || endsWith(key, "_kgm2")) return ParameterKind::Inertia;
  const size_t bracket = key.find('[');
  if (bracket != std::string::npos) key = key.substr(0, bracket);
  if (endsWith(key, "_deg")) return ParameterKind::Angle;
  if (endsWith(key, "_kg")) return ParameterKind::Mass;
  if (endsWith(key, "_m")) return ParameterKind::Length;
  return ParameterKind::Other;
}

std::vector<ScalarParameter> listScalarParameters(const YAML::Node& tree) {
  std::vector<ScalarParameter> out;
  for (const char* section : {"geometry", "total", "rear_frame", "front_frame", "rear_wheel", "front_wheel"}) {
    const YAML::Node n = findKeyPath(tree, section);
    if (n && n.IsMap()) collect(n, section, out);
  }
  // Measured parts of optional sections: the swingarm, the leaning rider's upper body and its lean
  // stiffness and damping, the fork's hub carrier when given explicitly, and a steer
  // controller's gains, gain factor, delay and schedule speed.
  const std::pair<const char*, std::vector<const char*>> sections[] = {
      {"swingarm", {"pivot_m", "mass_kg", "com_m", "inertia_kgm2"}},
      {"rider_lean", {"hinge_height_m", "mass_kg", "com_m", "inertia_kgm2", "stiffness_Nm_per_rad", "damping_Nms_per_rad"}},
      {"fork_compliance.carrier", {"mass_kg", "com_m", "inertia_kgm2"}},
      {"rider_arms", {"inertia_kgm2", "stiffness_Nm_per_rad", "damping_Nms_per_rad", "grip_half_width_m"}},
      {"steer_controller", {"roll_angle_Nm_per_rad", "roll_rate_Nms_per_rad", "steer_angle_Nm_per_rad",
                            "steer_rate_Nms_per_rad", "gain_factor", "delay_s"}},
      {"steer_controller.schedule", {"below_mps"}},
  };
  for (const auto& [name, keys] : sections) {
    const YAML::Node section = findKeyPath(tree, name);
    if (!section || !section.IsMap()) continue;
    for (const char* key : keys) {
      const YAML::Node n = findKeyPath(section, key);
      if (n) collect(n, std::string(name) + "." + key, out);
    }
  }
  setInertiaScales(out);
  return out;
}

double getScalarParameter(const YAML::Node& tree, const std::string& path) {
  const YAML::Node n = findKeyPath(tree, path);
  if (!n) throw InputError({"", 0, 0, path}, "no such key in the scenario");
  double v = 0;
  if (!readFinite(n, v)) {
    const YAML::Mark m = n.Mark();
    throw InputError({"", m.line + 1, m.column + 1, path}, "expected a finite number");
  }
  return v;
}

std::string formatOverride(const std::string& path, double value) { return path + "=" + io::formatNumber(value); }

double getDefaultSigma(const ScalarParameter& p) {
  switch (p.kind) {
    case ParameterKind::Length: return 0.01;
    case ParameterKind::Angle: return 1.0;
    default: return 0.1 * p.scale;
  }
}

}  // namespace motostab::scenario
