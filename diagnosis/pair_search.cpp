#include "diagnosis/pair_search.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/parallel.h"
#include "diagnosis/cause_criteria.h"
#include "diagnosis/least_squares.h"
#include "diagnosis/model_fit.h"
#include "diagnosis/priors.h"
#include "diagnosis/stepwise_search.h"

namespace motostab::diagnosis {

using core::runParallel;
namespace {

std::vector<CandidateParameter> renameParameters(const Candidate& c) {
  std::vector<CandidateParameter> out = c.parameters;
  for (auto& p : out) p.name = p.name == "value" ? p.path : c.name + "." + p.name;
  return out;
}

// The singles to pair: the kPairPool largest deviance gains over the baseline, whatever their sign (a
// member whose effect the other cancels may gain nothing alone). Of two candidates that predict alike
// (Candidate::sameModelAs: steer_friction and steer_damper) only the better is taken: they cannot be
// paired with each other, and the other would take a place that a different effect could use.
std::vector<int> choosePairPool(const std::vector<FitSummary>& fits, const std::vector<const Candidate*>& pool) {
  std::vector<int> order, out;
  for (size_t i = 0; i < fits.size(); ++i)
    if (std::isfinite(fits[i].deviance)) order.push_back(static_cast<int>(i));
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return fits[a].deviance < fits[b].deviance; });
  const auto alike = [&](int a, int b) { return pool[a]->sameModelAs == pool[b]->name || pool[b]->sameModelAs == pool[a]->name; };
  for (int i : order) {
    if (out.size() == static_cast<size_t>(kPairPool)) break;
    if (std::none_of(out.begin(), out.end(), [&](int j) { return alike(i, j); })) out.push_back(i);
  }
  return out;
}

// Each member needed: the pair beats the single fit of either member by BIC and by likelihood ratio.
void requireBothMembers(const FitSummary& a, const FitSummary& b, const Candidate& ca, const Candidate& cb, FitSummary& pair,
                        const DiagnosisOptions& opt) {
  const auto needs = [&](const FitSummary& single, const Candidate& other) {
    const double lr = std::max(0.0, single.deviance - pair.deviance);
    return pair.bic < single.bic && calcChiSquareSurvival(lr, static_cast<int>(other.parameters.size())) < opt.maxPValue;
  };
  if (!needs(a, cb) || !needs(b, ca)) pair.failed.push_back("a member alone explains as much");
}

}  // namespace

Candidate mergeCandidates(const Candidate& a, const Candidate& b) {
  Candidate c{a.name + " + " + b.name, a.fixedOverrides, renameParameters(a)};
  c.fixedOverrides.append(b.fixedOverrides);
  const std::vector<CandidateParameter> pb = renameParameters(b);
  c.parameters.insert(c.parameters.end(), pb.begin(), pb.end());
  return c;
}

PairSearch searchPairs(const FitProblem& problem, const std::vector<const Candidate*>& causes,
                       const std::vector<const Candidate*>& pool, const FitSummary& baseline,
                       const std::vector<FitSummary>& fits, const DiagnosisOptions& opt) {
  PairSearch out;
  const std::vector<int> top = choosePairPool(fits, pool);
  std::vector<std::pair<int, int>> members;
  for (size_t i = 0; i < top.size(); ++i)
    for (size_t j = i + 1; j < top.size(); ++j)
      if (!conflicts(*pool[top[i]], *pool[top[j]])) {
        members.push_back({top[i], top[j]});
        out.candidates.push_back(mergeCandidates(*pool[top[i]], *pool[top[j]]));
      }
  out.fits.resize(members.size());
  const int numCauses = makeModel(causes, nullptr).size();
  runParallel(members.size(), opt.threads, [&](size_t k) {
    const auto [a, b] = members[k];
    const int na = static_cast<int>(pool[a]->parameters.size()), nb = static_cast<int>(pool[b]->parameters.size());
    Eigen::VectorXd x0(numCauses + na + nb);  // the causes' and both members' single estimates
    x0 << fits[a].x, fits[b].x.tail(nb);
    for (auto [m, from] : {std::pair<int, int>{a, numCauses}, {b, numCauses + na}})
      if (fits[m].atBound)  // no gradient at "off at infinity": from the candidate's own start instead
        x0.segment(from, pool[m]->parameters.size()) = makeModel({}, pool[m]).getStart();
    FitSummary& f = out.fits[k];
    f = fitOrFail(problem, makeModel(causes, &out.candidates[k]), x0, out.candidates[k].name, baseline.noise);
    f.members = {pool[a]->name, pool[b]->name};
    judgeCandidate(problem, causes, out.candidates[k], baseline, f, opt, false);
    if (std::isfinite(f.chi2)) requireBothMembers(fits[a], fits[b], *pool[a], *pool[b], f, opt);
  });
  out.named = pickCause(out.fits, baseline.bic, &out.contradicting);
  return out;
}

}  // namespace motostab::diagnosis
