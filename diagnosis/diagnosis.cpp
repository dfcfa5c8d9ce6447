#include "diagnosis/diagnosis.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "core/parallel.h"
#include "diagnosis/controller_groups.h"
#include "diagnosis/cross_validation.h"
#include "diagnosis/fit_problem.h"
#include "diagnosis/least_squares.h"
#include "diagnosis/priors.h"
#include "diagnosis/robustness.h"
#include "scenario/scenario.h"
#include "io/yaml_map.h"

namespace motostab::diagnosis {

using core::runParallel;
using io::InputError;
using io::applyOverride;
using io::loadYamlFile;
using scenario::loadScenario;

namespace {

constexpr double kZ95 = 1.959963984540054;   // two-sided 95 % normal quantile
constexpr double kChi95 = 3.841458820694124;  // chi-square(1) 95 % quantile
// Fits stop when chi2 falls by less than this fraction of itself: a chi2 within about 1e-6 chi2 of
// its minimum (5e-4 for 500 observations) leaves a parameter within 0.03 standard errors of it, and
// a fold's held-out RMS within well under 1e-4 of itself.
constexpr double kFitTolerance = 1e-6;

// A fold of -1 fits every observation; else the observations outside fold `fold`.
struct FitContext {
  const FitProblem& problem;
  const ModelSpec& model;
  int fold = -1;
};

Eigen::VectorXd selectResiduals(const FitContext& c, const Eigen::VectorXd& all) {
  if (c.fold < 0) return all;
  std::vector<double> r;
  for (size_t i = 0; i < c.problem.observations.size(); ++i)
    if (c.problem.observations[i].fold != c.fold) r.push_back(all(i));
  return Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<int>(r.size()));
}

LeastSquaresProblem makeLeastSquares(const FitContext& c) {
  const auto ps = c.model.getParameters();
  const int n = static_cast<int>(ps.size());
  LeastSquaresProblem p;
  p.lower.resize(n), p.upper.resize(n), p.step.resize(n);
  for (int i = 0; i < n; ++i) {
    p.lower(i) = ps[i]->logScale ? std::log(ps[i]->lower) : ps[i]->lower;
    p.upper(i) = ps[i]->logScale ? std::log(ps[i]->upper) : ps[i]->upper;
    p.step(i) = ps[i]->step;
  }
  p.residual = [c](const Eigen::VectorXd& x) {
    const Eigen::VectorXd data = selectResiduals(c, c.problem.calcResiduals(c.problem.predict(c.model, x)));
    const Eigen::VectorXd prior = c.model.calcPriorResiduals(x);
    Eigen::VectorXd r(data.size() + prior.size());
    r << data, prior;
    return r;
  };
  int numData = 0;
  for (const auto& o : c.problem.observations) numData += o.fold != c.fold;
  p.numData = numData;
  return p;
}

// Fits `model` from x0 (on every observation when fold < 0); a model without parameters is evaluated.
// fixIndex >= 0 holds that parameter at its x0 value (profile likelihood).
LeastSquaresResult fitModel(const FitProblem& problem, const ModelSpec& model, const Eigen::VectorXd& x0, int fold,
                            int maxIterations = 30, int fixIndex = -1, bool statistics = true) {
  const FitContext c{problem, model, fold};
  LeastSquaresProblem p = makeLeastSquares(c);
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
  return e;
}

// Summary of a full-data fit: chi2, rms over data, BIC, estimates.
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
  return s;
}

void score(const FitProblem& problem, const Prediction& p, FitSummary& s, int numModel) {
  const int n = static_cast<int>(problem.observations.size());
  s.numParameters = numModel + p.numLinear;
  s.bic = s.deviance + s.numParameters * std::log(static_cast<double>(n));
}

// K-fold cross-validation of a model around its full fit x (diagnosis/cross_validation.h guards the
// folds whose fit fails or diverges).
void crossValidate(const FitProblem& problem, const ModelSpec& model, FitSummary& s, int threads = 1) {
  std::vector<int> foldOf;
  for (const auto& o : problem.observations) foldOf.push_back(o.fold);
  const auto fitFold = [&](int f) {
    const Eigen::VectorXd x = model.size() ? fitModel(problem, model, s.x, f, 6, -1, false).x : s.x;
    return Eigen::VectorXd(problem.calcResiduals(problem.predict(model, x)));
  };
  const FoldScores scores =
      scoreFolds(problem.numFolds, foldOf, fitFold, problem.calcResiduals(problem.predict(model, s.x)), 100, threads);
  s.foldRms = scores.rms;
  s.foldFailed = scores.failed;
  s.foldFailures.clear();
  for (int f = 0; f < problem.numFolds; ++f)
    if (scores.failed[f]) s.foldFailures.push_back("fold " + std::to_string(f + 1) + ": " + scores.reasons[f]);
  s.cvRms = scores.cvRms;
  s.hasCv = true;
}

ModelSpec makeModel(const std::vector<const Candidate*>& causes, const Candidate* candidate) {
  ModelSpec m;
  m.parts = causes;
  if (candidate) m.parts.push_back(candidate);
  return m;
}

FitSummary fitFull(const FitProblem& problem, const ModelSpec& model, const Eigen::VectorXd& x0, const std::string& name) {
  const LeastSquaresResult r = fitModel(problem, model, x0, -1);
  // A candidate's own parameters are the last part's; the baseline and the extended model own all.
  const bool candidate = !model.parts.empty() && name == model.parts.back()->name;
  const int own = candidate ? model.size() - static_cast<int>(model.parts.back()->parameters.size()) : 0;
  FitSummary s = summarise(name, problem, model, r, own);
  score(problem, problem.predict(model, r.x), s, model.size());
  return s;
}

struct Step {
  std::vector<const Candidate*> causes;
  Eigen::VectorXd xCauses;
  std::vector<const Candidate*> pool;
  FitSummary baseline;
  std::vector<FitSummary> fits;   // per pool entry
};

Eigen::VectorXd joinStart(const Eigen::VectorXd& xCauses, const Candidate& c) {
  const Eigen::VectorXd own = makeModel({}, &c).getStart();
  Eigen::VectorXd x(xCauses.size() + own.size());
  x << xCauses, own;
  return x;
}

void fitStep(const FitProblem& problem, Step& step, const DiagnosisOptions& opt, const std::string& stage) {
  const bool warm = !step.fits.empty();
  step.baseline = fitFull(problem, makeModel(step.causes, nullptr), warm ? step.baseline.x : step.xCauses, "baseline");
  step.fits.resize(step.pool.size());
  std::atomic<int> done{0};
  std::mutex progressMutex;
  runParallel(step.pool.size(), opt.threads, [&](size_t i) {
    const Candidate& c = *step.pool[i];
    const Eigen::VectorXd x0 = warm ? step.fits[i].x : joinStart(step.baseline.x, c);
    try {
      step.fits[i] = fitFull(problem, makeModel(step.causes, &c), x0, c.name);
    } catch (const std::exception& e) {  // its start is no valid vehicle, or a trim failed
      step.fits[i] = FitSummary();
      step.fits[i].name = c.name;
      step.fits[i].x = x0;
      step.fits[i].chi2 = step.fits[i].bic = step.fits[i].rms = step.fits[i].deviance = HUGE_VAL;
      step.fits[i].failed = {std::string("fit failed: ") + e.what()};
    }
    std::lock_guard<std::mutex> lock(progressMutex);
    if (opt.progress) opt.progress(stage, ++done, static_cast<int>(step.pool.size()));
  });
}

// Noise of unknown components from the best fit of the step (lowest chi2), then everything refitted.
void estimateNoise(FitProblem& problem, Step& step, const DiagnosisOptions& opt, const std::string& stage) {
  for (int pass = 0; pass < 1; ++pass) {  // one refit: a second changes sigma by well under 1 %
    const FitSummary* best = &step.baseline;
    const Candidate* bestCandidate = nullptr;
    for (size_t i = 0; i < step.fits.size(); ++i)
      if (step.fits[i].deviance < best->deviance) best = &step.fits[i], bestCandidate = step.pool[i];
    const ModelSpec model = makeModel(step.causes, bestCandidate);
    const std::vector<double> before = problem.componentSigma;
    problem.updateNoise(problem.calcRawResiduals(problem.predict(model, best->x)), best->numParameters);
    double change = 0;
    for (size_t c = 0; c < before.size(); ++c)
      change = std::max(change, std::abs(std::log(problem.componentSigma[c] / before[c])));
    if (change < 0.01) break;
    fitStep(problem, step, opt, stage + " (noise re-estimated)");
  }
}

bool excludesOff(const CandidateParameter& p, const ParameterEstimate& e, double xInternal, double seInternal) {
  if (!(seInternal > 0) || !std::isfinite(seInternal)) return false;
  if (p.offAtInfinity) return xInternal + kZ95 * seInternal < std::log(p.upper) && !e.atBound;
  return std::abs(e.value - p.off) > kZ95 * e.stderr_;
}

// The criteria of a cause that `fit` fails; CV only if the cheap ones pass.
void judge(const FitProblem& problem, const Step& step, size_t i, FitSummary& fit, const DiagnosisOptions& opt,
           bool alwaysCv) {
  const Candidate& c = *step.pool[i];
  const ModelSpec model = makeModel(step.causes, &c);
  if (!std::isfinite(fit.chi2)) return;
  fit.deltaBic = fit.bic - step.baseline.bic;
  const double lr = std::max(0.0, step.baseline.deviance - fit.deviance);
  const int df = static_cast<int>(c.parameters.size());
  const bool bound = df == 1 && c.parameters[0].offAtBound;
  fit.pValue = (bound ? 0.5 : 1.0) * calcChiSquareSurvival(lr, df);
  fit.failed.clear();
  if (!(fit.deltaBic <= -opt.minBicDrop)) fit.failed.push_back("BIC drop < " + std::to_string(int(opt.minBicDrop)));
  if (!(fit.pValue < opt.maxPValue)) fit.failed.push_back("likelihood-ratio p >= 0.01");
  const int off = model.size() - df;
  for (int k = 0; k < df; ++k) {
    const ParameterEstimate& e = fit.parameters[k];
    const double seInternal = c.parameters[k].logScale ? e.stderr_ / std::max(e.value, 1e-300) : e.stderr_;
    if (!excludesOff(c.parameters[k], e, fit.x(off + k), seInternal)) fit.failed.push_back("confidence interval includes off");
    // An estimate held at a bound of its search range (30 prior sigmas, a stiffness's factor 1000) is
    // not determined by the data: its fit only says "further than this".
    if (e.atBound && e.value != c.parameters[k].off) fit.failed.push_back("estimate at a bound of its range");
    for (int l = 0; l < k; ++l)
      if (std::abs(fit.correlation(off + k, off + l)) > opt.maxCorrelation) fit.failed.push_back("correlation > 0.95");
  }
  fit.contradictsMeasurement = false;
  for (const ParameterEstimate& e : fit.parameters)
    fit.contradictsMeasurement |= e.priorMeasured && std::abs(e.sigmas) > kContradictionSigmas;
  if (fit.failed.empty() || alwaysCv) crossValidate(problem, model, fit);
  if (fit.hasCv) {
    fit.foldsBetter = 0;
    for (size_t f = 0; f < fit.foldRms.size(); ++f)  // a failed fold never counts as better
      fit.foldsBetter += !fit.foldFailed[f] && fit.foldRms[f] < step.baseline.foldRms[f];
    if (fit.foldsBetter < opt.minFoldShare * problem.numFolds - 1e-9) fit.failed.push_back("CV better in < 80 % of folds");
  }
}


// chi2 with parameter i held at internal value v, the others refitted; infinite where v makes no
// valid vehicle (an inertia past the triangle inequality, a trim that fails): the profile then ends
// at the edge of the valid values.
double calcProfileChi2(const FitProblem& problem, const ModelSpec& model, Eigen::VectorXd x, int i, double v) {
  x(i) = v;
  try {
    return fitModel(problem, model, x, -1, 15, i).chi2;
  } catch (const std::exception&) {
    return HUGE_VAL;
  }
}

// One end of the 95 % profile-likelihood interval (chi2 rise of 3.84) in direction dir, internal units.
double findProfileEnd(const FitProblem& problem, const ModelSpec& model, const FitSummary& s, int i, double se,
                      double bound, int dir) {
  const double target = s.chi2 + kChi95, x0 = s.x(i);
  double inside = x0, outside = x0, d = std::max(se, 1e-6 * std::max(1.0, std::abs(x0)));
  for (int k = 0; k < 10; ++k, d *= 2) {
    outside = dir > 0 ? std::min(x0 + d, bound) : std::max(x0 - d, bound);
    if (calcProfileChi2(problem, model, s.x, i, outside) >= target) break;
    inside = outside;
    if (outside == bound) return bound;
  }
  for (int k = 0; k < 8; ++k) {
    const double mid = 0.5 * (inside + outside);
    (calcProfileChi2(problem, model, s.x, i, mid) >= target ? outside : inside) = mid;
  }
  return 0.5 * (inside + outside);
}

void calcProfiles(const FitProblem& problem, const ModelSpec& model, FitSummary& s) {
  const auto ps = model.getParameters();
  for (size_t i = 0; i < ps.size(); ++i) {
    ParameterEstimate& e = s.allParameters[i];
    const bool lg = ps[i]->logScale;
    const double se = lg ? e.stderr_ / e.value : e.stderr_;
    const double lo = lg ? std::log(ps[i]->lower) : ps[i]->lower, hi = lg ? std::log(ps[i]->upper) : ps[i]->upper;
    const double a = findProfileEnd(problem, model, s, static_cast<int>(i), se, lo, -1);
    const double b = findProfileEnd(problem, model, s, static_cast<int>(i), se, hi, +1);
    e.profileLow = lg ? std::exp(a) : a;
    e.profileHigh = lg ? std::exp(b) : b;
    e.hasProfile = true;
  }
}

std::vector<ComponentResidual> summariseResiduals(const FitProblem& problem, const Prediction& p) {
  std::vector<ComponentResidual> out(problem.components.size());
  std::vector<std::vector<std::pair<double, double>>> trend(out.size());  // speed, real residual
  std::vector<double> ss(out.size(), 0.0);
  for (const auto& o : problem.observations) {
    const double raw = o.value - problem.getPredicted(p, o), z = raw / problem.getSigma(o);
    ComponentResidual& c = out[o.component];
    ++c.count;
    c.meanReal += raw;
    ss[o.component] += z * z;
    if (o.row >= 0) trend[o.component].push_back({o.speed, raw});
  }
  for (size_t k = 0; k < out.size(); ++k) {
    ComponentResidual& c = out[k];
    c.name = problem.components[k];
    c.meanReal /= std::max(c.count, 1);
    c.rmsReal = std::sqrt(ss[k] / std::max(c.count, 1));
    const auto& t = trend[k];
    if (t.size() < 3) continue;
    double mv = 0, mr = 0;
    for (auto [v, r] : t) mv += v / t.size(), mr += r / t.size();
    double sxx = 0, sxy = 0;
    for (auto [v, r] : t) sxx += (v - mv) * (v - mv), sxy += (v - mv) * (r - mr);
    if (sxx <= 0) continue;
    c.slopeRealPerMps = sxy / sxx;
    double sse = 0;
    for (auto [v, r] : t) sse += std::pow(r - mr - c.slopeRealPerMps * (v - mv), 2);
    c.slopeStderr = std::sqrt(sse / (t.size() - 2) / sxx);
    c.slopeP = c.slopeStderr > 0 ? std::erfc(std::abs(c.slopeRealPerMps / c.slopeStderr) / std::sqrt(2.0)) : 0.0;
  }
  for (size_t r = 0; r < p.responses.size(); ++r)
    for (size_t j = 0; j < p.responses[r].vaf.size(); ++j)
      for (auto& c : out)
        if (c.name == "run" + std::to_string(r + 1) + "." + problem.getData().responses[r].signals[j].column)
          c.vafAfter = p.responses[r].vaf[j];
  return out;
}

std::vector<const Candidate*> probeCandidates(const std::string& file, const DiagnosisOptions& opt,
                                              const std::vector<Candidate>& all, std::vector<std::string>& unavailable) {
  std::vector<const Candidate*> out;
  for (const auto& c : all) {
    std::vector<std::string> ov = opt.overrides;
    const ModelSpec m = makeModel({}, &c);
    for (const auto& o : m.makeOverrides(m.getStart())) ov.push_back(o);
    try {
      loadScenario(file, ov);
      out.push_back(&c);
    } catch (const InputError& e) {
      unavailable.push_back(c.name + ": " + e.getReason() + " (" + e.getLocation().key + ")");
    }
  }
  return out;
}

// Candidates that cannot join a model holding `cause` (same switch or same parameter).
bool conflicts(const Candidate& a, const Candidate& b) {
  auto key = [](const std::string& o) { return o.substr(0, o.find('=')); };
  for (const auto& x : a.fixedOverrides)
    for (const auto& y : b.fixedOverrides)
      if (key(x) == key(y)) return true;
  for (const auto& p : a.parameters)
    for (const auto& q : b.parameters)
      if (p.path == q.path) return true;
  return false;
}

}  // namespace

YAML::Node makeScenarioTree(const std::string& scenarioFile, const std::vector<std::string>& overrides) {
  YAML::Node root = loadYamlFile(scenarioFile).getNode();
  for (const auto& o : overrides) applyOverride(root, o);
  return root;
}

namespace {

std::vector<std::pair<std::string, double>> getUncertainty(const std::string& file, const DiagnosisOptions& opt) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& u : loadScenario(file, opt.overrides).uncertainty) out.push_back({u.path, u.sigma});
  return out;
}


// Per candidate of the step: the correlation of what it changes in the (whitened, normalised)
// residuals, r_baseline - r_candidate, with what the named candidate k changes; 0 for failed fits.
std::vector<double> calcPredictionCorrelations(const FitProblem& problem, const Step& step, int k) {
  const auto change = [&](size_t i) -> Eigen::VectorXd {
    const ModelSpec base = makeModel(step.causes, nullptr), cand = makeModel(step.causes, step.pool[i]);
    return problem.calcResiduals(problem.predict(base, step.baseline.x)) - problem.calcResiduals(problem.predict(cand, step.fits[i].x));
  };
  std::vector<double> out(step.fits.size(), 0.0);
  try {
    const Eigen::VectorXd dk = change(k);
    for (size_t i = 0; i < step.fits.size(); ++i) {
      if (static_cast<int>(i) == k || !std::isfinite(step.fits[i].chi2) || !step.fits[i].failed.empty()) continue;
      const Eigen::VectorXd di = change(i);
      const double den = dk.norm() * di.norm();
      out[i] = den > 0 ? dk.dot(di) / den : 0.0;
    }
  } catch (const std::exception&) {  // a prediction that fails here was fitted: leave the rest at 0
  }
  return out;
}

// The forward stepwise search. `candidateTable`: cross-validate every first-step candidate (for the
// report's table); else only those meeting the cheap criteria (the robustness reruns).
void runSearch(FitProblem& problem, Step& step, const DiagnosisOptions& opt, DiagnosisResult& result, bool candidateTable) {
  for (int s = 0; s < opt.maxCauses && !step.pool.empty(); ++s) {
    const std::string stage = "step " + std::to_string(s + 1);
    step.fits.clear();
    fitStep(problem, step, opt, stage);
    estimateNoise(problem, step, opt, stage);
    crossValidate(problem, makeModel(step.causes, nullptr), step.baseline, opt.threads);
    runParallel(step.fits.size(), opt.threads, [&](size_t i) { judge(problem, step, i, step.fits[i], opt, s == 0 && candidateTable); });
    if (s == 0) {
      result.candidates = step.fits;
      std::sort(result.candidates.begin(), result.candidates.end(), [](auto& a, auto& b) { return a.bic < b.bic; });
    }
    std::vector<int> contradicting;
    const int k = pickCause(step.fits, step.baseline.bic, &contradicting);
    for (int i : contradicting) result.contradicting.push_back(step.fits[i]);
    if (k < 0) break;
    Cause cause{step.fits[k], {}};
    const std::vector<double> similarity = calcPredictionCorrelations(problem, step, k);
    for (size_t i = 0; i < step.fits.size(); ++i)
      if (static_cast<int>(i) != k && (std::abs(step.fits[i].bic - step.fits[k].bic) <= opt.indistinguishableBic ||
                                       (step.fits[i].failed.empty() && similarity[i] > opt.maxPredictionCorrelation)))
        cause.indistinguishable.push_back(step.fits[i]);
    result.causes.push_back(cause);
    const Candidate* named = step.pool[k];
    step.causes.push_back(named);
    step.xCauses = step.fits[k].x;
    std::vector<const Candidate*> rest;
    for (const auto* c : step.pool)
      if (c != named && !conflicts(*c, *named)) rest.push_back(c);
    step.pool = rest;
  }
}

void finish(FitProblem& problem, const Step& step, DiagnosisResult& result, int threads) {
  const ModelSpec none, extended = makeModel(step.causes, nullptr);
  result.baseline = fitFull(problem, none, Eigen::VectorXd(), "baseline");
  crossValidate(problem, none, result.baseline);
  result.extended = fitFull(problem, extended, step.xCauses, "extended");
  crossValidate(problem, extended, result.extended, threads);
  calcProfiles(problem, extended, result.extended);
  for (size_t c = 0, i = 0; c < result.causes.size(); ++c)
    for (auto& e : result.causes[c].fit.parameters) e = result.extended.allParameters[i++];
  result.before = problem.predict(none, Eigen::VectorXd(), true);
  result.after = problem.predict(extended, result.extended.x, true);
  for (const auto& o : extended.makeOverrides(result.extended.x)) result.extendedOverrides.push_back(o);
  result.residualsBefore = summariseResiduals(problem, result.before);
  result.residualsAfter = summariseResiduals(problem, result.after);
  for (size_t k = 0; k < result.residualsAfter.size(); ++k) {
    result.residualsAfter[k].vafBefore = result.residualsBefore[k].vafAfter;
    result.residualsBefore[k].vafBefore = result.residualsBefore[k].vafAfter;
  }
  for (size_t c = 0; c < problem.components.size(); ++c)
    result.noise.push_back({problem.components[c], problem.componentSigma[c], !problem.componentKnown[c],
                            problem.componentAr[c].phi, problem.componentSigma[c] * problem.componentAr[c].calcMarginalFactor()});
  for (const auto& o : problem.observations) {
    result.sigma.push_back(problem.getMarginalSigma(o));
    result.observed.push_back(o.value);
    result.observationComponent.push_back(problem.components[o.component]);
    result.predictedBefore.push_back(problem.getPredicted(result.before, o));
    result.predictedAfter.push_back(problem.getPredicted(result.after, o));
    result.observationSpeed.push_back(o.speed);
    result.observationTime.push_back(o.run >= 0 ? problem.getData().responses[o.run].time[o.sample] : std::nan(""));
    result.observationRow.push_back(o.row);
    result.observationPart.push_back(o.part);
    result.observationRun.push_back(o.run);
    result.observationSignal.push_back(o.signal);
  }
  result.numObservations = static_cast<int>(problem.observations.size());
  result.numFolds = problem.numFolds;
}

// The stepwise search on the problem's data with the candidates `pool` (probed against the scenario once).
DiagnosisResult searchCauses(const DiagnosisOptions& opt, const std::vector<const Candidate*>& pool, FitProblem& problem,
                             Step& step, bool candidateTable) {
  DiagnosisResult result;
  step.pool = pool;
  const Prediction base = problem.predict(ModelSpec(), Eigen::VectorXd());
  problem.updateNoise(problem.calcRawResiduals(base), base.numLinear);  // provisional
  runSearch(problem, step, opt, result, candidateTable);
  return result;
}

std::vector<RobustnessRun> runRobustness(const std::string& scenarioFile, const MeasuredData& data, const DiagnosisOptions& opt,
                                         const std::vector<const Candidate*>& pool, const std::vector<Cause>& causes) {
  std::vector<RobustnessRun> out;
  const std::vector<DataVariant> variants = makeRobustnessVariants(data);
  DiagnosisOptions quiet = opt;
  quiet.progress = nullptr;
  // As many steps as named on all the data (one when none was): a rerun asks whether those causes
  // survive, not what a further step would add.
  quiet.maxCauses = std::max(1, static_cast<int>(causes.size()));
  for (size_t k = 0; k < variants.size(); ++k) {
    if (opt.progress) opt.progress("robustness reruns", static_cast<int>(k), static_cast<int>(variants.size()));
    RobustnessRun run;
    run.leftOut = variants[k].leftOut;
    try {
      const Predictor predictor(scenarioFile, opt.overrides, variants[k].data);
      FitProblem problem(predictor, variants[k].data, opt.folds);
      Step step;
      const DiagnosisResult r = searchCauses(quiet, pool, problem, step, false);
      for (const auto& c : r.causes) run.causes.push_back(c.fit.name), run.fits.push_back(c.fit);
    } catch (const std::exception& e) {
      run.error = e.what();
    }
    run.sameCauses = run.error.empty() && run.causes.size() == causes.size();
    for (size_t c = 0; run.sameCauses && c < causes.size(); ++c) run.sameCauses = run.causes[c] == causes[c].fit.name;
    out.push_back(run);
  }
  if (opt.progress) opt.progress("robustness reruns", static_cast<int>(variants.size()), static_cast<int>(variants.size()));
  return out;
}

}  // namespace

bool DiagnosisResult::isFragile() const {
  for (const auto& r : robustness)
    if (!r.sameCauses) return true;
  return false;
}

DiagnosisResult runDiagnosis(const std::string& scenarioFile, const MeasuredData& data, const DiagnosisOptions& opt) {
  if (opt.progress) opt.progress("reference sweep", 0, 1);
  const Predictor predictor(scenarioFile, opt.overrides, data);
  FitProblem problem(predictor, data, opt.folds);
  std::vector<std::string> unavailable;
  std::vector<Candidate> listed = listCandidates(makeScenarioTree(scenarioFile, opt.overrides),
                                                getUncertainty(scenarioFile, opt), &unavailable);
  for (const std::string& path : getControllerPaths(data))  // set per row/run by the data: not one value
    for (auto it = listed.begin(); it != listed.end();)
      if (it->name == "parameter:" + path) {
        unavailable.push_back(it->name + ": the measured data set it per controller setting");
        it = listed.erase(it);
      } else {
        ++it;
      }
  std::vector<Candidate> all;
  try {
    all = filterCandidates(listed, opt.candidates);
  } catch (const std::invalid_argument& e) {  // say why a known candidate is missing
    std::string why = e.what();
    for (const auto& u : unavailable) why += "; " + u;
    throw std::invalid_argument(why);
  }
  const std::vector<const Candidate*> pool = probeCandidates(scenarioFile, opt, all, unavailable);
  Step step;
  DiagnosisResult result = searchCauses(opt, pool, problem, step, true);
  result.scenarioFile = scenarioFile;
  result.data = &data;
  result.unavailable = unavailable;
  result.extendedOverrides = opt.overrides;
  finish(problem, step, result, opt.threads);
  if (opt.robustness) result.robustness = runRobustness(scenarioFile, data, opt, pool, result.causes);
  return result;
}

}  // namespace motostab::diagnosis
