#pragma once
// Outputs of a simulation: DIR/timeseries.csv, the response plot, and modes identified from the
// free response (DIR/modes.json, through response/).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "response/mode_identification.h"
#include "simulation/simulation.h"

namespace motostab::simulation {

/// Writes DIR/timeseries.csv: a header of result.columns and one row per sample (17 significant
/// digits), through a temporary file and a rename.
void writeTimeseries(const std::filesystem::path& dir, const SimulationResult& result);

/// Plots roll and steer (deg), yaw rate (deg/s) and every compliance coordinate (q not among the
/// rigid vehicle's) against time: DIR/response.{gp,png,svg}, reading DIR/timeseries.csv.
/// Throws std::runtime_error if gnuplot fails.
void writeResponsePlot(const std::filesystem::path& dir, const SimulationResult& result, const std::string& title);

/// Time (s) from which the response is free: the end of the last force pulse, 0 without pulses.
double getFreeResponseStart(const std::vector<Perturbation>& perturbations);

/// Identifies the modes of `signals` (column names; default roll_rate and steer_rate, fitted jointly)
/// of `result` from `windowStart` (s) on. Throws std::invalid_argument if the window is too short.
response::IdentificationResult identifySimulatedModes(
    const SimulationResult& result, double windowStart,
    const std::vector<std::string>& signals = {"roll_rate", "steer_rate"},
    response::IdentificationOptions options = {});

/// Identifies as above and writes DIR/modes.json (format of docs/response-identification.md, with the
/// simulation settings under "simulation") plus the fit plot DIR/response_fit.{gp,png,svg}.
response::IdentificationResult writeSimulatedModes(const std::filesystem::path& dir, const SimulationResult& result,
                                                   double windowStart, const nlohmann::json& settings,
                                                   const std::vector<std::string>& signals = {"roll_rate",
                                                                                              "steer_rate"});

}  // namespace motostab::simulation
