#pragma once
// motostab diagnose: what a scenario gets wrong against measured data, which candidate
// change explains it, the extended scenario and the gain.
//
// Residuals r = (measured - predicted) / sigma: per eigenvalue row its real part and, for a complex
// pair, its imaginary part; per response signal each sample. sigma is the row's stderr or the
// signal's noise_std when given, else one per component (mode.real, mode.imag, run.column) estimated
// for each model from its own residuals, response signals as AR(p) noise that prewhitens them
// (diagnosis/noise_model.h), fit and noise alternating (diagnosis/model_fit.h). chi2 = sum r^2 plus the
// priors (Student-t, diagnosis/priors.h) of fitted scenario parameters. Models are compared by their
// deviance -2 ln L with each unestimated component's noise profiled out (n_c ln(RSS_c / n_c)), each
// at its own maximised likelihood. BIC = deviance + k ln n (Schwarz 1978), k = fitted parameters
// including the responses' initial states, offsets, free gains and AR coefficients. Likelihood ratio,
// criteria and look-alikes: diagnosis/cause_criteria.h; the search: diagnosis/stepwise_search.h and
// diagnosis/pair_search.h; robustness: diagnosis/robustness.h. Cross-validation: the measurement units
// (eigenvalue rows and response runs) sorted by speed and cut into K blocks; each block is predicted
// from a fit to the others (every parameter refitted; a run's initial state, offsets and gains are
// fitted on the run itself).
#include <functional>
#include <memory>
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
  scenario::ParameterOverrides overrides;  ///< --set on the base scenario
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
  /// Cross-validate every first-step candidate for the report's table, also those failing a cheaper
  /// criterion (false: only those meeting the others, as in later steps; the causes do not change).
  bool candidateTableCv = true;
  /// When no single candidate qualifies, search pairs of the best singles (diagnosis/pair_search.h).
  bool pairSearch = true;
  /// Rerun the stepwise search on each variant of the data (diagnosis/robustness.h).
  bool robustness = false;
  /// Keep the linear models computed and take a chain asked for again (same changes, same speeds) from
  /// the store, across the search, folds, profiles and reruns (diagnosis/sweep_cache.h). The results
  /// are the same to the bit either way.
  bool reuseLinearModels = true;
  /// The store to use (e.g. to read its counters afterwards); none: a new one per diagnosis.
  std::shared_ptr<SweepCache> sweepCache;
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
  std::string note;                     ///< read the value with this (steer_friction: its steer-rate amplitude)
};

/// One model's fit at a step: the current causes plus a candidate (or none: the baseline).
struct FitSummary {
  std::string name;                           ///< candidate name; "baseline" for the current model
  std::vector<ParameterEstimate> parameters;  ///< the candidate's own
  std::vector<ParameterEstimate> allParameters;  ///< causes' and candidate's
  Eigen::MatrixXd correlation;                ///< of all fitted parameters
  /// rms: of the normalised data residuals, in the step baseline's noise (candidates) or the extended
  /// model's (baseline and extended of the result), so that RMS values compared share one noise.
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
  NoiseState noise;                           ///< the model's own noise estimate (diagnosis/model_fit.h)
  int numNoiseParameters = 0;                 ///< AR coefficients of that noise (counted in numParameters)
  std::vector<std::string> members;           ///< a pair's two candidates (diagnosis/pair_search.h); else empty
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
/// How a rerun's first cause compares with the full data's (diagnosis/robustness.h).
enum class RobustnessVerdict {
  Same,               ///< the same first cause, its values consistent within their intervals
  LostPower,          ///< names nothing where the full data named a cause: less data, not a contradiction
  Indistinguishable,  ///< names a candidate the full data listed as indistinguishable from its cause
  OtherCause,         ///< names another cause (or one where the full data named none): fragile
  ValueDiffers,       ///< the same cause with a value outside the intervals of the full data's: fragile
  Failed              ///< the search failed on this variant: no verdict
};

/// The causes the stepwise search names on one variant of the data (diagnosis/robustness.h).
struct RobustnessRun {
  std::string leftOut;
  std::vector<std::string> causes;          ///< names, in the order named
  std::vector<FitSummary> fits;             ///< their fits (estimates before the final refit)
  RobustnessVerdict verdict = RobustnessVerdict::Same;
  std::string error;                        ///< the search failed on this variant (then causes is empty)
  bool isFragile() const { return verdict == RobustnessVerdict::OtherCause || verdict == RobustnessVerdict::ValueDiffers; }
};

struct DiagnosisResult {
  std::string scenarioFile;
  const MeasuredData* data = nullptr;
  int numObservations = 0, numFolds = 0;
  FitSummary baseline, extended;               ///< the base model and the model with every cause
  std::vector<FitSummary> candidates;          ///< first step's, best (lowest BIC) first
  std::vector<Cause> causes;
  std::vector<FitSummary> pairs;               ///< the pair search's fits, when it ran (diagnosis/pair_search.h)
  /// Candidates that met every criterion but "fit, but contradict the measurement" and were not
  /// named (diagnosis/priors.h), with the step they were found at.
  std::vector<FitSummary> contradicting;
  std::vector<RobustnessRun> robustness;      ///< empty unless DiagnosisOptions::robustness
  /// Some variant names another first cause, or the same with an inconsistent value (robustness.h).
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
  /// Per observation: the normalised residual the likelihood sees (a response sample's prewhitened one
  /// over the innovation sigma; diagnosis/residual_summary.h), before and after.
  std::vector<double> whitenedBefore, whitenedAfter;
  std::vector<double> observationSpeed;               ///< m/s
  std::vector<double> observationTime;                ///< s (responses), NaN for eigenvalues
  std::vector<int> observationRow, observationPart;   ///< eigenvalue row (-1: response) and part (0 real, 1 imag)
  std::vector<int> observationRun, observationSignal; ///< response run (-1: eigenvalue) and signal
};

/// Runs the whole diagnosis.
DiagnosisResult runDiagnosis(const std::string& scenarioFile, const MeasuredData& data, const DiagnosisOptions& options);
/// The same from a scenario source already read (its getFile() names it).
DiagnosisResult runDiagnosis(std::shared_ptr<const scenario::ScenarioSource> source, const MeasuredData& data,
                             const DiagnosisOptions& options);

/// The base scenario's YAML tree with `overrides` applied (what extended.yaml holds).
YAML::Node makeScenarioTree(const std::string& scenarioFile, const std::vector<std::string>& overrides);

}  // namespace motostab::diagnosis
