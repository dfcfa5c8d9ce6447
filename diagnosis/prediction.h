#pragma once
// Predictions of measured data by a scenario (with --set overrides): labelled eigenvalues at the
// measured speeds and output-error fits of the linear free responses.
//
// Eigenvalues: the scenario is trimmed and linearised (the sweep's options: analysis/sweep.h) at each
// needed speed, in increasing order with warm starts. A row's mode is matched at each speed by the
// sum of two match costs (analysis/modes.h calcMatchCost): against the base scenario's labelled branch
// at the nearest sweep speed, and against the mode's eigenvalue at the previous speed of the model
// being predicted (the candidate), so that the match follows the candidate's own modes by continuity
// where a large change (a strong steer damper) moves them away from the base's; a row without a label takes the eigenvalue (imag >= 0) nearest the measured one. A row with a
// speed range [a, b] (the speed fell during the fit window) is predicted by the mean of the model's
// eigenvalue over the range, by two-point Gauss-Legendre quadrature at m -/+ h/sqrt(3) (m, h: the
// range's middle and half width; exact for a cubic in speed).
//
// Fast predictions (predict with exact = false, used inside fits): labelled rows are interpolated
// from the model's eigenvalues at Chebyshev points of the second kind spanning the labelled rows'
// speeds (barycentric formula, Berrut & Trefethen 2004, SIAM Review 46:501), when that needs fewer
// linearisations than the rows' own speeds: the fewest points (5 to 16) that reproduce the base
// scenario's labelled modes at its reference sweep's speeds to 3e-4 (1 + |lambda|) 1/s. Reported
// predictions are exact (exact = true), so a sweep of the extended scenario reproduces them.
//
// Responses: x' = A x at the run's speed, y_j(t) = g_j c_j x(t) + o_j, x(t) = exp(A (t - t0)) x0
// (t0: the window's first sample). The initial state x0 and the offsets o_j enter linearly; the free
// gains g_j (scale: free) make the fit bilinear, solved by alternating least squares (a nested fit:
// x0 and offsets by minimum-norm least squares for fixed gains, then each free gain with its offset),
// to a relative change of the weighted residual below 1e-13. With no calibrated signal the first
// free gain is 1 (the overall scale is in x0). Calibrated: g_j = 1/scale.
#include <Eigen/Dense>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "analysis/sweep.h"
#include "diagnosis/controller_groups.h"
#include "diagnosis/measured_data.h"
#include "diagnosis/noise_model.h"

namespace motostab::diagnosis {

/// The fitted free response of one run.
struct ResponseFit {
  std::vector<std::vector<double>> predicted;  ///< per signal, per sample (column unit)
  Eigen::VectorXd initialState;                ///< x0 in the linear model's states
  std::vector<double> gains, offsets;          ///< per signal (column unit per rad(/s); column unit)
  std::vector<double> vaf;                     ///< per signal, % (100 (1 - var(residual)/var(signal)))
  int numLinear = 0;                           ///< fitted linear/bilinear parameters (x0, offsets, free gains)
};

/// Everything a scenario predicts for a measurement set.
struct Prediction {
  std::vector<std::complex<double>> eigenvalues;  ///< per measured row (imag >= 0), 1/s
  std::vector<ResponseFit> responses;            ///< per run
  int numLinear = 0;                             ///< sum over runs of ResponseFit::numLinear
};

/// Fits one run's free response for a linear model (A at the run's speed). `sigma` per signal
/// (column unit, the noise's marginal sigma) weights the signals; `noise` per signal (optional): its
/// AR noise, which prewhitens the fit (generalised least squares, noise_model.h). Throws InputError
/// (at the run) if a signal's quantity is not a state of the model.
ResponseFit fitFreeResponse(const analysis::LinearModel& lin, const ResponseRun& run, const std::vector<double>& sigma,
                            const std::vector<ArNoise>& noise = {});

/// Predicts measured data for a scenario file with overrides. Thread-safe: predict() builds its own
/// model on each call.
class Predictor {
 public:
  /// Sweeps the base scenario (`overrides` applied) once for the mode labels. Data taken with several
  /// controller settings is predicted group by group (diagnosis/controller_groups.h), each group by a
  /// predictor of its own whose base overrides end with the group's.
  Predictor(std::string scenarioFile, std::vector<std::string> baseOverrides, const MeasuredData& data);
  /// Predictions with `overrides` added to the base overrides; `sigma` per response run and signal.
  /// `noise` per run and signal (optional): AR noise prewhitening the response fits.
  Prediction predict(const std::vector<std::string>& overrides, const std::vector<std::vector<double>>& sigma,
                     bool exact = true, const std::vector<std::vector<ArNoise>>& noise = {}) const;
  /// Linear models at `speeds` (sorted, unique; m/s) for `overrides` (after the base overrides only:
  /// no controller setting of the data is added here).
  std::vector<analysis::LinearModel> calcLinearModels(const std::vector<std::string>& overrides, const std::vector<double>& speeds) const;
  /// The sorted, unique speeds predict() linearises at, m/s.
  const std::vector<double>& getSpeeds() const { return speeds_; }
  const std::string& getScenarioFile() const { return scenarioFile_; }
  const std::vector<std::string>& getBaseOverrides() const { return baseOverrides_; }
  const analysis::SweepResult& getReferenceSweep() const { return *reference_; }
  /// The Chebyshev points (m/s) of the fast predictions; empty when fits predict exactly.
  const std::vector<double>& getNodes() const { return nodes_; }

 private:
  struct ControllerPart {
    ControllerGroup group;
    std::unique_ptr<Predictor> predictor;
  };
  Prediction predictParts(const std::vector<std::string>& overrides, const std::vector<std::vector<double>>& sigma,
                          bool exact, const std::vector<std::vector<ArNoise>>& noise) const;
  std::vector<std::complex<double>> predictInterpolated(const std::vector<analysis::LinearModel>& models,
                                                        const std::vector<double>& speeds) const;
  struct ModeTrack {
    std::string mode;
    std::vector<int> index;  ///< per model (-1: no such mode in the base sweep there)
  };
  std::vector<double> chooseNodes(double lo, double hi, int labelled) const;
  bool isExactMode(const std::string& mode) const;
  std::vector<std::string> findBranchPointModes(double lo, double hi) const;
  Eigen::VectorXd calcModeCosts(const std::string& mode, const analysis::LinearModel& lin, const analysis::LinearModel* prev,
                                int prevIndex) const;
  std::vector<ModeTrack> trackModes(const std::vector<analysis::LinearModel>& models) const;
  std::complex<double> pickEigenvalue(const std::vector<analysis::LinearModel>& models, size_t k, const MeasuredEigenvalue& row,
                                      const std::vector<ModeTrack>& tracks) const;

  std::string scenarioFile_;
  std::vector<std::string> baseOverrides_;
  const MeasuredData& data_;
  std::vector<double> speeds_;
  std::vector<double> nodes_;       ///< Chebyshev points of the fast predictions (empty: none)
  std::vector<double> fastSpeeds_;  ///< speeds of the fast predictions (nodes, runs, rows not interpolated)
  /// Labelled modes whose base branch turns between real and complex over the rows' speeds (a
  /// branch point no polynomial follows): the fast predictions take them at the rows' own speeds.
  std::vector<std::string> exactModes_;
  std::shared_ptr<analysis::SweepResult> reference_;
  std::vector<std::shared_ptr<ControllerPart>> parts_;  ///< per controller setting (empty: one setting)
};

/// The speeds at which a row is evaluated (one, or two Gauss-Legendre nodes of its range), m/s.
std::vector<double> getEvaluationSpeeds(const MeasuredEigenvalue& row);

}  // namespace motostab::diagnosis
