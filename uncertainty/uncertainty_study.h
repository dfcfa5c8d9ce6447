#pragma once
// Uncertainty of stability: the scenario's `uncertainty:` section (parameter standard deviations)
// propagated to the labelled sweep and critical speeds by sampling.
//
// Work is a list of tasks, each one full serial sweep (trim, linearise, track, label, Brent-refined
// critical speeds; analysis/sweep.h): the nominal scenario, 2P central-difference neighbours
// (parameter j at nominal +/- h sigma_j, for the first-order estimate
// std_1 = sqrt(sum_j (dv/dx_j)^2 sigma_j^2), i.e. J Sigma J^T with diagonal Sigma), then the samples.
//   mc:    sample i draws every parameter from (seed, i) (uncertainty/sampling.h).
//   sobol: Saltelli's design (Saltelli et al. 2010, Comput. Phys. Commun. 181:259, Table 2): base rows
//          A_j = draw (seed, 2j), B_j = draw (seed, 2j+1) and, per parameter i, A_j with column i from
//          B_j; N rows give N (P + 2) sweeps; first-order indices by Jansen's estimator.
// A draw that leaves the physical range (the loader or the model rejects it: negative mass, inertia
// not positive definite or violating the triangle inequality, a plugin's range) is redrawn with the
// next attempt counter, up to maxAttempts; redraws are counted. A sweep that fails (trim does not
// converge) marks its task failed with the reason; the study goes on.
// Each task depends only on (scenario, seed, task index): results are identical to the bit for any
// split of the tasks over threads or MPI ranks.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "analysis/mode_label.h"
#include "scenario/scenario.h"
#include "scenario/scenario_source.h"

namespace motostab::uncertainty {

/// Critical speeds reported per sample: the first crossing of each mode in the speed range.
constexpr std::array<analysis::ModeLabel, 3> kUncertainModes{analysis::ModeLabel::Weave, analysis::ModeLabel::Capsize,
                                                              analysis::ModeLabel::Wobble};
/// Modes whose real part and frequency are kept per speed (fan charts).
constexpr std::array<analysis::ModeLabel, 4> kFanModes{analysis::ModeLabel::Weave, analysis::ModeLabel::Capsize,
                                                       analysis::ModeLabel::Wobble, analysis::ModeLabel::Castor};

enum class SamplingMethod { MonteCarlo, Sobol };

struct UncertaintyOptions {
  SamplingMethod method = SamplingMethod::MonteCarlo;
  size_t samples = 1000;       ///< mc: samples; sobol: base rows N
  uint64_t seed = 1;
  double start = 0, stop = 10, step = 0.1;  ///< speed grid, m/s
  int maxAttempts = 100;       ///< draws per sample before it is recorded as unphysical
  double derivativeStep = 0.5; ///< h of the first-order central differences, in standard deviations
};

/// One uncertainty study: the scenario, its overrides, the uncertain parameters and their nominal values.
struct UncertaintySetup {
  std::string scenarioFile;
  std::shared_ptr<const scenario::ScenarioSource> source;  ///< the scenario file, read once for every sample
  scenario::ParameterOverrides overrides;   ///< --set changes, applied before every sample's own
  std::vector<scenario::ParameterUncertainty> params; ///< the scenario's uncertainty section (sigma >= 0)
  std::vector<double> nominal;              ///< nominal value of each parameter (its unit)
  UncertaintyOptions options;
};

/// Loads the scenario (with overrides), checks it builds, and reads the parameters' nominal values.
/// InputError for a bad scenario or an empty uncertainty section.
UncertaintySetup prepareUncertainty(const std::string& scenarioFile, const scenario::ParameterOverrides& overrides,
                                    const UncertaintyOptions& options);
/// The same from a scenario source already read.
UncertaintySetup prepareUncertainty(std::shared_ptr<const scenario::ScenarioSource> source,
                                    const scenario::ParameterOverrides& overrides, const UncertaintyOptions& options);

enum class TaskKind { Nominal, Plus, Minus, Sample, SobolA, SobolB, SobolAB };

/// Task t of the study: kind, row (sample or Sobol row) and parameter (Plus/Minus/SobolAB).
struct UncertaintyTask {
  TaskKind kind = TaskKind::Nominal;
  size_t row = 0;
  int param = -1;
};

/// Number of tasks: 1 + 2P + samples (mc) or 1 + 2P + N (P + 2) (sobol).
size_t getTaskCount(const UncertaintySetup& setup);
UncertaintyTask getTask(const UncertaintySetup& setup, size_t t);

/// The result of one task.
struct TaskResult {
  bool ok = false;
  std::string reason;                ///< why it failed (empty when ok)
  int redraws = 0;                   ///< unphysical draws replaced
  std::vector<double> parameters;    ///< the values used, one per parameter
  std::array<double, kUncertainModes.size()> firstCrossing;  ///< m/s, NaN where the mode does not cross
  std::string crossings;             ///< every crossing: "mode@speed(+|-)" separated by ';', + destabilising
  /// Per fan mode m, speed k: real part (1/s) at [2 (m n + k)], frequency (Hz) at [2 (m n + k) + 1];
  /// of the mode's least stable eigenvalue with imag >= 0; NaN where the mode is absent.
  std::vector<double> modeValues;
};

/// Length of TaskResult::modeValues: 2 x fan modes x speeds of the grid.
size_t getModeValueCount(const UncertaintySetup& setup);

/// Runs task t (one serial sweep).
TaskResult runTask(const UncertaintySetup& setup, size_t t);

/// Runs tasks `indices` on `threads` threads (each task builds its own model; results in the order of
/// `indices`). `progress(done)` is called from worker threads after each task, if set.
std::vector<TaskResult> runTasks(const UncertaintySetup& setup, const std::vector<size_t>& indices, int threads,
                                 const std::function<void(size_t)>& progress = {});

}  // namespace motostab::uncertainty
