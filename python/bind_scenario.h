#pragma once
// The scenario handle the bindings pass around (python/bind_scenario.cpp binds it).
#include <yaml-cpp/yaml.h>

#include <memory>

#include "python/common.h"
#include "scenario/parameter_overrides.h"
#include "scenario/scenario_source.h"

namespace motostab::python {

/// A scenario source, the typed changes applied to it, and the scenario they give (validated on
/// construction: InputError as the command line's --set). Immutable; copies share the source.
struct ScenarioHandle {
  ScenarioHandle(std::shared_ptr<const scenario::ScenarioSource> source, scenario::ParameterOverrides changes);
  /// A new handle with `values` (key path -> Python value) applied after these changes: a number is a
  /// typed number change, a string a switch, a dict, list or None a whole section.
  ScenarioHandle withChanges(const py::dict& values) const;
  /// The source's tree with the changes applied.
  YAML::Node makeTree() const;

  std::shared_ptr<const scenario::ScenarioSource> source;
  scenario::ParameterOverrides changes;
  std::shared_ptr<const scenario::Scenario> scenario;
};

}  // namespace motostab::python
