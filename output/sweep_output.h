#pragma once
// Files written by `motostab sweep` and `motostab linearize`.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/sweep.h"
#include "output/plot_window.h"
#include "nlohmann/json.hpp"

namespace motostab::output {

/// Frequency imag/(2 pi) in Hz and damping ratio -real/|lambda| (seed eq. 27; NaN for lambda = 0).
double calcFrequencyHz(std::complex<double> lambda);
double calcDampingRatio(std::complex<double> lambda);

/// The modes the sweep plots draw, in their order (weave, capsize, castor, wobble).
std::vector<std::string> getPlottedModes();

/// gnuplot labels and arrows marking the speed along the root loci of `modes`: at `count` evenly
/// spaced speeds of the grid, a circle with the speed (m/s) on each mode's upper root and an arrowhead
/// along its step to the next speed. Points outside `window`, and points within 3 % of the axes of a
/// mark already placed (modes in the order given, speeds ascending), are not marked. Label and arrow tags
/// are numbered from `firstTag`.
std::string makeSpeedMarks(const analysis::SweepResult& sweep, const std::vector<analysis::ModeLabel>& modes,
                           const LocusWindow& window, int firstTag, int count = 5);

/// DIR/eigenvalues.csv and DIR/summary.json only.
void writeSweepData(const std::filesystem::path& dir, const std::string& scenarioName, const analysis::SweepResult& sweep);

/// DIR/eigenvalues.csv (speed_mps,mode,real,imag,frequency_hz,damping_ratio; 17 digits; mode: the
/// root's label at that speed), DIR/summary.json (critical speeds, stable ranges, failed speeds), the root locus, and real_part_vs_speed: the
/// eigenvalues against speed as in Meijaard et al. (2007) Fig. 3 (real parts solid, imaginary parts in
/// rad/s dashed), each critical speed a labelled vertical line, the stable ranges shaded
/// (calcStableSpeedRanges), or a note that there is none; each plot with its gnuplot script. Both plots
/// are scaled to the plotted modes (calcLocusWindow, calcAxisRange); the other roots are drawn grey
/// and the legend counts those off the axes. The root locus marks the speed (makeSpeedMarks).
void writeSweepOutputs(const std::filesystem::path& dir, const std::string& scenarioName, const analysis::SweepResult& sweep);

/// The summary as JSON: every critical speed (mode, speed, direction, frequency, refined), the first of
/// each lateral mode, the speed ranges where all modes are stable, on the grid (stable_grid_ranges_mps)
/// and bounded by the critical speeds (stable_speed_ranges_mps), and the speeds that did not trim.
nlohmann::json makeSweepSummary(const std::string& scenarioName, const analysis::SweepResult& sweep);

/// A readable table at about `rows` speeds: a column per named mode (the lateral and compliance modes
/// and any mode with a critical speed), "absent" where no root has it; then the critical speeds, the
/// stable ranges and the speeds that did not trim.
std::string formatSweepTable(const analysis::SweepResult& sweep, int rows = 11);

/// DIR/A.csv, DIR/B.csv (named rows and columns), DIR/eigenvalues.csv (index,mode,real,imag,
/// frequency_hz,damping_ratio), DIR/eigenvectors.csv and DIR/linear_model.json (speed_mps, roll_rad,
/// heading_frame: true about a steady turn, states, inputs, A, B, eigenvalues, modes: each eigenvalue's
/// label and, given `contents` (calcModeContents of lin), its shares by state role). lin.labels names
/// each eigenvalue's mode; one per eigenvalue, else std::logic_error.
void writeLinearModel(const std::filesystem::path& dir, const analysis::LinearModel& lin,
                      const std::vector<analysis::ModeContent>& contents = {});

}  // namespace motostab::output
