#pragma once
// Typed changes of scenario keys: a key path (as --set takes it: `geometry.trail_m`,
// `rear_frame.com_m[2]`) mapped to a value. A number is kept as the double itself (full precision:
// it reaches the scenario tree as the shortest text that reads back to the same double), a string is
// a switch (`swingarm.compliance=twist`), and a YAML subtree is a whole section
// (`steer_damper={damping_Nms_per_rad: 0.4}`). `--set` text is parsed once into this map; diagnosis,
// uncertainty and the swingarm study build their changes as values, never as text.
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <variant>
#include <vector>

namespace motostab::scenario {

/// One change: the key path and its value.
struct ParameterOverride {
  std::string path;
  std::variant<double, std::string, YAML::Node> value;
  std::string text;  ///< the assignment as the user wrote it (empty when set as a value)
  /// "path=value" as --set takes it (the user's text when parsed from one; numbers in the shortest
  /// form that reads back to the same double).
  std::string format() const;
};

/// An ordered map of key path -> value. Setting a path already present replaces its value and moves
/// it last; changes are applied in order, so a section set before one of its keys keeps that key's
/// later value.
class ParameterOverrides {
 public:
  ParameterOverrides() = default;
  /// Parses "a.b=value" assignments (--set text): the value is read as YAML once; a scalar that
  /// parseFiniteNumber reads is a number, any other scalar a string, a mapping or list a section.
  /// InputError naming the assignment on malformed text or a duplicate key in the value.
  ParameterOverrides(const std::vector<std::string>& assignments);  // NOLINT: text converts implicitly
  ParameterOverrides(std::initializer_list<std::string> assignments);

  void set(const std::string& path, double value);
  void set(const std::string& path, const std::string& value);
  void set(const std::string& path, const char* value) { set(path, std::string(value)); }
  /// A whole section (or list) as a YAML subtree.
  void setNode(const std::string& path, const YAML::Node& value);
  /// Appends `later`'s changes after these (each set again: later values win).
  void append(const ParameterOverrides& later);

  bool empty() const { return items_.empty(); }
  size_t size() const { return items_.size(); }
  const std::vector<ParameterOverride>& getItems() const { return items_; }
  /// Every change as "path=value" text, in order (for messages, reports and reproducible commands).
  std::vector<std::string> format() const;
  /// Applies the changes in order to `tree` (setKeyPath); InputError naming the change on a path
  /// through a non-map or an index out of range.
  void applyTo(YAML::Node& tree) const;

 private:
  void add(ParameterOverride change);
  std::vector<ParameterOverride> items_;
};

}  // namespace motostab::scenario
