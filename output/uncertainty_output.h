#pragma once
// Files written by `motostab uncertainty` (docs/uncertainty.md): summary.json, samples.csv,
// mode_quantiles.csv, sensitivity.csv, report.md and gnuplot fan charts, histograms and
// sensitivity bars with their scripts.
#include <filesystem>
#include <string>
#include <vector>

#include "nlohmann/json.hpp"
#include "uncertainty/uncertainty_summary.h"

namespace motostab::output {

/// The summary as JSON, with the pinned keys critical_speeds.<weave|capsize|wobble>.{mean_mps,
/// std_mps, p05_mps, p50_mps, p95_mps, fraction, first_order_std_mps} (m/s; fraction 0..1; null
/// where undefined), the sensitivities, and per fan mode and speed the 5/50/95 % real part (1/s)
/// and frequency (Hz).
nlohmann::json makeUncertaintyJson(const std::string& scenarioName, const uncertainty::UncertaintySetup& setup,
                                   const uncertainty::UncertaintySummary& summary);

/// samples.csv: one row per sample (mc) or Sobol evaluation: task, kind, row, status, redraws,
/// the parameter values, the first weave/capsize/wobble crossing (m/s), every crossing, the reason
/// of a failure.
std::string makeSamplesCsv(const uncertainty::UncertaintySetup& setup, const std::vector<uncertainty::TaskResult>& results);

/// report.md: set-up, critical-speed table (Monte Carlo against first order), ranked sensitivity
/// tables, failures.
std::string makeUncertaintyReport(const std::string& scenarioName, const uncertainty::UncertaintySetup& setup,
                                  const uncertainty::UncertaintySummary& summary);

/// Writes every file to `dir` (each complete or absent), and renders the plots with gnuplot.
void writeUncertaintyOutputs(const std::filesystem::path& dir, const std::string& scenarioName,
                             const uncertainty::UncertaintySetup& setup, const uncertainty::UncertaintySummary& summary,
                             const std::vector<uncertainty::TaskResult>& results);

}  // namespace motostab::output
