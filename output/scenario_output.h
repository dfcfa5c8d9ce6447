#pragma once
// The loaded scenario as outputs record it: the whole vehicle in the form engineers tabulate (seed
// Table 6: total mass, CoG, roll/pitch/yaw inertias and product about the CoG, static wheel loads,
// steer geometry), every body as the model builds it (with the rear frame derived from `total:`),
// the values assumed from defaults and the plausibility warnings. `motostab check` prints it; every
// command that writes an output folder writes it as DIR/scenario.json.
#include <filesystem>
#include <string>

#include "nlohmann/json.hpp"
#include "scenario/scenario.h"

namespace motostab::output {

/// The scenario's metadata: {name, file, overrides, vehicle (Table 6 form), rear_frame (with
/// derived_from_total), bodies, assumed, warnings}. Units in the key names.
nlohmann::json makeScenarioJson(const scenario::Scenario& scenario);

/// DIR/scenario.json (makeScenarioJson).
void writeScenarioJson(const std::filesystem::path& dir, const scenario::Scenario& scenario);

/// The vehicle table, the bodies and the assumed values as text, for `check`.
std::string formatVehicleTable(const scenario::Scenario& scenario);

}  // namespace motostab::output
