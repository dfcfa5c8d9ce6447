#include "scenario/parameter_paths.h"

#include <algorithm>
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

bool readFinite(const YAML::Node& n, double& v) {
  return n && n.IsScalar() && YAML::convert<double>::decode(n, v) && std::isfinite(v);
}

// Appends the numbers of one measured field at `path` (a number, [x, y, z] or an inertia tensor).
void collect(const YAML::Node& node, const std::string& path, const io::Field& f, std::vector<ScalarParameter>& out) {
  auto add = [&](const YAML::Node& n, const std::string& p, bool positive) {
    double v = 0;
    if (readFinite(n, v)) out.push_back({p, v, f.quantity, std::abs(v), positive});
  };
  switch (f.shape) {
    case io::Shape::Number: add(node, path, f.keepsSign); break;
    case io::Shape::Vector3:
      if (node.IsSequence())
        for (size_t i = 0; i < node.size(); ++i)
          if (!(f.inPlane && i == 1)) add(node[i], path + "[" + std::to_string(i) + "]", false);
      break;
    case io::Shape::Inertia: {
      if (!node.IsMap()) break;
      const size_t first = out.size();
      double scale = 0;  // the largest principal-axis (diagonal) entry
      for (const char* e : {"xx", "yy", "zz", "xy", "xz", "yz"}) {
        add(node[e], path + "." + e, e[0] == e[1]);
        if (out.size() > first && e[0] == e[1]) scale = std::max(scale, out.back().scale);
      }
      for (size_t i = first; i < out.size(); ++i) out[i].scale = std::max(out[i].scale, scale);
      break;
    }
    case io::Shape::Other: break;
  }
}

}  // namespace

std::vector<ScalarParameter> listScalarParameters(const YAML::Node& tree, const std::vector<io::SectionFields>& sections) {
  std::vector<ScalarParameter> out;
  for (const io::SectionFields& section : sections) {
    if (!section.isSelectedIn(tree)) continue;
    const YAML::Node n = section.path.empty() ? tree : findKeyPath(tree, section.path);
    if (!n || !n.IsMap()) continue;
    for (const io::Field& f : section.fields)
      if (f.measured && n[f.key]) collect(n[f.key], section.getKeyPath(f.key), f, out);
  }
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
