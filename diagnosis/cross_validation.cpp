#include "diagnosis/cross_validation.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include "core/parallel.h"

namespace motostab::diagnosis {

using core::runParallel;

namespace {

// Sum of squares of r over the observations of fold f, and their count.
double sumFold(const Eigen::VectorXd& r, const std::vector<int>& foldOf, int f, int& count) {
  double sum = 0;
  count = 0;
  for (size_t i = 0; i < foldOf.size(); ++i)
    if (foldOf[i] == f) sum += r(static_cast<int>(i)) * r(static_cast<int>(i)), ++count;
  return sum;
}

}  // namespace

FoldScores scoreFolds(int numFolds, const std::vector<int>& foldOf, const std::function<Eigen::VectorXd(int)>& fitFold,
                      const Eigen::VectorXd& fullFit, double divergence, int threads) {
  std::vector<Eigen::VectorXd> fitted(numFolds);
  std::vector<std::string> errors(numFolds);
  runParallel(static_cast<size_t>(std::max(numFolds, 0)), threads, [&](size_t f) {
    try {
      fitted[f] = fitFold(static_cast<int>(f));
    } catch (const std::exception& e) {
      errors[f] = std::string("fit failed: ") + e.what();
    }
  });
  FoldScores s;
  s.rms.assign(numFolds, 0.0);
  s.failed.assign(numFolds, false);
  s.reasons.assign(numFolds, "");
  double total = 0;
  int count = 0;
  for (int f = 0; f < numFolds; ++f) {
    int m = 0;
    const double fallback = sumFold(fullFit, foldOf, f, m);
    double sum = 0;
    s.reasons[f] = errors[f];
    if (errors[f].empty()) {
      sum = sumFold(fitted[f], foldOf, f, m);
      if (!std::isfinite(sum)) s.reasons[f] = "non-finite prediction";
      else if (m && std::sqrt(sum / m) > divergence * std::max(1.0, std::sqrt(fallback / m)))
        s.reasons[f] = "diverged (held-out RMS " + std::to_string(std::sqrt(sum / m)) + ")";
    }
    if (!s.reasons[f].empty()) {
      s.failed[f] = true, ++s.numFailed, s.rms[f] = std::nan("");
      continue;
    }
    s.rms[f] = m ? std::sqrt(sum / m) : 0.0;
    total += sum;
    count += m;
  }
  s.cvRms = count > 0 ? std::sqrt(total / count) : std::nan("");
  return s;
}

}  // namespace motostab::diagnosis
