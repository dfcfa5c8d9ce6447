#pragma once
// `motostab simulate --identify`: modes identified from a simulated free response. The glue between
// the time domain (simulation/) and free-response fitting (response/) lives here, above both, so
// neither library depends on the other.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "response/mode_identification.h"
#include "simulation/simulation.h"

namespace motostab::cli {

/// Identifies the modes of `signals` (column names; default roll_rate and steer_rate, fitted jointly)
/// of `result` from `windowStart` (s) on. Throws io::ResultError if the response after `windowStart` cannot be fitted (too short, constant).
response::IdentificationResult identifySimulatedModes(
    const simulation::SimulationResult& result, double windowStart,
    const std::vector<std::string>& signals = {"roll_rate", "steer_rate"},
    response::IdentificationOptions options = {});

/// Identifies as above and writes DIR/modes.json (format of docs/response-identification.md, with the
/// simulation settings under "simulation") plus the fit plot DIR/response_fit.{gp,png,svg}.
response::IdentificationResult writeSimulatedModes(const std::filesystem::path& dir,
                                                   const simulation::SimulationResult& result, double windowStart,
                                                   const nlohmann::json& settings,
                                                   const std::vector<std::string>& signals = {"roll_rate",
                                                                                              "steer_rate"});

}  // namespace motostab::cli
