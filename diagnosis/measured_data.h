#pragma once
// Measured data for `motostab diagnose` (format: docs/measured-data-format.md): eigenvalues of
// labelled modes at measured speeds, and free-response runs with their signals. Signs are those of
// the design frame (ISO 8855): roll > 0 leans right, steer > 0 steers left, yaw rate > 0 turns left.
#include <optional>
#include <string>
#include <vector>

#include "analysis/mode_label.h"
#include "io/input_error.h"
#include "io/number.h"

namespace motostab::diagnosis {

/// One measured eigenvalue (one complex pair with imag >= 0, or a real eigenvalue with imag = 0).
struct MeasuredEigenvalue {
  double speed = 0;            ///< m/s (the middle of the speed range when one is given)
  double speedMin = 0, speedMax = 0;  ///< m/s; equal to speed without a range
  bool hasRange = false;
  std::optional<analysis::ModeLabel> mode;  ///< the row's mode (file: its name); none: the nearest eigenvalue
  double real = 0, imag = 0;   ///< 1/s, rad/s
  double realStderr = 0, imagStderr = 0;  ///< 0: unknown (estimated per model from its residuals)
  io::InputLocation where;         ///< file and line of the row
  /// `steer_controller.*` overrides in force for this row (its file's `controller:` mapping, then its
  /// `steer_controller.<key>` columns); empty: the scenario's own controller.
  std::vector<std::string> controller;
};

/// A measured quantity of a response signal (rad, rad/s).
enum class Quantity { RollAngle, RollRate, SteerAngle, SteerRate, YawRate };
/// "roll_angle", ... ; the inverse of parseQuantity.
std::string getQuantityName(Quantity q);

/// One signal of a response run.
struct ResponseSignal {
  std::string column;     ///< CSV column name
  Quantity quantity = Quantity::RollRate;
  bool freeScale = false; ///< uncalibrated: a gain is fitted (else the column is in rad or rad/s)
  double scale = 1;       ///< calibrated: factor to rad or rad/s
  double noiseStd = 0;    ///< in the column's unit; 0: estimated per model from its residuals
  std::vector<double> values;  ///< samples in the window, column unit
};

/// A free-response run (output-error fit of the linear free response at the run's speed).
struct ResponseRun {
  std::string file;       ///< resolved CSV path
  double speed = 0;       ///< m/s (given, or the mean of the speed column in the window)
  std::vector<double> time;  ///< s, samples in the window
  std::vector<double> speeds;  ///< m/s per sample: the speed column in the window (empty: speed_mps given)
  std::vector<ResponseSignal> signals;
  io::InputLocation where;    ///< the run's entry in the YAML file
  std::vector<std::string> controller;  ///< `steer_controller.*` overrides of its `controller:` mapping
};

/// What a paper, road test or rider reports of a mode without its eigenvalues
/// (docs/measured-data-format.md, Findings; likelihood: diagnosis/findings.h).
enum class FindingKind {
  Stable,           ///< the mode's real part is <= 0 over the speeds
  Unstable,         ///< the mode's real part is >= 0 over the speeds
  FrequencyWithin,  ///< its frequency |imag| / (2 pi) lies in [frequencyMin, frequencyMax] over the speeds
  MostStableNear,   ///< its real part is lowest over the speeds near `speed`
  ChangeBelow       ///< `change` moves its eigenvalue by less than `percent` % over the speeds
};

/// One finding with its stated tolerance.
struct Finding {
  FindingKind kind = FindingKind::Stable;
  analysis::ModeLabel mode{};                ///< the mode the finding is about
  double speedMin = 0, speedMax = 0;         ///< m/s, the speeds it holds over
  double frequencyMin = 0, frequencyMax = 0; ///< Hz (FrequencyWithin)
  double speed = 0;                          ///< m/s (MostStableNear)
  double percent = 0;                        ///< % (ChangeBelow)
  std::vector<std::string> change;           ///< `--set` overrides of the change (ChangeBelow)
  /// `--set` overrides of the model variant the finding is stated for (e.g. a swingarm compliance),
  /// applied before the change; empty: the scenario as it is.
  std::vector<std::string> variant;
  /// Scale of the likelihood term, in the finding's unit: 1/s (Stable, Unstable), Hz
  /// (FrequencyWithin), m/s (MostStableNear), percentage points (ChangeBelow).
  double tolerance = 0;
  std::string source;                        ///< where the finding is stated (free text)
  io::InputLocation where;                   ///< its entry in the YAML file
};

struct MeasuredData {
  std::string name;
  std::string file;       ///< the YAML file
  std::vector<MeasuredEigenvalue> eigenvalues;
  std::vector<ResponseRun> responses;
  std::vector<Finding> findings;
  std::vector<std::string> eigenvalueFiles;  ///< resolved CSV paths
  /// `steer_rate_amplitude_rad_s`: the steer-rate amplitude of the measured oscillations (rad/s), at
  /// which the steer_friction candidate's equivalent damping is taken; 0: not given.
  double steerRateAmplitude = 0;
};

/// Measured speeds lie in [0, kMaxMeasuredSpeed] m/s (540 km/h, beyond any measured two-wheeler: the
/// reference sweep spans the measured speeds in 0.1 m/s steps).
constexpr double kMaxMeasuredSpeed = 150;
/// Standard deviations (noise_std, stderr columns), signal scales and samples (in rad or rad/s) lie
/// within the magnitudes motostab computes with (io/number.h), so that the squares and inverse squares
/// weighting the fits stay finite.
constexpr double kMinStd = io::kMinMagnitude, kMaxStd = io::kMaxMagnitude;

/// Reads a measurement YAML file and every CSV it names (paths relative to it). Strict: an unknown
/// key, a missing file or column, a bad or non-finite cell, a speed outside [0, kMaxMeasuredSpeed], a
/// standard deviation outside [kMinStd, kMaxStd], a controller setting the scenario's steer_controller
/// section would refuse, an unknown mode label or quantity, or a response window with fewer than 20
/// samples is an InputError naming the file and line (and column for YAML). Findings are read as
/// diagnosis/findings.h readFindings says.
MeasuredData loadMeasuredData(const std::string& path);

/// Mode labels accepted in eigenvalue files: the names of analysis::ModeLabel (analysis/modes.h assigns them).
std::vector<std::string> getModeLabels();

}  // namespace motostab::diagnosis
