#pragma once
// One scenario source: the scenario file read and parsed once (the strict YAML layer: duplicate keys
// and syntax errors located), kept as a tree with each node's file, line and column. Every variant
// of the scenario (a --set, a diagnosis candidate, an uncertainty sample, a study variant) is a copy
// of that tree with typed parameter changes applied (scenario/parameter_overrides.h), then read by
// the same strict reader as the file itself: the same checks and the same messages (file:line:col
// and key, "(value from --set ...)" for a value a change gave).
#include <memory>
#include <string>

#include "scenario/parameter_overrides.h"
#include "scenario/scenario.h"

namespace motostab::scenario {

class ScenarioSource {
 public:
  /// Reads and parses `file`; InputError on a missing file, a syntax error or a duplicate key.
  explicit ScenarioSource(std::string file);
  /// A tree built in memory (e.g. from a Python dict); `name` stands for the file in messages, and
  /// relative paths in it resolve against the working folder.
  ScenarioSource(YAML::Node tree, std::string name);
  /// Shared, for objects that outlive the caller's scope (predictors, study jobs).
  static std::shared_ptr<const ScenarioSource> open(const std::string& file);

  const std::string& getFile() const { return file_; }
  /// A deep copy of the parsed tree (marks kept) with `changes` applied in order. Thread-safe.
  YAML::Node makeTree(const ParameterOverrides& changes = {}) const;
  /// The scenario with `changes` applied, validated as loadScenario validates a file. Thread-safe.
  Scenario load(const ParameterOverrides& changes = {}) const;

 private:
  std::string file_;
  YAML::Node tree_;  ///< never modified after construction (only copied)
  /// Shared by every scenario loaded from this source: the files its plugins name are read once.
  std::shared_ptr<io::InputStore> inputs_ = std::make_shared<io::InputStore>();
};

}  // namespace motostab::scenario
