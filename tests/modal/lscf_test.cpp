// LSCF, LSFD and half-power against analytic FRFs with known poles.
#include <gtest/gtest.h>

#include <cmath>

#include "modal/lscf.h"
#include "modal/peak_picking.h"

using motostab::modal::LscfEstimator;
using motostab::modal::LscfOptions;
using motostab::modal::ModalModel;
using motostab::modal::calcStabilisationDiagram;
using motostab::modal::findHalfPowerPeaks;
using motostab::modal::fitModalModel;
using motostab::modal::selectStableModes;


namespace {

using namespace motostab::modal;
using cd = std::complex<double>;

struct AnalyticMode {
  double f, zeta;
  cd residue;
};

cd evaluateReceptance(const std::vector<AnalyticMode>& modes, double f) {
  const cd iw(0, 2 * M_PI * f);
  cd h = 0;
  for (const auto& m : modes) {
    const double w = 2 * M_PI * m.f;
    const cd lambda(-m.zeta * w, w * std::sqrt(1 - m.zeta * m.zeta));
    h += m.residue / (iw - lambda) + std::conj(m.residue) / (iw - std::conj(lambda));
  }
  return h;
}

TEST(Lscf, RecoversPolesOfAnalyticFrfIncludingAClosePair) {
  // Two channels, three modes; 3669/3690 Hz mimic the close pair of the pyFRF data.
  const std::vector<AnalyticMode> ch1{{900, 0.002, cd(0, -1)}, {3669, 0.0008, cd(0, -0.5)}, {3690, 0.0006, cd(0, -0.4)}};
  const std::vector<AnalyticMode> ch2{{900, 0.002, cd(0, -0.3)}, {3669, 0.0008, cd(0, 0.6)}, {3690, 0.0006, cd(0, -0.2)}};
  std::vector<double> f;
  std::vector<std::vector<cd>> h(2);
  for (int k = 0; k <= 6000; ++k) {
    f.push_back(k * 1.0);
    h[0].push_back(evaluateReceptance(ch1, k));
    h[1].push_back(evaluateReceptance(ch2, k));
  }
  LscfOptions o;
  o.fMin = 500;
  o.fMax = 5000;
  o.minOrder = 6;
  o.maxOrder = 20;
  const auto modes = selectStableModes(calcStabilisationDiagram(LscfEstimator(f, h, o)), o);
  ASSERT_EQ(modes.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(modes[i].frequencyHz, ch1[i].f, 1e-5 * ch1[i].f);
    EXPECT_NEAR(modes[i].dampingRatio, ch1[i].zeta, 1e-3 * ch1[i].zeta);
  }
  // LSFD with the identified poles reproduces the residues of channel 1.
  std::vector<cd> poles;
  for (const auto& m : modes) poles.push_back(m.rawLambda);
  const ModalModel model = fitModalModel(f, h[0], 500, 5000, poles);
  for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(std::abs(model.residues[i] - ch1[i].residue), 0.0, 1e-3 * std::abs(ch1[i].residue));
  EXPECT_NEAR(std::abs(model.evaluate(2000) - h[0][2000]), 0.0, 1e-3 * std::abs(h[0][2000]));
}

TEST(HalfPower, RecoversSdofDampingWhenBandwidthIsResolved) {
  const std::vector<AnalyticMode> m{{100, 0.02, cd(0, -1)}};
  std::vector<double> f, y;
  for (int k = 0; k <= 4000; ++k) {
    f.push_back(k * 0.05);
    y.push_back(std::norm(evaluateReceptance(m, k * 0.05)));
  }
  const auto peaks = findHalfPowerPeaks(f, y, 50, 150);
  ASSERT_EQ(peaks.size(), 1u);
  EXPECT_NEAR(peaks[0].frequencyHz, 100 * std::sqrt(1 - 2 * 0.02 * 0.02), 0.05);
  EXPECT_NEAR(peaks[0].dampingRatio, 0.02, 0.02 * 0.02);
  EXPECT_NEAR(peaks[0].lossFactor, 0.04, 0.04 * 0.02);
  // A window decay of sigma_w widens the peak by sigma_w/pi Hz; it is removed again.
  const double sw = 2.0;
  std::vector<double> yw;
  const double wn = 2 * M_PI * 100, sig = 0.02 * wn + sw, wd = wn * std::sqrt(1 - 0.0004);
  for (double fk : f) {
    const cd iw(0, 2 * M_PI * fk), lambda(-sig, wd);
    yw.push_back(std::norm(cd(0, -1) / (iw - lambda) + cd(0, 1) / (iw - std::conj(lambda))));
  }
  const auto pw = findHalfPowerPeaks(f, yw, 50, 150, sw);
  ASSERT_EQ(pw.size(), 1u);
  EXPECT_NEAR(pw[0].dampingRatio, 0.02, 0.02 * 0.03);
}

}  // namespace
