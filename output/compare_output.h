#pragma once
// Files written by `motostab compare`: several scenarios swept over the same speeds, side by side.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/sweep.h"
#include "nlohmann/json.hpp"
#include "scenario/scenario.h"

namespace motostab::output {

/// One scenario of a comparison and its sweep. `label` names its folder and its lines in the plots
/// (the scenario's name, made unique and safe as a folder name: makeCompareLabels).
struct ComparedSweep {
  std::string label;
  scenario::Scenario scenario;
  analysis::SweepResult sweep;
};

/// A label per scenario name: the name with every character but letters, digits, '.', '_' and '-'
/// replaced by '_', and "-2", "-3", ... appended to repeats.
std::vector<std::string> makeCompareLabels(const std::vector<std::string>& names);

/// The critical speeds of every sweep matched across them: a row per (mode, direction, occurrence),
/// in the order of the first sweep, then of the others; each row's speed per sweep (NaN where that
/// sweep has none) and its difference against the first sweep (NaN where either is missing).
struct CriticalSpeedRow {
  std::string mode, direction;
  int occurrence = 1;               ///< 1 for the first sign change of this mode in this direction
  std::vector<double> speeds;       ///< m/s, per sweep
  std::vector<double> differences;  ///< m/s, speeds[i] - speeds[0]
};
std::vector<CriticalSpeedRow> matchCriticalSpeeds(const std::vector<ComparedSweep>& sweeps);

/// DIR/summary.json: {speeds_mps, reference, scenarios: [{label, name, file, summary: the sweep's
/// summary.json (makeSweepSummary)}], critical_speeds: [{mode, direction, occurrence, speeds_mps,
/// differences_mps}] (null where missing)}.
nlohmann::json makeCompareSummary(const std::vector<ComparedSweep>& sweeps);

/// The critical-speed table with the differences against the first scenario, as text.
std::string formatCompareTable(const std::vector<ComparedSweep>& sweeps);

/// Writes DIR/summary.json, DIR/critical_speeds.csv (mode,direction,occurrence, then per scenario
/// LABEL_speed_mps and, after the first, LABEL_difference_mps), DIR/LABEL/{eigenvalues.csv,
/// summary.json, scenario.json} for each scenario (the sweep's own files), and the overlaid plots
/// root_locus and real_part_vs_speed (.gp, .png, .svg; one colour per scenario).
void writeCompareOutputs(const std::filesystem::path& dir, const std::vector<ComparedSweep>& sweeps);

}  // namespace motostab::output
