// Hit checks, windows, DFT and H1 against analytic references.
#include <gtest/gtest.h>

#include <cmath>

#include "core/portable_random.h"
#include "modal/lscf.h"
#include "modal/spectra.h"

using motostab::modal::HitCheck;
using motostab::modal::HitCheckOptions;
using motostab::modal::ImpactRecord;
using motostab::modal::LscfEstimator;
using motostab::modal::LscfOptions;
using motostab::modal::WindowOptions;
using motostab::modal::calcExponentialDecayRate;
using motostab::modal::calcForceWindow;
using motostab::modal::calcRealDft;
using motostab::modal::calcStabilisationDiagram;
using motostab::modal::checkHit;
using motostab::modal::estimateH1;
using motostab::modal::selectStableModes;


namespace {

using namespace motostab::modal;

ImpactRecord makeHalfSineHit(size_t n, double dt, double start, double width, double peak) {
  ImpactRecord r;
  r.dt = dt;
  r.force.assign(n, 0.0);
  for (size_t k = 0; k < n; ++k) {
    const double s = (k * dt - start) / width;
    if (s > 0 && s < 1) r.force[k] = peak * std::sin(M_PI * s);
  }
  r.responses = {std::vector<double>(n, 0.0)};
  for (size_t k = 0; k < n; ++k) r.responses[0][k] = 0.1 * std::sin(0.3 * k);
  return r;
}

TEST(HitCheck, CleanPulseHasNoProblemsAndIsLocated) {
  const auto hit = makeHalfSineHit(1000, 1e-4, 0.01, 0.001, 100);
  const auto c = checkHit(hit);
  EXPECT_TRUE(c.problems.empty());
  EXPECT_NEAR(c.peakForce, 100, 1.0);
  EXPECT_NEAR(c.pulseStart * 1e-4, 0.01, 2e-4);
  EXPECT_NEAR(c.pulseEnd * 1e-4, 0.011, 2e-4);
}

TEST(HitCheck, DoubleHitIsDetected) {
  auto hit = makeHalfSineHit(1000, 1e-4, 0.01, 0.001, 100);
  const auto second = makeHalfSineHit(1000, 1e-4, 0.02, 0.001, 25);
  for (size_t k = 0; k < hit.force.size(); ++k) hit.force[k] += second.force[k];
  const auto c = checkHit(hit);
  ASSERT_EQ(c.problems.size(), 1u);
  EXPECT_NE(c.problems[0].find("double hit"), std::string::npos);
}

TEST(HitCheck, OverloadByFlatTopAndByStatedRange) {
  auto hit = makeHalfSineHit(1000, 1e-4, 0.01, 0.001, 100);
  for (auto& v : hit.responses[0]) v = std::clamp(v, -0.08, 0.08);  // clipped converter
  auto c = checkHit(hit);
  ASSERT_EQ(c.problems.size(), 1u);
  EXPECT_NE(c.problems[0].find("overload on response channel 1"), std::string::npos);
  const auto clean = makeHalfSineHit(1000, 1e-4, 0.01, 0.001, 100);
  HitCheckOptions o;
  o.forceRange = 90;
  c = checkHit(clean, o);
  ASSERT_EQ(c.problems.size(), 1u);
  EXPECT_NE(c.problems[0].find("overload on force"), std::string::npos);
}

TEST(Windows, ForceWindowCoversPulseAndExponentialRate) {
  const auto w = calcForceWindow(100, 20, 25);
  EXPECT_EQ(w[10], 0.0);
  for (size_t k = 15; k < 30; ++k) EXPECT_EQ(w[k], 1.0);
  EXPECT_GT(w[30], 0.0);
  EXPECT_LT(w[30], 1.0);
  EXPECT_EQ(w[60], 0.0);
  EXPECT_NEAR(calcExponentialDecayRate(2.0, 0.01), std::log(100.0) / 2.0, 1e-12);
}

TEST(Dft, MatchesDirectSum) {
  std::vector<double> x(37);
  for (size_t i = 0; i < x.size(); ++i) x[i] = std::cos(0.7 * i) + 0.01 * i * i;
  const auto y = calcRealDft(x);
  ASSERT_EQ(y.size(), 19u);
  for (size_t k = 0; k < y.size(); ++k) {
    std::complex<double> s = 0;
    for (size_t n = 0; n < x.size(); ++n) s += x[n] * std::polar(1.0, -2 * M_PI * k * n / x.size());
    EXPECT_NEAR(std::abs(y[k] - s), 0.0, 1e-9);
  }
}

// SDOF oscillator struck by a one-sample impulse: the acceleration is known in closed form, so H1 with an
// exponential window and LSCF must give back f and zeta once the window decay is removed.
TEST(H1, ExponentialWindowCorrectionRecoversSdofDamping) {
  const double fs = 1000, f0 = 73.0, zeta = 0.004, m = 2.0, dt = 1 / fs;
  const double w0 = 2 * M_PI * f0, wd = w0 * std::sqrt(1 - zeta * zeta), sigma = zeta * w0;
  const size_t n = 2000, k0 = 10;
  motostab::core::PortableRandom rng(3);
  std::vector<ImpactRecord> hits;
  for (int h = 0; h < 4; ++h) {
    ImpactRecord r;
    r.dt = dt;
    r.force.assign(n, 0.0);
    const double impulse = 0.5 + 0.1 * h;  // N s
    r.force[k0] = impulse / dt;
    r.responses = {std::vector<double>(n, 0.0)};
    for (size_t k = k0 + 1; k < n; ++k) {
      // x = I/(m wd) e^{-sigma t} sin(wd t); a = x''
      const double t = (k - k0) * dt, e = std::exp(-sigma * t);
      const double a = impulse / (m * wd) * e * ((sigma * sigma - wd * wd) * std::sin(wd * t) - 2 * sigma * wd * std::cos(wd * t));
      r.responses[0][k] = a + 1e-3 * rng.drawNormal();
    }
    hits.push_back(r);
  }
  WindowOptions w;
  w.exponentialEndValue = 0.01;  // adds a decay 2.3/s, i.e. more than the true 1.8/s
  const auto frf = estimateH1(hits, w);
  EXPECT_NEAR(frf.windowDecayRate, std::log(100.0) / 2.0, 1e-12);
  const size_t peak = static_cast<size_t>(std::lround(f0 / frf.df));
  EXPECT_GT(frf.coherence[0][peak], 0.999);
  LscfOptions o;
  o.fMin = 20;
  o.fMax = 200;
  o.minOrder = 2;
  o.maxOrder = 12;
  o.windowDecayRate = frf.windowDecayRate;
  const auto modes = selectStableModes(calcStabilisationDiagram(LscfEstimator(frf.frequency, frf.h1, o)), o);
  ASSERT_EQ(modes.size(), 1u);
  EXPECT_NEAR(modes[0].frequencyHz, f0, 1e-3 * f0);
  EXPECT_NEAR(modes[0].dampingRatio, zeta, 0.03 * zeta);
}

}  // namespace
