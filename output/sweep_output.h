#pragma once
// Files written by `motostab sweep` and `motostab linearize`.
#include <filesystem>
#include <string>

#include "analysis/sweep.h"
#include "nlohmann/json.hpp"

namespace motostab::output {

/// Frequency imag/(2 pi) in Hz and damping ratio -real/|lambda| (seed eq. 27; NaN for lambda = 0).
double calcFrequencyHz(std::complex<double> lambda);
double calcDampingRatio(std::complex<double> lambda);

/// DIR/eigenvalues.csv and DIR/summary.json only.
void writeSweepData(const std::filesystem::path& dir, const std::string& scenarioName, const analysis::SweepResult& sweep);

/// DIR/eigenvalues.csv (speed_mps,mode,real,imag,frequency_hz,damping_ratio; 17 digits),
/// DIR/summary.json (critical speeds), and the root-locus and real-part plots with their scripts.
void writeSweepOutputs(const std::filesystem::path& dir, const std::string& scenarioName, const analysis::SweepResult& sweep);

/// The summary as JSON: critical speeds per mode and the speed ranges where all modes are stable.
nlohmann::json makeSweepSummary(const std::string& scenarioName, const analysis::SweepResult& sweep);

/// A readable table of the labelled eigenvalues at about `rows` speeds, and the critical speeds.
std::string formatSweepTable(const analysis::SweepResult& sweep, int rows = 11);

/// DIR/A.csv, DIR/B.csv (named rows and columns), DIR/eigenvalues.csv, DIR/eigenvectors.csv and
/// DIR/linear_model.json (speed_mps, roll_rad, heading_frame: true about a steady turn, states, inputs,
/// A, B, eigenvalues).
void writeLinearModel(const std::filesystem::path& dir, const analysis::LinearModel& lin);

}  // namespace motostab::output
