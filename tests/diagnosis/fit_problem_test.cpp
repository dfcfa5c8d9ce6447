// FitProblem's noise components (diagnosis/fit_problem.h): a part of a mode with fewer than
// kMinEstimatedRows rows shares one noise level with the other part, so that a fit matching one or
// two residuals cannot drive its sigma to zero; larger parts keep their own; a part whose rows all
// carry their stderr is known (reported as given), not estimated.
#include "diagnosis/fit_problem.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "diagnosis/prediction.h"
#include "hidden_effect.h"

namespace motostab::diagnosis {
namespace {

const std::string kBenchmark = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

MeasuredEigenvalue makeRow(double v, const std::string& mode, double re, double im, double stderr_ = 0) {
  MeasuredEigenvalue e;
  e.speed = e.speedMin = e.speedMax = v;
  e.mode = analysis::parseModeLabel(mode), e.real = re, e.imag = im, e.realStderr = e.imagStderr = stderr_;
  return e;
}

TEST(FitProblem, PartsWithFewRowsShareTheirModesNoise) {
  testing::Draw draw(9191);
  const int complexCastor = 1 + static_cast<int>(draw.uniform() * (kMinEstimatedRows - 1));  // 1 .. kMin - 1
  MeasuredData data;
  for (int k = 0; k < 10; ++k) {
    const double v = 3 + 0.5 * k;
    data.eigenvalues.push_back(makeRow(v, "weave", -0.1 * k, 4 + 0.3 * k));
    data.eigenvalues.push_back(makeRow(v, "castor", -10 - k, k < complexCastor ? 0.5 : 0));
    data.eigenvalues.push_back(makeRow(v, "capsize", -0.2, k < 2 ? 0.1 : 0, 0.05));  // stderr given
  }
  const Predictor predictor(kBenchmark, {}, data);
  FitProblem p(predictor, data, 5);
  auto has = [&](const std::string& n) { return std::find(p.components.begin(), p.components.end(), n) != p.components.end(); };
  EXPECT_TRUE(has("weave.real") && has("weave.imag"));
  EXPECT_TRUE(has("castor.real+imag"));
  EXPECT_FALSE(has("castor.real") || has("castor.imag"));
  EXPECT_TRUE(has("capsize.real") && has("capsize.imag")) << "rows with stderr estimate nothing: nothing to pool";
  for (const char* n : {"capsize.real", "capsize.imag"}) {  // every row has its stderr: given, not estimated
    const auto k = std::find(p.components.begin(), p.components.end(), n) - p.components.begin();
    EXPECT_TRUE(p.componentKnown[k]) << n;
    EXPECT_DOUBLE_EQ(p.componentSigma[k], 0.05) << n;
  }
  ASSERT_EQ(p.componentSigma.size(), p.components.size());
  ASSERT_EQ(p.componentKnown.size(), p.components.size());
  int castor = 0;
  for (const auto& o : p.observations) {
    ASSERT_GE(o.component, 0);
    ASSERT_LT(o.component, static_cast<int>(p.components.size()));
    const std::string& name = p.components[o.component];
    const std::string mode = analysis::toString(*data.eigenvalues[o.row].mode);
    EXPECT_EQ(name.substr(0, name.find('.')), mode);
    castor += name == "castor.real+imag";
  }
  EXPECT_EQ(castor, 10 + complexCastor);
  // Residuals of 1 sigma on the real parts and 1e-9 on the few imaginary ones: the pooled noise stays
  // near the real parts' level (the imaginary rows alone would give about 1e-9).
  Eigen::VectorXd r = Eigen::VectorXd::Ones(static_cast<Eigen::Index>(p.observations.size()));
  for (size_t i = 0; i < p.observations.size(); ++i)
    if (p.observations[i].part == 1 && data.eigenvalues[p.observations[i].row].mode == analysis::ModeLabel::Castor) r(i) = 1e-9;
  p.updateSigma(r, 0);
  const auto c = std::find(p.components.begin(), p.components.end(), "castor.real+imag") - p.components.begin();
  EXPECT_GT(p.componentSigma[c], 0.5);
}

}  // namespace
}  // namespace motostab::diagnosis
