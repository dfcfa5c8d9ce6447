#pragma once
// Plausibility of a loaded scenario: values that are valid input but most likely a unit slip or two
// swapped quantities (a steer-axis tilt in radians, a head angle given as the caster, a wheelbase in
// millimetres, an inertia in kg cm^2, a tyre coefficient of the wrong sign). They are warnings, kept in
// Scenario::warnings at load (never printed here); commands print them and `--strict` makes them errors.
// The ranges and their reasons: docs/scenario-format.md#plausibility-warnings.
#include <string>
#include <vector>

#include "scenario/scenario.h"

namespace motostab::scenario {

/// Every warning for `scenario`, read from `tree` (the YAML it was read from, in `file`), each
/// located at the key that gives the value.
std::vector<ScenarioWarning> checkPlausibility(const Scenario& scenario, const YAML::Node& tree, const std::string& file);

/// The check's name as outputs write it (e.g. "steer_axis_tilt").
const char* getCheckName(ScenarioWarning::Check check);

/// "file:line:col: key: message" of one warning.
std::string formatWarning(const ScenarioWarning& warning);

}  // namespace motostab::scenario
