#include "diagnosis/cause_criteria.h"

#include <algorithm>
#include <cmath>

#include "diagnosis/least_squares.h"
#include "diagnosis/model_fit.h"
#include "diagnosis/priors.h"
#include "diagnosis/profile_likelihood.h"

namespace motostab::diagnosis {

const char* const kAtBoundFailure = "estimate at a bound of its range";

namespace {

constexpr double kZ95 = 1.959963984540054;  // two-sided 95 % normal quantile

bool excludesOff(const CandidateParameter& p, const ParameterEstimate& e, double xInternal, double seInternal) {
  if (!(seInternal > 0) || !std::isfinite(seInternal)) return false;
  if (p.offAtInfinity) return xInternal + kZ95 * seInternal < std::log(p.upper) && !e.atBound;
  return std::abs(e.value - p.off) > kZ95 * e.stderr_;
}

// "Off" in internal units for the profile test: a stiffness's (off at infinity) the upper end of its
// range, where the data cannot tell it from rigid; NaN where a log-scale parameter has no finite off.
double getOffInternal(const CandidateParameter& p) {
  if (p.offAtInfinity) return std::log(p.upper);
  if (!p.logScale) return p.off;
  return p.off > 0 ? std::log(p.off) : NAN;
}

// The profile-likelihood test of "off" where the Wald interval does not exclude it: parameter k held
// at off, the others refitted (the fit's own noise), chi2 rises by more than 3.84. A likelihood that is
// flat about its maximum (findings that all hold there: zero information, a zero Wald standard error)
// still excludes off when holding the parameter at off violates the data.
bool profileExcludesOff(const FitProblem& problem, const ModelSpec& model, const CandidateParameter& p,
                        const FitSummary& fit, int index) {
  const double off = getOffInternal(p);
  if (!std::isfinite(off)) return false;
  return calcProfileRise(withNoise(problem, fit.noise), model, fit, index, off) > kProfileChi2_95;
}

// The parameter criteria: interval excludes off (Wald, else the profile likelihood: one refit per
// parameter the Wald interval does not decide), not at a bound, correlations.
void judgeParameters(const FitProblem& problem, const ModelSpec& model, const Candidate& c, FitSummary& fit, int off,
                     const DiagnosisOptions& opt) {
  const int df = static_cast<int>(c.parameters.size());
  for (int k = 0; k < df; ++k) {
    const ParameterEstimate& e = fit.parameters[k];
    const double seInternal = c.parameters[k].logScale ? e.stderr_ / std::max(e.value, 1e-300) : e.stderr_;
    const bool excluded = excludesOff(c.parameters[k], e, fit.x(off + k), seInternal) ||
                          profileExcludesOff(problem, model, c.parameters[k], fit, off + k);
    if (!excluded) fit.failed.push_back("confidence interval includes off");
    // An estimate held at a bound of its search range (kParameterRangeSigmas prior sigmas, a
    // stiffness's factor 1000) is not determined by the data: its fit only says "further than this".
    if (e.atBound && e.value != c.parameters[k].off) fit.failed.push_back(kAtBoundFailure);
    for (int l = 0; l < k; ++l)
      if (std::abs(fit.correlation(off + k, off + l)) > opt.maxCorrelation) fit.failed.push_back("correlation > 0.95");
  }
}

}  // namespace

void judgeCandidate(const FitProblem& problem, const std::vector<const Candidate*>& causes, const Candidate& c,
                    const FitSummary& baseline, FitSummary& fit, const DiagnosisOptions& opt, bool alwaysCv) {
  if (!std::isfinite(fit.chi2)) return;
  const ModelSpec model = makeModel(causes, &c);
  fit.deltaBic = fit.bic - baseline.bic;
  const double lr = std::max(0.0, baseline.deviance - fit.deviance);
  const int df = static_cast<int>(c.parameters.size());
  const int dfNoise = std::max(0, fit.numNoiseParameters - baseline.numNoiseParameters);
  const bool bound = df == 1 && dfNoise == 0 && c.parameters[0].offAtBound;
  fit.pValue = (bound ? 0.5 : 1.0) * calcChiSquareSurvival(lr, df + dfNoise);
  fit.failed.clear();
  if (!(fit.deltaBic <= -opt.minBicDrop)) fit.failed.push_back("BIC drop < " + std::to_string(int(opt.minBicDrop)));
  if (!(fit.pValue < opt.maxPValue)) fit.failed.push_back("likelihood-ratio p >= 0.01");
  judgeParameters(problem, model, c, fit, model.size() - df, opt);
  fit.contradictsMeasurement = contradictsMeasurement(fit.parameters);
  if (!fit.failed.empty() && !alwaysCv) return;
  // Both scored with the candidate's own noise: one metric for the two (the baseline's noise has
  // absorbed the misfit the candidate explains and would whiten it away).
  crossValidate(problem, model, fit.noise, fit);
  FitSummary base = baseline;
  crossValidate(problem, makeModel(causes, nullptr), fit.noise, base);
  if (fit.hasCv) {
    fit.foldsBetter = 0;
    int even = 0;  // folds both predict exactly (findings that hold either way): no evidence, left out
    for (size_t f = 0; f < fit.foldRms.size(); ++f) {  // a failed fold never counts as better
      fit.foldsBetter += !fit.foldFailed[f] && fit.foldRms[f] < base.foldRms[f];
      even += !fit.foldFailed[f] && fit.foldRms[f] == 0 && base.foldRms[f] == 0;
    }
    if (fit.foldsBetter == 0 || fit.foldsBetter < opt.minFoldShare * (problem.numFolds - even) - 1e-9)
      fit.failed.push_back("CV better in < 80 % of folds");
  }
}

std::vector<FitSummary> findIndistinguishable(const FitProblem& problem, const std::vector<const Candidate*>& causes,
                                              const std::vector<const Candidate*>& parts, const FitSummary& baseline,
                                              const std::vector<FitSummary>& fits, int k, const DiagnosisOptions& opt) {
  // Residual changes measured with the named fit's noise, so that every candidate's is in one metric.
  const FitProblem common = withNoise(problem, fits[k].noise);
  const auto change = [&](size_t i) -> Eigen::VectorXd {
    return common.calcResiduals(common.predict(makeModel(causes, nullptr), baseline.x)) -
           common.calcResiduals(common.predict(makeModel(causes, parts[i]), fits[i].x));
  };
  std::vector<double> similarity(fits.size(), 0.0);
  try {
    const Eigen::VectorXd dk = change(k);
    for (size_t i = 0; i < fits.size(); ++i) {
      if (static_cast<int>(i) == k || !std::isfinite(fits[i].chi2) || !fits[i].failed.empty()) continue;
      const Eigen::VectorXd di = change(i);
      const double den = dk.norm() * di.norm();
      similarity[i] = den > 0 ? dk.dot(di) / den : 0.0;
    }
  } catch (const std::exception&) {  // a prediction that fails here was fitted: leave the rest at 0
  }
  std::vector<FitSummary> out;
  for (size_t i = 0; i < fits.size(); ++i)
    if (static_cast<int>(i) != k && (std::abs(fits[i].bic - fits[k].bic) <= opt.indistinguishableBic ||
                                     (fits[i].failed.empty() && similarity[i] > opt.maxPredictionCorrelation)))
      out.push_back(fits[i]);
  return out;
}

}  // namespace motostab::diagnosis
