#pragma once
// Outputs of a simulation: DIR/timeseries.csv and the response plot. The modes identified from the
// free response (`simulate --identify`) are written by output/response_output.h (apps/simulate_identify.h).
#include <filesystem>
#include <string>

#include "simulation/simulation.h"

namespace motostab::output {

/// Writes DIR/timeseries.csv: a header of result.columns and one row per sample (17 significant
/// digits), through a temporary file and a rename.
void writeTimeseries(const std::filesystem::path& dir, const simulation::SimulationResult& result);

/// Plots roll and steer (deg), yaw rate (deg/s) and every compliance coordinate (q not among the
/// rigid vehicle's) against time: DIR/response.{gp,png,svg}, reading DIR/timeseries.csv.
/// Throws std::runtime_error if gnuplot fails.
void writeResponsePlot(const std::filesystem::path& dir, const simulation::SimulationResult& result, const std::string& title);

}  // namespace motostab::output
