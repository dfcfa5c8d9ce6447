#pragma once
// motostab diagnose: what a scenario gets wrong against measured data, which candidate
// change explains it, the extended scenario and the gain.
//
// Residuals r = (measured - predicted) / sigma: per eigenvalue row its real part and, for a complex
// pair, its imaginary part; per response signal each sample. sigma is the row's stderr or the
// signal's noise_std when given, else one per component (mode.real, mode.imag, run.column) estimated
// at each step from the best candidate's fit (RSS / (n - k)), not the baseline's. chi2 = sum r^2 plus
// the priors (Student-t, diagnosis/priors.h) of fitted scenario parameters; response signals whose
// noise is estimated are prewhitened by their AR(p) noise (diagnosis/noise_model.h). Models are compared by their
// deviance -2 ln L, in which the noise of each unestimated component is profiled out for that model
// (n_c ln(RSS_c / n_c)): a candidate is never judged with the noise fitted to another model's
// residuals, which with a few rows per component lets a flexible model trade misfit between
// components. BIC = deviance + k ln n (Schwarz 1978), k = fitted parameters including the responses' initial
// states, offsets and free gains. Likelihood ratio: deviance_base - deviance_cand against chi-square with as
// many degrees of freedom as the candidate adds, halved (the 50:50 mixture of chi2_0 and chi2_1, Self
// & Liang 1987) when "effect off" sits at a bound. Cross-validation: the measurement units
// (eigenvalue rows and response runs) sorted by speed and cut into K blocks; each block is predicted
// from a fit to the others (every parameter refitted; a run's initial state, offsets and gains are
// fitted on the run itself), for every candidate of the first step.
#include <functional>
#include <string>
#include <vector>

#include "diagnosis/candidates.h"
#include "diagnosis/measured_data.h"
#include "diagnosis/prediction.h"

namespace motostab::diagnosis {

struct DiagnosisOptions {
  std::vector<std::string> candidates;  ///< names or globs; empty: all
  int maxCauses = 3;
  int folds = 0;                         ///< 0: 5, or one per run for response-only data
  int threads = 1;
  std::vector<std::string> overrides;    ///< --set on the base scenario
  /// Called as work proceeds: stage name, done, total.
  std::function<void(const std::string&, int, int)> progress;
  // Evidence needed to name a cause.
  double minBicDrop = 10;
  double maxPValue = 0.01;
  double minFoldShare = 0.8;
  double maxCorrelation = 0.95;
  double indistinguishableBic = 2;
  /// A candidate meeting every criterion whose change of the residuals correlates with the named
  /// cause's above this is listed with it as indistinguishable (swingarm bending vs twist).
  double maxPredictionCorrelation = 0.95;
  /// Rerun the stepwise search on each variant of the data (diagnosis/robustness.h).
  bool robustness = false;
};

struct ParameterEstimate {
  std::string name, path;
  double value = 0, stderr_ = 0;        ///< key unit
  double profileLow = 0, profileHigh = 0;  ///< 95 % profile-likelihood interval (causes only; else equal to value)
  bool hasProfile = false;
  double priorSigma = 0;                ///< measured parameter's sigma (0: none)
  double priorMean = 0;                 ///< its measured value
  bool priorMeasured = false;           ///< priorSigma is the scenario's `uncertainty:` sigma (not the default)
  double sigmas = 0;                    ///< (value - prior mean) / priorSigma
  bool atBound = false;
};

/// One model's fit at a step: the current causes plus a candidate (or none: the baseline).
struct FitSummary {
  std::string name;                           ///< candidate name; "baseline" for the current model
  std::vector<ParameterEstimate> parameters;  ///< the candidate's own
  std::vector<ParameterEstimate> allParameters;  ///< causes' and candidate's
  Eigen::MatrixXd correlation;                ///< of all fitted parameters
  double chi2 = 0, rms = 0, cvRms = 0, bic = 0, deltaBic = 0, pValue = 1;
  double deviance = 0;                        ///< -2 ln L, unknown noise profiled out (FitProblem::calcDeviance)
  std::vector<double> foldRms;                ///< per fold
  std::vector<bool> foldFailed;               ///< per fold: its fit failed or diverged (cross_validation.h)
  std::vector<std::string> foldFailures;      ///< "fold k: reason" of each failed fold
  int foldsBetter = 0;
  bool hasCv = false, atBound = false, converged = true;
  Eigen::MatrixXd jacobian;                   ///< of the full fit's residuals (data, then priors) in x
  std::vector<std::string> failed;            ///< criteria not met
  int numParameters = 0;                      ///< k of BIC
  /// Moves a measured parameter by more than kContradictionSigmas sigma (diagnosis/priors.h).
  bool contradictsMeasurement = false;
  Eigen::VectorXd x;                          ///< internal coordinates
};

struct ComponentResidual {   ///< residuals of one mode (eigenvalues) or signal (responses)
  std::string name;          ///< weave, capsize, run1.roll_rate_radps, ...
  int count = 0;
  double meanReal = 0, meanImag = 0;          ///< mean measured - predicted (1/s, rad/s; column unit)
  double rmsReal = 0, rmsImag = 0;            ///< normalised by sigma
  double slopeRealPerMps = 0, slopeStderr = 0, slopeP = 1;  ///< trend of the real residual vs speed
  double vafBefore = 0, vafAfter = 0;         ///< responses: % variance accounted for
};

struct Cause {
  FitSummary fit;
  std::vector<FitSummary> indistinguishable;
};

struct NoiseLevel {
  std::string component;
  double sigma = 0;       ///< 1/s, rad/s or column unit; the innovation sigma of AR noise
  bool estimated = true;  ///< false: from stderr columns or noise_std
  std::vector<double> ar; ///< AR coefficients phi_1..phi_p of a response signal's noise (noise_model.h); empty: white
  double marginalSigma = 0;  ///< sigma of the noise itself (equal to sigma when white)
};

/// The causes the stepwise search names on one variant of the data (diagnosis/robustness.h).
struct RobustnessRun {
  std::string leftOut;
  std::vector<std::string> causes;          ///< names, in the order named
  std::vector<FitSummary> fits;             ///< their fits (estimates before the final refit)
  bool sameCauses = false;                  ///< the same causes as on all the data
  std::string error;                        ///< the search failed on this variant (then causes is empty)
};

struct DiagnosisResult {
  std::string scenarioFile;
  const MeasuredData* data = nullptr;
  int numObservations = 0, numFolds = 0;
  FitSummary baseline, extended;               ///< the base model and the model with every cause
  std::vector<FitSummary> candidates;          ///< first step's, best (lowest BIC) first
  std::vector<Cause> causes;
  /// Candidates that met every criterion but "fit, but contradict the measurement" and were not
  /// named (diagnosis/priors.h), with the step they were found at.
  std::vector<FitSummary> contradicting;
  std::vector<RobustnessRun> robustness;      ///< empty unless DiagnosisOptions::robustness
  /// Some variant names other causes (or fails): the causes are fragile.
  bool isFragile() const;
  std::vector<ComponentResidual> residualsBefore, residualsAfter;
  std::vector<NoiseLevel> noise;
  std::vector<std::string> unavailable;        ///< candidates this build or scenario cannot apply, with why
  std::vector<std::string> extendedOverrides;  ///< the overrides that make extended.yaml
  Prediction before, after;
  std::vector<double> sigma;                   ///< per observation
  std::vector<double> observed;                ///< per observation
  std::vector<std::string> observationComponent;
  std::vector<double> predictedBefore, predictedAfter;  ///< per observation
  std::vector<double> observationSpeed;               ///< m/s
  std::vector<double> observationTime;                ///< s (responses), NaN for eigenvalues
  std::vector<int> observationRow, observationPart;   ///< eigenvalue row (-1: response) and part (0 real, 1 imag)
  std::vector<int> observationRun, observationSignal; ///< response run (-1: eigenvalue) and signal
};

/// Runs the whole diagnosis.
DiagnosisResult runDiagnosis(const std::string& scenarioFile, const MeasuredData& data, const DiagnosisOptions& options);

/// The base scenario's YAML tree with `overrides` applied (what extended.yaml holds).
YAML::Node makeScenarioTree(const std::string& scenarioFile, const std::vector<std::string>& overrides);

}  // namespace motostab::diagnosis
