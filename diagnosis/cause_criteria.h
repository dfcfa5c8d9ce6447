#pragma once
// The criteria a candidate's fit must meet to be named as a cause, against the step's baseline (the
// causes named so far): BIC drop >= minBicDrop (Schwarz 1978; each model with its own noise,
// model_fit.h), likelihood-ratio p < maxPValue (Wilks 1938; df = the candidate's parameters plus any
// AR coefficients it adds; halved, the 50:50 mixture of chi2_0 and chi2_1, when "effect off" is a bound,
// Self & Liang 1987), each parameter's 95 % interval excluding "off", no estimate held at a bound of its
// search range, pairwise parameter correlation <= maxCorrelation, and cross-validated error lower in at
// least minFoldShare of the folds. And the look-alikes the data cannot tell from a named cause.
#include <vector>

#include "diagnosis/diagnosis.h"
#include "diagnosis/fit_problem.h"

namespace motostab::diagnosis {

/// Failure text of the bound criterion (priors.h lets a contradicting fit failing only this be reported).
extern const char* const kAtBoundFailure;

/// Fills fit.deltaBic, pValue, contradictsMeasurement, failed (and the CV scores when the cheap criteria
/// pass or `alwaysCv`; the candidate and the baseline cross-validated with the candidate's own noise).
/// `baseline`: the step's model without the candidate; `causes`:
/// the causes named so far; `c`: the candidate.
void judgeCandidate(const FitProblem& problem, const std::vector<const Candidate*>& causes, const Candidate& c,
                    const FitSummary& baseline, FitSummary& fit, const DiagnosisOptions& opt, bool alwaysCv);

/// The fits of `fits` the data cannot tell from fits[k]: BIC within opt.indistinguishableBic, or meeting
/// every criterion with a change of the (whitened, normalised) residuals from the baseline that correlates
/// with fits[k]'s above opt.maxPredictionCorrelation. `parts[i]`: the candidate of fits[i].
std::vector<FitSummary> findIndistinguishable(const FitProblem& problem, const std::vector<const Candidate*>& causes,
                                              const std::vector<const Candidate*>& parts, const FitSummary& baseline,
                                              const std::vector<FitSummary>& fits, int k, const DiagnosisOptions& opt);

}  // namespace motostab::diagnosis
