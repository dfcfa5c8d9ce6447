#include "swingarm/identification/yaml_input.h"

#include <cmath>
#include <set>

namespace motostab::identification {
namespace {
std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }
}  // namespace

YamlInput::YamlInput(const std::filesystem::path& file) : file_(file) {
  if (!std::filesystem::exists(file)) throw InputError({file.string(), 0, 0, ""}, "file not found");
  try {
    root_ = YAML::LoadFile(file.string());
  } catch (const YAML::Exception& e) {
    throw InputError({file.string(), e.mark.line + 1, e.mark.column + 1, ""}, "YAML syntax error: " + e.msg);
  }
  if (!root_.IsMap()) throw InputError({file.string(), 1, 1, ""}, "the document must be a YAML map");
}

InputLocation YamlInput::locate(const YAML::Node& node, const std::string& key) const {
  const auto m = node.Mark();
  if (m.is_null()) return {file_.string(), 0, 0, key};
  return {file_.string(), m.line + 1, m.column + 1, key};
}

void YamlInput::fail(const YAML::Node& node, const std::string& key, const std::string& message) const {
  throw InputError(locate(node, key), message);
}

void YamlInput::checkMap(const YAML::Node& node, const std::string& path,
                         std::initializer_list<const char*> allowed) const {
  if (!node.IsMap()) fail(node, path, "expected a map");
  std::set<std::string> seen;
  for (const auto& kv : node) {
    const std::string k = kv.first.as<std::string>();
    if (!seen.insert(k).second) fail(kv.first, join(path, k), "duplicate key");
    bool ok = false;
    std::string list;
    for (const char* a : allowed) {
      ok = ok || k == a;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    if (!ok) fail(kv.first, join(path, k), "unknown key (allowed: " + list + ")");
  }
}

YAML::Node YamlInput::getChild(const YAML::Node& map, const std::string& path, const std::string& key) const {
  const YAML::Node n = map[key];
  if (!n || n.IsNull()) fail(map, join(path, key), "missing required key '" + key + "'");
  return n;
}

double YamlInput::toDouble(const YAML::Node& n, const std::string& key) const {
  if (!n.IsScalar()) fail(n, key, "expected a number");
  double v = 0;
  try {
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    fail(n, key, "not a number: '" + n.Scalar() + "'");
  }
  if (!std::isfinite(v)) fail(n, key, "not a finite number");
  return v;
}

double YamlInput::getDouble(const YAML::Node& map, const std::string& path, const std::string& key) const {
  return toDouble(getChild(map, path, key), join(path, key));
}

double YamlInput::getDouble(const YAML::Node& map, const std::string& path, const std::string& key,
                            double fallback) const {
  return map[key] ? getDouble(map, path, key) : fallback;
}

double YamlInput::getPositive(const YAML::Node& map, const std::string& path, const std::string& key,
                              bool allowZero) const {
  const double v = getDouble(map, path, key);
  if (v < 0 || (!allowZero && v == 0))
    fail(map[key], join(path, key), allowZero ? "must not be negative" : "must be positive");
  return v;
}

double YamlInput::getPositive(const YAML::Node& map, const std::string& path, const std::string& key,
                              double fallback) const {
  return map[key] ? getPositive(map, path, key, false) : fallback;
}

std::string YamlInput::getString(const YAML::Node& map, const std::string& path, const std::string& key) const {
  const YAML::Node n = getChild(map, path, key);
  if (!n.IsScalar()) fail(n, join(path, key), "expected a string");
  return n.Scalar();
}

std::string YamlInput::getString(const YAML::Node& map, const std::string& path, const std::string& key,
                                 const std::string& fallback) const {
  return map[key] ? getString(map, path, key) : fallback;
}

bool YamlInput::getBool(const YAML::Node& map, const std::string& path, const std::string& key, bool fallback) const {
  if (!map[key]) return fallback;
  const YAML::Node n = map[key];
  try {
    return n.as<bool>();
  } catch (const YAML::Exception&) {
    fail(n, join(path, key), "expected true or false");
  }
}

std::vector<double> YamlInput::getNumbers(const YAML::Node& map, const std::string& path, const std::string& key,
                                          size_t size) const {
  const YAML::Node n = getChild(map, path, key);
  if (!n.IsSequence()) fail(n, join(path, key), "expected a list of numbers");
  if (size > 0 && n.size() != size) fail(n, join(path, key), "expected " + std::to_string(size) + " numbers");
  std::vector<double> v;
  for (size_t i = 0; i < n.size(); ++i) v.push_back(toDouble(n[i], join(path, key) + "[" + std::to_string(i) + "]"));
  return v;
}

std::filesystem::path YamlInput::resolvePath(const std::string& name) const {
  const std::filesystem::path p(name);
  return p.is_absolute() ? p : file_.parent_path() / p;
}

void YamlInput::checkTestKind(const std::string& kind) const {
  const std::string t = getString(root_, "", "test");
  if (t != kind) fail(root_["test"], "test", "expected 'test: " + kind + "', found '" + t + "'");
}

PlatePoint YamlInput::getForcePoint() const {
  const YAML::Node fp = getChild(root_, "", "force_point");
  checkMap(fp, "force_point", {"x", "z"});
  return {getDouble(fp, "force_point", "x"), getDouble(fp, "force_point", "z")};
}

}  // namespace motostab::identification
