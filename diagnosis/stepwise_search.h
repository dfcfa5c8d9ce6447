#pragma once
// The forward stepwise search for causes (Draper & Smith 1998, Applied Regression Analysis, 3rd ed.,
// ch. 15): at each step every candidate of the pool is fitted together with the causes named so far
// (each model with its own noise, model_fit.h), judged against the step's baseline (cause_criteria.h),
// and the cause picked by priors.h's rule is added; the search stops when none qualifies or after
// maxCauses causes. When no single candidate qualifies, pairs are searched (pair_search.h).
#include <deque>
#include <vector>

#include "diagnosis/diagnosis.h"
#include "diagnosis/fit_problem.h"

namespace motostab::diagnosis {

/// State of the search between steps.
struct SearchState {
  std::vector<const Candidate*> causes;  ///< named so far
  Eigen::VectorXd xCauses;                ///< their parameters (internal coordinates)
  NoiseState noise;                       ///< the noise of the model of `causes` (start of the next step's fits)
  std::vector<const Candidate*> pool;     ///< candidates still to try
  FitSummary baseline;                    ///< the current step's model of `causes`
  std::vector<FitSummary> fits;           ///< per pool entry
  std::deque<Candidate> pairs;            ///< storage of the pairs named (their merged candidates)
};

/// Runs the search on `problem` from `state.pool` into result.candidates (first step's, best BIC first,
/// every one cross-validated when `candidateTable`), result.causes, result.contradicting and
/// result.pairs.
void runStepwiseSearch(const FitProblem& problem, SearchState& state, const DiagnosisOptions& opt, DiagnosisResult& result,
                       bool candidateTable);

/// True when a and b cannot be in one model (the same switch or the same parameter).
bool conflicts(const Candidate& a, const Candidate& b);

}  // namespace motostab::diagnosis
