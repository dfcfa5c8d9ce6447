#include "diagnosis/stepwise_search.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

#include "core/parallel.h"
#include "diagnosis/cause_criteria.h"
#include "diagnosis/model_fit.h"
#include "diagnosis/pair_search.h"
#include "diagnosis/priors.h"

namespace motostab::diagnosis {

using core::runParallel;
namespace {

Eigen::VectorXd joinStart(const Eigen::VectorXd& xCauses, const Candidate& c) {
  const Eigen::VectorXd own = makeModel({}, &c).getStart();
  Eigen::VectorXd x(xCauses.size() + own.size());
  x << xCauses, own;
  return x;
}

// The baseline of the step and every candidate of the pool, each with its own noise.
void fitStep(const FitProblem& problem, SearchState& state, const DiagnosisOptions& opt, const std::string& stage) {
  state.baseline = fitFull(problem, makeModel(state.causes, nullptr), state.xCauses, "baseline", &state.noise);
  state.noise = state.baseline.noise;
  state.fits.assign(state.pool.size(), FitSummary());
  std::atomic<int> done{0};
  std::mutex progressMutex;
  runParallel(state.pool.size(), opt.threads, [&](size_t i) {
    const Candidate& c = *state.pool[i];
    const Eigen::VectorXd x0 = joinStart(state.baseline.x, c);
    state.fits[i] = fitOrFail(problem, makeModel(state.causes, &c), x0, c.name, state.baseline.noise);
    if (std::isfinite(state.fits[i].chi2))  // the table's RMS in the baseline's noise: one metric for all
      state.fits[i].rms = calcRms(problem, makeModel(state.causes, &c), state.fits[i].x, state.baseline.noise);
    std::lock_guard<std::mutex> lock(progressMutex);
    if (opt.progress) opt.progress(stage, ++done, static_cast<int>(state.pool.size()));
  });
}

// Adds the cause fits[k] of candidate `named` to the state and the result; the pool loses it and
// whatever conflicts with it.
void nameCause(const FitProblem& problem, SearchState& state, const std::vector<const Candidate*>& parts,
               const std::vector<FitSummary>& fits, int k, const Candidate* named, const DiagnosisOptions& opt,
               DiagnosisResult& result) {
  result.causes.push_back({fits[k], findIndistinguishable(problem, state.causes, parts, state.baseline, fits, k, opt)});
  state.causes.push_back(named);
  state.xCauses = fits[k].x;
  state.noise = fits[k].noise;
  std::vector<const Candidate*> rest;
  for (const auto* c : state.pool)
    if (c != named && !conflicts(*c, *named)) rest.push_back(c);
  state.pool = rest;
}

}  // namespace

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

void runStepwiseSearch(const FitProblem& problem, SearchState& state, const DiagnosisOptions& opt, DiagnosisResult& result,
                       bool candidateTable) {
  if (state.noise.sigma.empty()) state.noise = problem.getNoise();  // white, sigma 1: the first fit estimates it
  for (int s = 0; s < opt.maxCauses && !state.pool.empty(); ++s) {
    const std::string stage = "step " + std::to_string(s + 1);
    fitStep(problem, state, opt, stage);
    runParallel(state.fits.size(), opt.threads, [&](size_t i) {
      judgeCandidate(problem, state.causes, *state.pool[i], state.baseline, state.fits[i], opt, s == 0 && candidateTable && opt.candidateTableCv);
    });
    if (s == 0) {
      result.candidates = state.fits;
      std::sort(result.candidates.begin(), result.candidates.end(), [](auto& a, auto& b) { return a.bic < b.bic; });
    }
    std::vector<int> contradicting;
    const int k = pickCause(state.fits, state.baseline.bic, &contradicting);
    for (int i : contradicting) result.contradicting.push_back(state.fits[i]);
    if (k >= 0) {
      nameCause(problem, state, state.pool, state.fits, k, state.pool[k], opt, result);
      continue;
    }
    if (!opt.pairSearch || opt.maxCauses - s < 2) break;
    PairSearch pairs = searchPairs(problem, state.causes, state.pool, state.baseline, state.fits, opt);
    result.pairs.insert(result.pairs.end(), pairs.fits.begin(), pairs.fits.end());
    for (int i : pairs.contradicting) result.contradicting.push_back(pairs.fits[i]);
    if (pairs.named < 0) break;
    state.pairs.push_back(pairs.candidates[pairs.named]);
    std::vector<const Candidate*> parts;
    for (const auto& c : pairs.candidates) parts.push_back(&c);
    nameCause(problem, state, parts, pairs.fits, pairs.named, &state.pairs.back(), opt, result);
    ++s;  // a pair counts as two causes
  }
}

}  // namespace motostab::diagnosis
