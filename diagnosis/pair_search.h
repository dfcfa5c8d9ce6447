#pragma once
// Pairs of candidates for effects that partly cancel (a compliant fork and a longer trail: each alone
// moves the weave one way, together they fit), searched when no single candidate qualifies as a cause.
// Bounded: the kPairPool single candidates with the largest deviance gain over the step's baseline
// (finite fits, whatever the sign of their gain) are paired with each other (at most kPairPool (kPairPool - 1) / 2 =
// 15 pairs; pairs that conflict, the same switch or parameter, are skipped). A member that gains
// nothing alone can still be found when the pool is not full; one ranked below kPairPool by its single
// gain is not (a greedy bound). Each pair is fitted as one model from its members' single estimates (a
// member held at a bound alone starts from its candidate's start) and judged by cause_criteria.h's criteria against the
// baseline (the likelihood ratio with as many degrees of freedom as both members' parameters, no
// mixture); in addition each member must be needed: the pair's BIC below each member's single BIC and
// its likelihood ratio against each member alone significant (p < maxPValue with the other member's
// parameters as degrees of freedom). priors.h's rule picks among the qualifying pairs.
#include <vector>

#include "diagnosis/diagnosis.h"
#include "diagnosis/fit_problem.h"

namespace motostab::diagnosis {

/// Singles paired at most (by deviance gain).
constexpr int kPairPool = 6;

struct PairSearch {
  std::vector<Candidate> candidates;  ///< the merged pairs (name "a + b"; parameters of both)
  std::vector<FitSummary> fits;       ///< per pair, judged (FitSummary::members: a, b)
  int named = -1;                     ///< the pair picked (-1: none)
  std::vector<int> contradicting;     ///< pairs that fit but contradict a measurement (priors.h)
};

/// One model of both candidates: a's then b's overrides and parameters. A parameter named "value" (a
/// scenario parameter) is renamed to its key path, others to "<candidate>.<name>", so that each is unique.
Candidate mergeCandidates(const Candidate& a, const Candidate& b);

/// The pair search of a step whose single candidates `pool` were fitted and judged into `fits` against
/// `baseline` (the model of `causes`).
PairSearch searchPairs(const FitProblem& problem, const std::vector<const Candidate*>& causes,
                       const std::vector<const Candidate*>& pool, const FitSummary& baseline,
                       const std::vector<FitSummary>& fits, const DiagnosisOptions& opt);

}  // namespace motostab::diagnosis
