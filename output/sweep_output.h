#pragma once
// Files written by `motostab sweep` and `motostab linearize`.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/sweep.h"
#include "nlohmann/json.hpp"

namespace motostab::output {

/// Frequency imag/(2 pi) in Hz and damping ratio -real/|lambda| (seed eq. 27; NaN for lambda = 0).
double calcFrequencyHz(std::complex<double> lambda);
double calcDampingRatio(std::complex<double> lambda);

/// The modes the sweep plots draw, in their order (weave, capsize, castor, wobble).
std::vector<std::string> getPlottedModes();

/// DIR/eigenvalues.csv and DIR/summary.json only.
void writeSweepData(const std::filesystem::path& dir, const std::string& scenarioName, const analysis::SweepResult& sweep);

/// DIR/eigenvalues.csv (speed_mps,mode,real,imag,frequency_hz,damping_ratio; 17 digits),
/// DIR/summary.json (critical speeds, stable ranges), the root locus, and real_part_vs_speed: the
/// eigenvalues against speed as in Meijaard et al. (2007) Fig. 3 (real parts solid, imaginary parts in
/// rad/s dashed), each critical speed a labelled vertical line, the stable ranges shaded
/// (calcStableSpeedRanges), or a note that there is none; each plot with its gnuplot script.
void writeSweepOutputs(const std::filesystem::path& dir, const std::string& scenarioName, const analysis::SweepResult& sweep);

/// The summary as JSON: critical speeds per mode and the speed ranges where all modes are stable, on the
/// grid (stable_grid_ranges_mps) and bounded by the critical speeds (stable_speed_ranges_mps).
nlohmann::json makeSweepSummary(const std::string& scenarioName, const analysis::SweepResult& sweep);

/// A readable table of the labelled eigenvalues at about `rows` speeds, and the critical speeds.
std::string formatSweepTable(const analysis::SweepResult& sweep, int rows = 11);

/// DIR/A.csv, DIR/B.csv (named rows and columns), DIR/eigenvalues.csv (index,mode,real,imag,
/// frequency_hz,damping_ratio), DIR/eigenvectors.csv and DIR/linear_model.json (speed_mps, roll_rad,
/// heading_frame: true about a steady turn, states, inputs, A, B, eigenvalues). modeLabels[k] names
/// eigenvalue k's mode (e.g. the labels trackModes gives this one model); one per eigenvalue, else
/// std::logic_error.
void writeLinearModel(const std::filesystem::path& dir, const analysis::LinearModel& lin, const std::vector<std::string>& modeLabels);

}  // namespace motostab::output
