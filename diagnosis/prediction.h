#pragma once
// Predictions of measured data by a scenario with typed parameter changes: labelled eigenvalues at
// the measured speeds and output-error fits of the linear free responses.
//
// The scenario is read once (scenario/scenario_source.h); each prediction applies its changes to a
// copy of the parsed tree. Its linear models come from the sweep's own chain at the needed speeds
// (analysis/sweep.h runSweep: warm-started trims in speed order, grouped and mirrored columns, modes
// tracked and labelled as a sweep's); a row's mode is then found among the candidate's branches of
// that label (diagnosis/mode_matching.h). A row with a speed range [a, b] (the speed fell during the
// fit window) is predicted by the mean of the model's eigenvalue over the range, by two-point
// Gauss-Legendre quadrature (diagnosis/speed_nodes.h). A response run with a speed trace is fitted with
// the speed varying along it (diagnosis/free_response.h).
//
// Fast predictions (predict with exact = false, used inside fits): labelled rows are interpolated
// from the model's eigenvalues at Chebyshev points spanning the labelled rows' speeds, when that needs
// fewer linearisations than the rows' own speeds: the fewest points (5 to 16) that reproduce the base
// scenario's labelled modes at its reference sweep's speeds to 3e-4 (1 + |lambda|) 1/s. Reported
// predictions are exact (exact = true), so a sweep of the extended scenario reproduces them.
//
// Predictors of one diagnosis may share a SweepCache (diagnosis/sweep_cache.h): a chain asked for again
// with the same changes and speeds (and the reference sweep and node choice of a rerun on the same
// rows) is taken from it, identical to the bit to a new evaluation.
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "analysis/sweep.h"
#include "diagnosis/controller_groups.h"
#include "diagnosis/free_response.h"
#include "diagnosis/measured_data.h"
#include "diagnosis/mode_matching.h"
#include "diagnosis/noise_model.h"
#include "diagnosis/speed_nodes.h"
#include "diagnosis/sweep_cache.h"
#include "scenario/scenario_source.h"

namespace motostab::diagnosis {

/// Everything a scenario predicts for a measurement set.
struct Prediction {
  /// Per measured row, then per probe row of the findings (makeProbeRows), imag >= 0, 1/s.
  std::vector<std::complex<double>> eigenvalues;
  std::vector<ResponseFit> responses;            ///< per run
  int numLinear = 0;                             ///< sum over runs of ResponseFit::numLinear
};

/// Predicts measured data for a scenario with parameter changes. Thread-safe: predict() builds its
/// own model on each chain it computes (or takes the chain from the shared cache).
class Predictor {
 public:
  /// Sweeps the base scenario (`baseChanges` applied) once for the mode labels. Data taken with
  /// several controller settings is predicted group by group (diagnosis/controller_groups.h), each
  /// group by a predictor of its own whose base changes end with the group's. `cache` (optional, for
  /// predictors of one `source` only) keeps and shares the chains computed. Data without eigenvalue
  /// rows and response runs: std::logic_error (there is nothing to sweep for).
  Predictor(std::shared_ptr<const scenario::ScenarioSource> source, scenario::ParameterOverrides baseChanges, const MeasuredData& data,
            std::shared_ptr<SweepCache> cache = nullptr);
  /// The same, reading `scenarioFile` (once).
  Predictor(const std::string& scenarioFile, scenario::ParameterOverrides baseChanges, const MeasuredData& data);
  /// Predictions with `changes` after the base changes; `sigma` per response run and signal.
  /// `noise` per run and signal (optional): AR noise prewhitening the response fits.
  Prediction predict(const scenario::ParameterOverrides& changes, const std::vector<std::vector<double>>& sigma,
                     bool exact = true, const std::vector<std::vector<ArNoise>>& noise = {}) const;
  /// The sweep's chain at `speeds` (sorted, unique; m/s) for `changes` (after the base changes only:
  /// no controller setting of the data is added here): linear models with labelled modes.
  analysis::SweepResult calcSweep(const scenario::ParameterOverrides& changes, const std::vector<double>& speeds) const;
  /// The linear models of calcSweep.
  std::vector<analysis::LinearModel> calcLinearModels(const scenario::ParameterOverrides& changes, const std::vector<double>& speeds) const;
  /// The sorted, unique speeds predict() linearises at, m/s.
  const std::vector<double>& getSpeeds() const { return speeds_; }
  const scenario::ScenarioSource& getSource() const { return *source_; }
  const scenario::ParameterOverrides& getBaseChanges() const { return baseChanges_; }
  const analysis::SweepResult& getReferenceSweep() const { return *reference_; }
  /// The Chebyshev points (m/s) of the fast predictions; empty when fits predict exactly.
  const std::vector<double>& getNodes() const { return nodes_; }

 private:
  struct ControllerPart {
    ControllerGroup group;
    std::unique_ptr<Predictor> predictor;
  };
  void makeControllerParts();
  std::vector<double> collectSpeeds() const;
  void makeReferenceSweep();
  /// calcSweep through the cache (when there is one).
  std::shared_ptr<const analysis::SweepResult> getSweep(const scenario::ParameterOverrides& changes,
                                                        const std::vector<double>& speeds) const;
  void chooseFastSpeeds();
  Prediction predictParts(const scenario::ParameterOverrides& changes, const std::vector<std::vector<double>>& sigma,
                          bool exact, const std::vector<std::vector<ArNoise>>& noise) const;
  std::vector<std::complex<double>> predictRows(const analysis::SweepResult& sweep, bool fast) const;
  std::vector<std::complex<double>> predictInterpolated(const analysis::SweepResult& sweep) const;
  std::vector<double> chooseNodes(double lo, double hi, int labelled) const;
  bool isExactMode(analysis::ModeLabel mode) const;
  std::vector<analysis::ModeLabel> findBranchPointModes(double lo, double hi) const;
  ResponseFit predictResponse(const analysis::SweepResult& sweep, size_t run, const std::vector<double>& sigma,
                              const std::vector<ArNoise>& noise) const;

  std::shared_ptr<const scenario::ScenarioSource> source_;
  scenario::ParameterOverrides baseChanges_;
  /// The data with the findings' probe rows appended to the eigenvalue rows (diagnosis/findings.h
  /// makeProbeRows), when it has findings; data_ refers to it then.
  std::shared_ptr<const MeasuredData> withProbes_;
  const MeasuredData& data_;
  std::vector<double> speeds_;
  std::vector<double> nodes_;       ///< Chebyshev points of the fast predictions (empty: none)
  std::vector<double> fastSpeeds_;  ///< speeds of the fast predictions (nodes, runs, rows not interpolated)
  /// Labelled modes whose base branch turns between real and complex over the rows' speeds (a
  /// branch point no polynomial follows): the fast predictions take them at the rows' own speeds.
  std::vector<analysis::ModeLabel> exactModes_;
  std::shared_ptr<const analysis::SweepResult> reference_;
  std::shared_ptr<SweepCache> cache_;
  std::unique_ptr<ModeMatcher> matcher_;
  std::vector<std::shared_ptr<ControllerPart>> parts_;  ///< per controller setting (empty: one setting)
};

}  // namespace motostab::diagnosis
