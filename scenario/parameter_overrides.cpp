#include "scenario/parameter_overrides.h"


#include "io/number.h"
#include "io/yaml_map.h"

namespace motostab::scenario {

using io::ParsedOverride;
using io::copyTree;
using io::formatShortest;
using io::makeOverrideScalar;
using io::parseFiniteNumber;
using io::parseOverride;
using io::setKeyPath;

std::string ParameterOverride::format() const {
  if (!text.empty()) return text;
  if (const double* v = std::get_if<double>(&value)) return path + "=" + formatShortest(*v);
  if (const std::string* s = std::get_if<std::string>(&value)) return path + "=" + *s;
  YAML::Emitter e;
  e.SetMapFormat(YAML::Flow);
  e.SetSeqFormat(YAML::Flow);
  e << std::get<YAML::Node>(value);
  return path + "=" + e.c_str();
}

ParameterOverrides::ParameterOverrides(const std::vector<std::string>& assignments) {
  for (const auto& a : assignments) {
    ParsedOverride o = parseOverride(a);
    ParameterOverride change{o.path, o.value, a};
    if (o.value.IsScalar()) {
      const auto number = parseFiniteNumber(o.value.Scalar());
      if (number) change.value = *number;
      else change.value = o.value.Scalar();
    }
    add(std::move(change));
  }
}

ParameterOverrides::ParameterOverrides(std::initializer_list<std::string> assignments)
    : ParameterOverrides(std::vector<std::string>(assignments)) {}

void ParameterOverrides::add(ParameterOverride change) {
  for (auto it = items_.begin(); it != items_.end(); ++it)
    if (it->path == change.path) {
      items_.erase(it);
      break;
    }
  items_.push_back(std::move(change));
}

void ParameterOverrides::set(const std::string& path, double value) { add({path, value, ""}); }

void ParameterOverrides::set(const std::string& path, const std::string& value) { add({path, value, ""}); }

void ParameterOverrides::setNode(const std::string& path, const YAML::Node& value) { add({path, copyTree(value), ""}); }

void ParameterOverrides::append(const ParameterOverrides& later) {
  for (const auto& c : later.items_) add(c);
}

std::vector<std::string> ParameterOverrides::format() const {
  std::vector<std::string> out;
  for (const auto& c : items_) out.push_back(c.format());
  return out;
}

void ParameterOverrides::applyTo(YAML::Node& tree) const {
  for (const auto& c : items_) {
    YAML::Node value;  // a fresh node per tree: trees never share (or edit) this map's sections
    if (const double* v = std::get_if<double>(&c.value))  // the user's digits, so a name "1e3" stays "1e3"
      value = makeOverrideScalar(c.text.empty() ? formatShortest(*v) : parseOverride(c.text).value.Scalar());
    else if (const std::string* s = std::get_if<std::string>(&c.value)) value = makeOverrideScalar(*s);
    else value = copyTree(std::get<YAML::Node>(c.value));
    setKeyPath(tree, c.path, value, c.format());
  }
}

}  // namespace motostab::scenario
