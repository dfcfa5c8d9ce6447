#pragma once
// Strict YAML reading for test descriptions: unknown keys, missing keys and bad values are InputErrors
// naming the file, line, column and dotted key.
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "swingarm/identification/plate_motion.h"

namespace motostab::identification {

/// One YAML file loaded for strict reading. Keys are addressed by a dotted path for messages.
class YamlInput {
 public:
  /// Loads `file`; an unreadable file or a syntax error is an InputError.
  explicit YamlInput(const std::filesystem::path& file);

  const YAML::Node& getRoot() const { return root_; }
  const std::filesystem::path& getFile() const { return file_; }

  /// Location of `node` (1-based line and column) labelled with `key`.
  InputLocation locate(const YAML::Node& node, const std::string& key) const;
  /// Throws an InputError at `node`.
  [[noreturn]] void fail(const YAML::Node& node, const std::string& key, const std::string& message) const;

  /// `node` must be a map whose keys are all in `allowed`, each at most once.
  void checkMap(const YAML::Node& node, const std::string& path, std::initializer_list<const char*> allowed) const;
  /// A required child (error names the missing key at the parent's location).
  YAML::Node getChild(const YAML::Node& map, const std::string& path, const std::string& key) const;

  /// Required finite number.
  double getDouble(const YAML::Node& map, const std::string& path, const std::string& key) const;
  /// Optional finite number with a default.
  double getDouble(const YAML::Node& map, const std::string& path, const std::string& key, double fallback) const;
  /// Required number > 0 (or >= 0 if allowZero).
  double getPositive(const YAML::Node& map, const std::string& path, const std::string& key, bool allowZero = false) const;
  /// Optional number > 0 with a default.
  double getPositive(const YAML::Node& map, const std::string& path, const std::string& key, double fallback) const;
  /// Required scalar string.
  std::string getString(const YAML::Node& map, const std::string& path, const std::string& key) const;
  /// Optional scalar string with a default.
  std::string getString(const YAML::Node& map, const std::string& path, const std::string& key,
                        const std::string& fallback) const;
  /// Optional boolean with a default.
  bool getBool(const YAML::Node& map, const std::string& path, const std::string& key, bool fallback) const;
  /// Required sequence of numbers, of `size` elements if size > 0.
  std::vector<double> getNumbers(const YAML::Node& map, const std::string& path, const std::string& key,
                                 size_t size = 0) const;
  /// Path of a file named in the YAML, relative to the YAML file's folder unless absolute.
  std::filesystem::path resolvePath(const std::string& name) const;
  /// Requires `test: <kind>` at the root.
  void checkTestKind(const std::string& kind) const;
  /// The required root key `force_point: {x, z}`, m.
  PlatePoint getForcePoint() const;

 private:
  double toDouble(const YAML::Node& node, const std::string& key) const;
  std::filesystem::path file_;
  YAML::Node root_;
};

}  // namespace motostab::identification
