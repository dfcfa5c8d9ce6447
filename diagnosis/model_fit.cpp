#include "diagnosis/model_fit.h"

#include <cmath>
#include <stdexcept>

#include "diagnosis/cross_validation.h"

namespace motostab::diagnosis {
namespace {

// A fold of -1 fits every observation; else the observations outside fold `fold`.
Eigen::VectorXd selectResiduals(const FitProblem& problem, int fold, const Eigen::VectorXd& all) {
  if (fold < 0) return all;
  std::vector<double> r;
  for (size_t i = 0; i < problem.observations.size(); ++i)
    if (problem.observations[i].fold != fold) r.push_back(all(i));
  return Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<int>(r.size()));
}

LeastSquaresProblem makeLeastSquares(const FitProblem& problem, const ModelSpec& model, int fold) {
  const auto ps = model.getParameters();
  const int n = static_cast<int>(ps.size());
  LeastSquaresProblem p;
  p.lower.resize(n), p.upper.resize(n), p.step.resize(n);
  for (int i = 0; i < n; ++i) {
    p.lower(i) = ps[i]->logScale ? std::log(ps[i]->lower) : ps[i]->lower;
    p.upper(i) = ps[i]->logScale ? std::log(ps[i]->upper) : ps[i]->upper;
    p.step(i) = ps[i]->step;
  }
  p.residual = [&problem, &model, fold](const Eigen::VectorXd& x) {
    const Eigen::VectorXd data = selectResiduals(problem, fold, problem.calcResiduals(problem.predict(model, x)));
    const Eigen::VectorXd prior = model.calcPriorResiduals(x);
    Eigen::VectorXd r(data.size() + prior.size());
    r << data, prior;
    return r;
  };
  int numData = 0;
  for (const auto& o : problem.observations) numData += o.fold != fold;
  p.numData = numData;
  return p;
}

ParameterEstimate makeEstimate(const ModelSpec& model, const LeastSquaresResult& r, int i) {
  const CandidateParameter& p = *model.getParameters()[i];
  ParameterEstimate e;
  e.name = p.name;
  e.path = p.path;
  e.value = model.getValue(i, r.x);
  const double se = r.stderr_.size() > i ? r.stderr_(i) : 0.0;
  e.stderr_ = p.logScale ? e.value * se : se;  // delta method
  e.profileLow = e.profileHigh = e.value;
  e.priorSigma = p.priorSigma;
  e.priorMean = p.priorMean;
  e.priorMeasured = p.priorMeasured;
  e.sigmas = p.priorSigma > 0 ? (e.value - p.priorMean) / p.priorSigma : 0.0;
  e.atBound = r.atBound.size() > i && r.atBound(i);
  e.note = p.note;
  return e;
}

// Summary of a full-data fit with the noise `problem` carries: chi2, deviance, RMS, BIC, estimates.
FitSummary summarise(const std::string& name, const FitProblem& problem, const ModelSpec& model,
                     const LeastSquaresResult& r, int ownFrom) {
  FitSummary s;
  s.name = name;
  s.x = r.x;
  s.chi2 = r.chi2;
  s.deviance = problem.calcDeviance(r.residual);
  const int n = static_cast<int>(problem.observations.size());
  s.rms = std::sqrt(r.residual.head(n).squaredNorm() / n);
  s.correlation = r.correlation;
  s.jacobian = r.jacobian;
  s.converged = r.stop == "converged";
  for (int i = 0; i < model.size(); ++i) {
    s.allParameters.push_back(makeEstimate(model, r, i));
    if (i >= ownFrom) s.parameters.push_back(s.allParameters.back());
    s.atBound |= s.allParameters.back().atBound && i >= ownFrom;
  }
  s.noise = problem.getNoise();
  s.numNoiseParameters = problem.countNoiseParameters();
  return s;
}

// Alternates fits and noise estimates (iterated Cochrane-Orcutt) on `own`; returns the last fit with
// its residuals re-evaluated under the final noise.
LeastSquaresResult fitWithOwnNoise(FitProblem& own, const ModelSpec& model, const Eigen::VectorXd& x0) {
  Eigen::VectorXd x = x0;
  for (int it = 1;; ++it) {
    LeastSquaresResult r = fitModel(own, model, x, -1);
    x = r.x;
    const NoiseState before = own.getNoise();
    const Prediction p = own.predict(model, x);
    own.updateNoise(own.calcRawResiduals(p), model.size() + p.numLinear);
    if (own.getNoise().calcChange(before) < kNoiseTolerance || it == kMaxNoiseIterations) {
      r.residual = calcFitResiduals(own, model, x);
      r.chi2 = r.residual.squaredNorm();
      return r;
    }
  }
}

}  // namespace

ModelSpec makeModel(const std::vector<const Candidate*>& causes, const Candidate* candidate) {
  ModelSpec m;
  m.parts = causes;
  if (candidate) m.parts.push_back(candidate);
  return m;
}

Eigen::VectorXd calcFitResiduals(const FitProblem& problem, const ModelSpec& model, const Eigen::VectorXd& x) {
  return makeLeastSquares(problem, model, -1).residual(x);
}

LeastSquaresResult fitModel(const FitProblem& problem, const ModelSpec& model, const Eigen::VectorXd& x0, int fold,
                            int maxIterations, int fixIndex, bool statistics) {
  LeastSquaresProblem p = makeLeastSquares(problem, model, fold);
  if (fixIndex >= 0) p.lower(fixIndex) = p.upper(fixIndex) = x0(fixIndex);
  if (model.size() == 0 || (model.size() == 1 && fixIndex == 0)) {
    LeastSquaresResult r;
    r.x = x0;
    r.residual = p.residual(x0);
    r.chi2 = r.residual.squaredNorm();
    r.stop = "converged";
    return r;
  }
  LeastSquaresOptions opt;
  opt.maxIterations = maxIterations;
  opt.statistics = statistics;
  opt.relativeTolerance = kFitTolerance;
  return solveBoundedLeastSquares(p, x0, opt);
}

FitSummary fitFull(const FitProblem& problem, const ModelSpec& model, const Eigen::VectorXd& x0, const std::string& name,
                   const NoiseState* startNoise) {
  FitProblem own = withNoise(problem, startNoise ? *startNoise : problem.getNoise());
  const LeastSquaresResult r = fitWithOwnNoise(own, model, x0);
  const bool candidate = !model.parts.empty() && name == model.parts.back()->name;
  const int ownFrom = candidate ? model.size() - static_cast<int>(model.parts.back()->parameters.size()) : 0;
  FitSummary s = summarise(name, own, model, r, ownFrom);
  const Prediction p = own.predict(model, r.x);
  s.numParameters = model.size() + p.numLinear + s.numNoiseParameters;
  s.bic = s.deviance + s.numParameters * std::log(static_cast<double>(problem.observations.size()));
  return s;
}

FitSummary fitOrFail(const FitProblem& problem, const ModelSpec& model, const Eigen::VectorXd& x0, const std::string& name,
                     const NoiseState& startNoise) {
  try {
    return fitFull(problem, model, x0, name, &startNoise);
  } catch (const std::exception& e) {
    FitSummary f;
    f.name = name;
    f.x = x0;
    f.chi2 = f.bic = f.rms = f.deviance = HUGE_VAL;
    f.failed = {std::string("fit failed: ") + e.what()};
    return f;
  }
}

void crossValidate(const FitProblem& problem, const ModelSpec& model, const NoiseState& noise, FitSummary& s, int threads) {
  const FitProblem scored = withNoise(problem, noise);
  std::vector<int> foldOf;
  for (const auto& o : scored.observations) foldOf.push_back(o.fold);
  // A model without parameters predicts every fold as the full fit does: one prediction for all.
  const Eigen::VectorXd full = scored.calcResiduals(scored.predict(model, s.x));
  const auto fitFold = [&](int f) {
    if (model.size() == 0) return full;
    return Eigen::VectorXd(scored.calcResiduals(scored.predict(model, fitModel(scored, model, s.x, f, 6, -1, false).x)));
  };
  const FoldScores scores = scoreFolds(scored.numFolds, foldOf, fitFold, full, 100, threads);
  s.foldRms = scores.rms;
  s.foldFailed = scores.failed;
  s.foldFailures.clear();
  for (int f = 0; f < scored.numFolds; ++f)
    if (scores.failed[f]) s.foldFailures.push_back("fold " + std::to_string(f + 1) + ": " + scores.reasons[f]);
  s.cvRms = scores.cvRms;
  s.hasCv = true;
}

double calcCvRmsOver(const FitProblem& problem, const FitSummary& s, const std::vector<bool>& skip) {
  std::vector<int> count(s.foldRms.size(), 0);
  for (const auto& o : problem.observations)
    if (o.fold >= 0 && o.fold < static_cast<int>(count.size())) ++count[o.fold];
  double sum = 0;
  int n = 0;
  for (size_t f = 0; f < count.size(); ++f)
    if (!(f < skip.size() && skip[f])) sum += s.foldRms[f] * s.foldRms[f] * count[f], n += count[f];
  return n > 0 ? std::sqrt(sum / n) : std::nan("");
}

double calcRms(const FitProblem& problem, const ModelSpec& model, const Eigen::VectorXd& x, const NoiseState& noise) {
  const FitProblem p = withNoise(problem, noise);
  return std::sqrt(p.calcResiduals(p.predict(model, x)).squaredNorm() / static_cast<double>(p.observations.size()));
}

FitProblem withNoise(const FitProblem& problem, const NoiseState& noise) {
  FitProblem p = problem;
  p.setNoise(noise);
  return p;
}

}  // namespace motostab::diagnosis
