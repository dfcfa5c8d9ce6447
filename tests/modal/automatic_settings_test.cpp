// Automatic band, indicator peaks and orders (modal/automatic_settings.h) on FRF estimates built here
// with known answers: the band edges from a force autospectrum and coherence written in closed form, and
// peaks of modal sums whose relative heights and coherence straddle the thresholds (1 %, 0.99).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdint>

#include "core/portable_random.h"
#include "modal/automatic_settings.h"

using motostab::modal::BandChoice;
using motostab::modal::FrfEstimate;
using motostab::modal::ImpactRecord;
using motostab::modal::OrderChoice;
using motostab::modal::WindowChoice;
using motostab::modal::chooseBand;
using motostab::modal::chooseExponentialWindow;
using motostab::modal::chooseOrders;
using motostab::modal::findIndicatorPeaks;


namespace {

using namespace motostab::modal;
using cd = std::complex<double>;

FrfEstimate makeEstimate(size_t bins, double df) {
  FrfEstimate e;
  e.df = df;
  for (size_t k = 0; k < bins; ++k) e.frequency.push_back(k * df);
  e.forceSpectra.assign(1, std::vector<cd>(bins, 1.0));
  e.h1.assign(1, std::vector<cd>(bins, 0.0));
  e.coherence.assign(1, std::vector<double>(bins, 1.0));
  e.averages = 1;
  return e;
}

TEST(AutomaticSettings, BandEndsWhereForceDropsTwentyDbAndStartsWhereCoherenceHolds) {
  motostab::core::PortableRandom rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const double fc = rng.drawUniform(80, 200), fLow = std::floor(rng.drawUniform(15, 60));
    FrfEstimate e = makeEstimate(513, 1.0);  // Nyquist 512 Hz
    for (size_t k = 0; k < 513; ++k) {
      const double f = e.frequency[k];
      e.forceSpectra[0][k] = 1.0 / std::sqrt(1 + std::pow(f / fc, 8));  // |F|^2 = 1/(1 + (f/fc)^8)
      e.coherence[0][k] = f < fLow ? 0.5 : 0.97;
      if (k > 100 && k % 37 == 0) e.coherence[0][k] = 0.1;  // single-bin antiresonance dips must not cut the band
    }
    // Last bin whose power is >= 1 % of the maximum (bin 0), written from the closed form.
    const double fForce = std::floor(fc * std::pow(99.0, 1.0 / 8));
    const BandChoice b = chooseBand(e);
    EXPECT_DOUBLE_EQ(b.fMin, fLow) << trial;
    EXPECT_DOUBLE_EQ(b.fMax, std::min(fForce, 409.0)) << trial;  // 0.8 Nyquist = 409.6 Hz
  }
}

TEST(AutomaticSettings, NoUsableBandIsAnErrorSayingWhy) {
  FrfEstimate e = makeEstimate(513, 1.0);
  for (auto& c : e.coherence[0]) c = 0.3;
  try {
    chooseBand(e);
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& x) {
    EXPECT_NE(std::string(x.what()).find("coherence"), std::string::npos) << x.what();
  }
}

// Modal sum sum_r A_r / (w_r^2 - w^2 + 2 i zeta w_r w): peaks 100 % (40 Hz), 1.3 % (150 Hz), 0.3 % (250 Hz,
// below the 1 % threshold even with the neighbours' tails), 5 % at 320 Hz but with coherence 0.95 there.
TEST(AutomaticSettings, IndicatorPeaksKeepWeakCoherentPeaksOnly) {
  FrfEstimate e = makeEstimate(1025, 0.5);
  const double fr[4] = {40, 150, 250, 320}, rel[4] = {1.0, 0.013, 0.003, 0.05}, zeta = 0.01;
  for (size_t k = 1; k < e.frequency.size(); ++k) {
    const double w = 2 * M_PI * e.frequency[k];
    for (int r = 0; r < 4; ++r) {
      const double wr = 2 * M_PI * fr[r];
      const double a = rel[r] * 2 * zeta * wr * wr;  // peak height rel[r] at its own resonance
      e.h1[0][k] += a / cd(wr * wr - w * w, 2 * zeta * wr * w);
    }
    if (std::abs(e.frequency[k] - 320) < 10) e.coherence[0][k] = 0.95;
  }
  const auto peaks = findIndicatorPeaks(e, 10, 400);
  for (const auto& p : peaks) std::printf("peak %.2f Hz rel %.4f coh %.4f\n", p.frequencyHz, p.relativeAmplitude, p.coherence);
  ASSERT_EQ(peaks.size(), 2u);
  EXPECT_NEAR(peaks[0].frequencyHz, 40, 0.5);
  EXPECT_NEAR(peaks[1].frequencyHz, 150, 0.5);
  EXPECT_NEAR(peaks[1].relativeAmplitude, 0.013, 0.002);
  EXPECT_GT(peaks[1].coherence, 0.99);
}

TEST(AutomaticSettings, OrdersFollowThePeakCount) {
  for (size_t n : {0u, 1u, 3u, 9u, 40u}) {
    const OrderChoice o = chooseOrders(n, 2000);
    EXPECT_EQ(o.minOrder, std::max<int>(4, 2 * n));
    EXPECT_EQ(o.maxOrder, std::min<int>(160, 4 * n + 24));
  }
  EXPECT_EQ(chooseOrders(9, 30).maxOrder, 28);  // never more than the band bins minus 2
}

// Decaying sines x = exp(-sigma t) sin(w t) over T = 1 s: the RMS of the last 10 % relative to the peak is
// about exp(-0.95 sigma) / sqrt(2) (envelope at the middle of the tail; peak ~1 for light decay).
TEST(AutomaticSettings, ExponentialWindowOnlyAsStrongAsTheTailNeeds) {
  auto record = [](double sigma) {
    ImpactRecord r;
    r.dt = 1.0 / 4096;
    r.force.assign(4096, 0.0);
    r.responses.assign(1, std::vector<double>(4096));
    for (size_t k = 0; k < 4096; ++k) r.responses[0][k] = std::exp(-sigma * k * r.dt) * std::sin(2 * M_PI * 200.5 * k * r.dt);
    return std::vector<ImpactRecord>{r};
  };
  EXPECT_EQ(chooseExponentialWindow(record(8.0)).endValue, 1.0);  // tail 0.05 % of the peak: no window
  EXPECT_EQ(chooseExponentialWindow(record(0.0)).endValue, 0.05);  // no decay at all: the strongest window
  const double sigma = 1.0, tail = std::exp(-0.95 * sigma) / std::sqrt(2.0);  // about 27 %
  const WindowChoice w = chooseExponentialWindow(record(sigma));
  EXPECT_NEAR(w.tail, tail, 0.02 * tail);
  EXPECT_NEAR(w.endValue, std::max(0.05, 0.01 / tail), 0.02 * w.endValue);
}

}  // namespace
