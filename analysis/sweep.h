#pragma once
// Linear stability sweep over forward speed: trim, linearise, label and track modes, and find
// the stability boundaries (critical speeds) by root bracketing.
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "analysis/modes.h"

namespace motostab::analysis {

struct SweepOptions {
  /// Sweeps use second-order differences (step 3e-6) at half the cost of the fourth-order default:
  /// worst eigenvalue error 1.2e-9 on the Whipple benchmark (Table 2), and 1.3e-9 relative to the
  /// fourth-order linearisation on the enduro with grouped columns (step 1e-5: 4e-10 and 1.5e-8,
  /// the grouped columns' cross third derivatives dominating).
  SweepOptions() {
    linearize.computeCyclicColumns = false;
    linearize.order = 2;
    linearize.step = 3e-6;
    linearize.computeB = false;
  }
  double start = 0, stop = 10, step = 0.1;  ///< m/s
  TrimOptions trim;
  LinearizeOptions linearize;
  double criticalSpeedTolerance = 1e-9;  ///< m/s
  /// Evaluate structurally orthogonal columns of A together (calcColumnGrouping), with the pattern
  /// of the reference speed and each worker's first two speeds. Eigenvalues agree with column-by-
  /// column differences to the difference error (tests/analysis/sweep_grouping_test.cpp).
  bool groupColumns = true;
  /// With groupColumns, on a laterally symmetric vehicle without constraints (checkMirrorSymmetry,
  /// at each worker's second speed) lateral groups take one evaluation instead of two, at every
  /// speed whose trim is symmetric.
  bool mirrorLateralColumns = true;
  /// Worker threads. Each worker builds its own model from the scenario (no shared Simbody
  /// caches) and trims a chain of speeds with warm starts, two workers sharing a span of speeds
  /// from both ends. Where they meet depends on timing, so threaded results equal the serial
  /// sweep's (and each other's) to the trim tolerance (eigenvalues within about 1e-8 relative),
  /// not bit for bit; threads = 1 is reproducible to the bit.
  int threads = 1;
  /// Bracket the critical speeds.
  bool findCriticalSpeeds = true;
  /// A speed whose trim fails is left out and listed in SweepResult::failures (the sweep goes on from
  /// the last trimmed speed) instead of failing the sweep; the sweep fails only when no speed trims.
  bool keepFailedSpeeds = false;
  /// A trim (of any roll: the step to trim.roll is a continuation) that starts the lead chain's first
  /// speed instead of a cold trim, e.g. the neighbouring roll's trim at that speed in a map.
  const TrimPoint* warmStart = nullptr;
};

/// A speed where a root's real part changes sign.
struct CriticalSpeed {
  ModeLabel mode = ModeLabel::Other;  ///< the root's label at the critical speed (labelModes there)
  double speed = 0;                    ///< m/s
  bool stabilising = false;            ///< real part goes from + to - as speed rises
  double frequency = 0;                ///< |imaginary part| / 2 pi at the critical speed, Hz
  /// By Brent's method to SweepOptions::criticalSpeedTolerance; false: interpolated linearly between
  /// the grid speeds, because a speed between them did not trim (SweepOptions::keepFailedSpeeds).
  bool refined = true;
};

/// A speed of the grid whose trim failed (SweepOptions::keepFailedSpeeds).
struct FailedSpeed {
  double speed = 0;      ///< m/s
  double residual = 0;   ///< the trim residual's infinity norm when it stopped
  std::string message;   ///< the trim's error message
};

struct SweepResult {
  std::vector<double> speeds;    ///< the speeds that trimmed, ascending
  std::vector<TrimPoint> trims;  ///< restoreTrim() gives a warm start from one
  std::vector<LinearModel> models;
  std::vector<ModeBranch> branches;
  std::vector<CriticalSpeed> criticalSpeeds;  ///< ascending speed
  std::vector<FailedSpeed> failures;          ///< speeds of the grid left out, ascending
};

/// The speeds start, start+step, ..., stop, m/s (stop included when it falls on the grid within 1e-9 of
/// a step). Throws std::logic_error (a caller's bug: the readers check user grids with
/// scenario::countSpeeds) unless start <= stop, step > 0 and there are at most 1e6 steps.
std::vector<double> makeSpeedGrid(double start, double stop, double step);

/// Trims and linearises at every speed (each trim warm-started from the previous one), labels and
/// tracks the modes, and brackets every sign change of a root's real part to the tolerance (neutral
/// roots excepted), naming each by its root's label at the critical speed.
SweepResult runSweep(const vehicle::VehicleModel& model, const SweepOptions& options);

/// The same at the given speeds (sorted, unique, m/s; options.start, stop and step unused), e.g. the
/// speeds of measured data: one chain of warm-started trims with the sweep's column grouping and
/// mirrored lateral columns, and its modes tracked and labelled as a sweep's.
SweepResult runSweep(const vehicle::VehicleModel& model, const std::vector<double>& speeds, const SweepOptions& options);

/// Recomputes sweep.criticalSpeeds from the branches; `options` as the sweep was run with.
void updateCriticalSpeeds(const vehicle::VehicleModel& model, const SweepOptions& options, SweepResult& sweep);

/// A stable speed range, m/s (closed).
struct StableRange {
  double start = 0, stop = 0;
};

/// The runs of grid speeds (m/s, first and last grid speed of each run) where every branch but the
/// neutral ones has a negative real part (a NaN real part counts as not stable).
std::vector<StableRange> calcStableGridRanges(const SweepResult& sweep);

/// The speed ranges where the vehicle is stable: every branch but the neutral ones has a negative
/// real part (Meijaard et al. 2007, sec. 6: the weave-to-capsize range of the benchmark bicycle).
/// Each run of stable grid speeds is widened to the critical speeds that bound it (the nearest one in
/// the grid interval on either side; none there, i.e. a sweep end: the run's own end speed). A range
/// narrower than the grid step that holds no grid speed is not found. Empty when no grid speed is stable.
std::vector<StableRange> calcStableSpeedRanges(const SweepResult& sweep);

/// The eigenvalue continuing `branch` from sweep speed index k to speed v (1/s), and with `withLabel`
/// its label there (labelModes: the cost of the rate mass matrix and the energy shares).
struct RootAtSpeed {
  std::complex<double> lambda;
  std::optional<ModeLabel> label;
};
RootAtSpeed calcBranchRoot(const vehicle::VehicleModel& model, const SweepResult& sweep, const ModeBranch& branch, size_t k,
                           double v, const SweepOptions& options, bool withLabel = true);

/// Real part of the eigenvalue continuing `branch` from sweep speed index k, at speed v (1/s).
double calcBranchRealPart(const vehicle::VehicleModel& model, const SweepResult& sweep, const ModeBranch& branch, size_t k,
                          double v, const SweepOptions& options);

}  // namespace motostab::analysis
