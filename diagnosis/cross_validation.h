#pragma once
// Scores of K-fold cross-validation with a guard against folds whose fit fails or
// diverges: such a fold must neither poison the cross-validated RMS nor count for the candidate.
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

namespace motostab::diagnosis {

struct FoldScores {
  std::vector<double> rms;           ///< held-out RMS per fold (normalised residuals); NaN for a failed fold
  std::vector<bool> failed;          ///< the fold's fit threw, gave non-finite or diverging predictions
  std::vector<std::string> reasons;  ///< per fold: why it failed ("" when it did not)
  double cvRms = 0;                  ///< RMS over the held-out observations of the folds that did not fail (NaN: none)
  int numFailed = 0;
};

/// Cross-validation scores. foldOf[i]: the fold of observation i (0..K-1). fitFold(f) returns the
/// normalised residuals of every observation predicted by the model refitted without fold f (it may
/// throw). fullFit: the residuals of the model fitted to all data. A fold fails when fitFold throws,
/// returns non-finite residuals on the fold, or its held-out RMS exceeds `divergence` times
/// max(1, the full fit's RMS on that fold) (a fit run off to a degenerate model: an RMS of order 1 is
/// what noise gives). A failed fold has no held-out score: it is marked (the caller counts the
/// candidate as not better there and states how many folds the CV RMS covers), its rms is NaN, and the
/// CV RMS is taken over the other folds' held-out observations (neither poisoned by a diverged fold nor
/// flattered by the full fit's residuals standing in for it). The folds are fitted on up to `threads` threads (fitFold must be thread-safe then).
FoldScores scoreFolds(int numFolds, const std::vector<int>& foldOf, const std::function<Eigen::VectorXd(int)>& fitFold,
                      const Eigen::VectorXd& fullFit, double divergence = 100, int threads = 1);

}  // namespace motostab::diagnosis
