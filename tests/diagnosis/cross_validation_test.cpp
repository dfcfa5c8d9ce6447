// Cross-validation scores with failing folds (diagnosis/cross_validation.h): a fold whose refit throws,
// returns NaN or runs off to a degenerate model (held-out RMS ~1e29, as fork_compliance gave on the
// Kooijman data) is marked failed, has no score (NaN) and is left out of the CV RMS, which covers the
// other folds' held-out residuals only; healthy folds, including one merely a few times worse than the
// full fit, keep their own. Reference: the sums written here.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/portable_random.h"
#include "diagnosis/cross_validation.h"

namespace motostab::diagnosis {

using core::PortableRandom;

namespace {

TEST(CrossValidation, FailedAndDivergingFoldsAreMarkedAndDoNotPoisonTheScore) {
  PortableRandom rng(911);
  const int K = 5 + static_cast<int>(rng.drawBits() % 4), n = 40 + static_cast<int>(rng.drawBits() % 40);
  std::vector<int> foldOf(n);
  for (int i = 0; i < n; ++i) foldOf[i] = i * K / n;
  Eigen::VectorXd full(n), held(n);
  for (int i = 0; i < n; ++i) full(i) = rng.drawUniform(-1.5, 1.5), held(i) = full(i) * rng.drawUniform(1.0, 4.0);
  const int throws = static_cast<int>(rng.drawBits() % K);
  const int nan = (throws + 1) % K, huge = (throws + 2) % K;
  const auto fitFold = [&](int f) -> Eigen::VectorXd {
    if (f == throws) throw std::runtime_error("trim failed");
    Eigen::VectorXd r = held;
    if (f == nan) r(static_cast<int>(std::find(foldOf.begin(), foldOf.end(), f) - foldOf.begin())) = std::nan("");
    if (f == huge) r *= 1e29;
    return r;
  };
  const FoldScores s = scoreFolds(K, foldOf, fitFold, full);
  double total = 0;
  int count = 0;
  for (int f = 0; f < K; ++f) {
    const bool bad = f == throws || f == nan || f == huge;
    EXPECT_EQ(s.failed[f], bad) << f;
    EXPECT_EQ(s.reasons[f].empty(), !bad) << f;
    double sum = 0;
    int m = 0;
    for (int i = 0; i < n; ++i)
      if (foldOf[i] == f) sum += held(i) * held(i), ++m;
    if (bad) {
      EXPECT_TRUE(std::isnan(s.rms[f])) << f;
      continue;
    }
    EXPECT_NEAR(s.rms[f], std::sqrt(sum / m), 1e-12) << f;
    total += sum, count += m;
  }
  EXPECT_EQ(s.numFailed, 3);
  EXPECT_NEAR(s.cvRms, std::sqrt(total / count), 1e-12);
  EXPECT_TRUE(std::isfinite(s.cvRms));
  // Every fold failing: no CV RMS at all.
  const FoldScores none = scoreFolds(K, foldOf, [](int) -> Eigen::VectorXd { throw std::runtime_error("no trim"); }, full);
  EXPECT_EQ(none.numFailed, K);
  EXPECT_TRUE(std::isnan(none.cvRms));
}

}  // namespace
}  // namespace motostab::diagnosis
