// Synthetic responses with known modes. References are the generating parameters; noise tolerances are
// Cramer-Rao bounds computed here from the analytic Jacobian of the model (independent of the code under test).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <iostream>
#include <stdexcept>

#include <Eigen/Dense>

#include "core/portable_random.h"
#include "io/input_error.h"
#include "response/mode_identification.h"

using motostab::response::IdentificationOptions;
using motostab::response::IdentificationResult;
using motostab::response::IdentifiedMode;
using motostab::response::identifyModes;


namespace {


struct TrueMode {
  double sigma, omega, amplitude, phase;  // 1/s, rad/s (0: real exponential), signal units, rad
};

std::vector<double> makeUniformTime(double duration, double step) {
  std::vector<double> t;
  for (int i = 0; i * step <= duration + 1e-12; ++i) t.push_back(i * step);
  return t;
}

// Random steps uniform in [minStep, maxStep].
std::vector<double> makeJitteredTime(double duration, double minStep, double maxStep, unsigned seed) {
  motostab::core::PortableRandom rng(seed);
  std::vector<double> t{0.0};
  while (t.back() < duration) t.push_back(t.back() + rng.drawUniform(minStep, maxStep));
  return t;
}

std::vector<double> makeSignal(const std::vector<double>& t, double offset, const std::vector<TrueMode>& modes,
                               double noiseStd, unsigned seed) {
  motostab::core::PortableRandom rng(seed);
  std::vector<double> y;
  for (double ti : t) {
    double v = offset;
    for (const auto& m : modes) v += m.amplitude * std::exp(m.sigma * ti) * std::cos(m.omega * ti + m.phase);
    y.push_back(v + noiseStd * rng.drawNormal());
  }
  return y;
}

// Cramer-Rao standard deviations of (sigma, omega) of each mode for white Gaussian noise of `noiseStd`:
// Fisher matrix J^T J / noiseStd^2 over parameters {offset, per mode a, b, sigma, omega} of
// offset + sum e^{sigma t} (a cos wt + b sin wt).
std::vector<std::pair<double, double>> calcCramerRao(const std::vector<double>& t, const std::vector<TrueMode>& modes,
                                                     double noiseStd) {
  const int n = static_cast<int>(t.size());
  int np = 1;
  for (const auto& m : modes) np += m.omega > 0 ? 4 : 2;
  Eigen::MatrixXd jac(n, np);
  for (int i = 0; i < n; ++i) {
    int c = 0;
    jac(i, c++) = 1;
    for (const auto& m : modes) {
      const double e = std::exp(m.sigma * t[i]);
      if (m.omega > 0) {
        const double a = m.amplitude * std::cos(m.phase), b = -m.amplitude * std::sin(m.phase);
        const double cw = std::cos(m.omega * t[i]), sw = std::sin(m.omega * t[i]);
        jac(i, c++) = e * cw;
        jac(i, c++) = e * sw;
        jac(i, c++) = t[i] * e * (a * cw + b * sw);
        jac(i, c++) = t[i] * e * (-a * sw + b * cw);
      } else {
        const double a = m.amplitude * std::cos(m.phase);
        jac(i, c++) = e;
        jac(i, c++) = t[i] * e * a;
      }
    }
  }
  const Eigen::MatrixXd cov = (jac.transpose() * jac).inverse() * noiseStd * noiseStd;
  std::vector<std::pair<double, double>> out;
  int c = 1;
  for (const auto& m : modes) {
    if (m.omega > 0) {
      out.emplace_back(std::sqrt(cov(c + 2, c + 2)), std::sqrt(cov(c + 3, c + 3)));
      c += 4;
    } else {
      out.emplace_back(std::sqrt(cov(c + 1, c + 1)), 0.0);
      c += 2;
    }
  }
  return out;
}

const IdentifiedMode& findNearest(const IdentificationResult& r, const TrueMode& m) {
  if (r.modes.empty()) throw std::runtime_error("no mode identified");
  const IdentifiedMode* best = &r.modes.front();
  for (const auto& x : r.modes)
    if (std::hypot(x.real - m.sigma, x.imag - m.omega) < std::hypot(best->real - m.sigma, best->imag - m.omega))
      best = &x;
  return *best;
}

// Weave-like and wobble-like modes of a motorcycle (orders of magnitude from Sharp 1971), plus an offset.
const std::vector<TrueMode> kTwoModes = {{-1.2, 5.4, 1.0, 0.3}, {-4.0, 45.0, 0.4, -1.1}};
constexpr double kTwoModesOffset = 2.5;

TEST(ResponseSynthetic, OneModeNoiseFreeIsExact) {
  const auto t = makeUniformTime(4.0, 0.01);
  const std::vector<TrueMode> modes = {{-0.8, 6.0, 1.5, 0.7}};
  const auto y = makeSignal(t, 0.7, modes, 0.0, 1);
  const auto r = identifyModes(t, {y});
  EXPECT_EQ(r.order, 2);
  ASSERT_EQ(r.modes.size(), 1u);
  const auto& m = r.modes.front();
  EXPECT_NEAR(m.real, -0.8, 1e-9);
  EXPECT_NEAR(m.imag, 6.0, 1e-9);
  EXPECT_NEAR(m.frequencyHz, 6.0 / (2 * M_PI), 1e-9);
  EXPECT_NEAR(m.dampingRatio, 0.8 / std::hypot(0.8, 6.0), 1e-9);
  EXPECT_NEAR(m.amplitude[0], 1.5, 1e-9);
  EXPECT_NEAR(m.phase[0], 0.7, 1e-9);
  EXPECT_NEAR(r.offset[0], 0.7, 1e-9);
  EXPECT_GT(r.rSquared, 1 - 1e-12);
  // The model evaluates back to the signal, also off the samples.
  const std::vector<double> probe = {0.005, 1.2345, 3.999};
  const auto model = motostab::response::calcModelResponse(r, 0, probe);
  const auto exact = makeSignal(probe, 0.7, modes, 0.0, 1);
  for (size_t i = 0; i < probe.size(); ++i) EXPECT_NEAR(model[i], exact[i], 1e-9);
}

// Two modes + offset at growing noise: errors within 5 Cramer-Rao standard deviations (tolerance proportional
// to noise); noise-free within 1e-8.
class ResponseSyntheticNoise : public ::testing::TestWithParam<double> {};

TEST_P(ResponseSyntheticNoise, TwoModesUniformSampling) {
  const double noise = GetParam();
  const auto t = makeUniformTime(3.0, 0.005);
  const auto y = makeSignal(t, kTwoModesOffset, kTwoModes, noise, 42);
  const auto r = identifyModes(t, {y});
  EXPECT_EQ(r.order, 4);
  const auto crb = calcCramerRao(t, kTwoModes, noise);
  for (size_t i = 0; i < kTwoModes.size(); ++i) {
    const auto& m = findNearest(r, kTwoModes[i]);
    const double tolSigma = noise > 0 ? 5 * crb[i].first : 1e-8;
    const double tolOmega = noise > 0 ? 5 * crb[i].second : 1e-8;
    std::cout << "noise " << noise << " mode " << i << ": real error " << m.real - kTwoModes[i].sigma
              << " (CRB std " << crb[i].first << "), imag error " << m.imag - kTwoModes[i].omega << " (CRB std "
              << crb[i].second << ")\n";
    EXPECT_NEAR(m.real, kTwoModes[i].sigma, tolSigma) << "mode " << i;
    EXPECT_NEAR(m.imag, kTwoModes[i].omega, tolOmega) << "mode " << i;
  }
}

TEST_P(ResponseSyntheticNoise, TwoModesNonUniformSampling) {
  const double noise = GetParam();
  const auto t = makeJitteredTime(3.0, 0.002, 0.008, 7);
  const auto y = makeSignal(t, kTwoModesOffset, kTwoModes, noise, 43);
  const auto r = identifyModes(t, {y});
  EXPECT_TRUE(r.resampled);
  EXPECT_EQ(r.order, 4);
  const auto crb = calcCramerRao(t, kTwoModes, noise);
  for (size_t i = 0; i < kTwoModes.size(); ++i) {
    const auto& m = findNearest(r, kTwoModes[i]);
    std::cout << "non-uniform, noise " << noise << " mode " << i << ": real error " << m.real - kTwoModes[i].sigma
              << " (CRB std " << crb[i].first << "), imag error " << m.imag - kTwoModes[i].omega << " (CRB std "
              << crb[i].second << ")\n";
    EXPECT_NEAR(m.real, kTwoModes[i].sigma, noise > 0 ? 5 * crb[i].first : 1e-8) << "mode " << i;
    EXPECT_NEAR(m.imag, kTwoModes[i].omega, noise > 0 ? 5 * crb[i].second : 1e-8) << "mode " << i;
  }
}

// Noise std in signal units (the weave amplitude is 1). Above ~0.05 the short wobble transient sinks into the
// noise floor of the Hankel singular values and only the weave is reported (see the single-mode test).
INSTANTIATE_TEST_SUITE_P(Noise, ResponseSyntheticNoise, ::testing::Values(0.0, 0.003, 0.01, 0.03, 0.05));

// One mode at high noise (up to 30 % of the amplitude): still within 5 Cramer-Rao standard deviations.
TEST(ResponseSynthetic, OneModeHighNoise) {
  const std::vector<TrueMode> modes = {{-0.7, 4.0, 1.0, 1.0}};
  const auto t = makeJitteredTime(4.0, 0.004, 0.012, 5);
  for (double noise : {0.1, 0.3}) {
    const auto r = identifyModes(t, {makeSignal(t, 0.4, modes, noise, 77)});
    const auto crb = calcCramerRao(t, modes, noise);
    const auto& m = findNearest(r, modes[0]);
    std::cout << "one mode, noise " << noise << ": real error " << m.real + 0.7 << " (CRB std " << crb[0].first
              << "), imag error " << m.imag - 4.0 << " (CRB std " << crb[0].second << ")\n";
    EXPECT_EQ(r.order, 2) << "noise " << noise;
    EXPECT_NEAR(m.real, -0.7, 5 * crb[0].first) << "noise " << noise;
    EXPECT_NEAR(m.imag, 4.0, 5 * crb[0].second) << "noise " << noise;
  }
}

// Over 20 noise realisations the RMS error approaches the Cramer-Rao bound (an efficient estimator).
TEST(ResponseSynthetic, RmsErrorNearCramerRaoBound) {
  const double noise = 0.02;
  const auto t = makeUniformTime(3.0, 0.005);
  const auto crb = calcCramerRao(t, kTwoModes, noise);
  double sumSigma = 0, sumOmega = 0;
  const int runs = 20;
  for (int seed = 0; seed < runs; ++seed) {
    const auto r = identifyModes(t, {makeSignal(t, kTwoModesOffset, kTwoModes, noise, 1000 + seed)});
    const auto& m = findNearest(r, kTwoModes[0]);
    sumSigma += std::pow(m.real - kTwoModes[0].sigma, 2);
    sumOmega += std::pow(m.imag - kTwoModes[0].omega, 2);
  }
  const double rmsSigma = std::sqrt(sumSigma / runs), rmsOmega = std::sqrt(sumOmega / runs);
  std::cout << "weave RMS error over " << runs << " runs: real " << rmsSigma << " (CRB " << crb[0].first
            << "), imag " << rmsOmega << " (CRB " << crb[0].second << ")\n";
  EXPECT_LT(rmsSigma, 1.6 * crb[0].first);
  EXPECT_LT(rmsOmega, 1.6 * crb[0].second);
}

TEST(ResponseSynthetic, RealExponentialAndGrowingPair) {
  // A decaying real mode (capsize-like) and a growing oscillation (unstable weave).
  const std::vector<TrueMode> modes = {{-0.6, 0.0, 0.5, 0.0}, {0.4, 8.0, 0.2, 2.0}};
  const auto t = makeUniformTime(2.5, 0.004);
  const auto y = makeSignal(t, -0.3, modes, 0.0, 3);
  const auto r = identifyModes(t, {y});
  EXPECT_EQ(r.order, 3);
  const auto& real = findNearest(r, modes[0]);
  EXPECT_NEAR(real.real, -0.6, 1e-8);
  EXPECT_EQ(real.imag, 0.0);
  EXPECT_NEAR(real.dampingRatio, 1.0, 1e-12);
  EXPECT_NEAR(real.amplitude[0], 0.5, 1e-8);
  const auto& pair = findNearest(r, modes[1]);
  EXPECT_NEAR(pair.real, 0.4, 1e-8);
  EXPECT_NEAR(pair.imag, 8.0, 1e-8);
  EXPECT_LT(pair.dampingRatio, 0.0);
  EXPECT_NEAR(r.offset[0], -0.3, 1e-8);
}

TEST(ResponseSynthetic, NoOffsetOptionFitsPureModes) {
  const std::vector<TrueMode> modes = {{-0.5, 3.0, 2.0, -0.4}};
  const auto t = makeUniformTime(5.0, 0.01);
  IdentificationOptions o;
  o.fitOffset = false;
  const auto r = identifyModes(t, {makeSignal(t, 0.0, modes, 0.0, 1)}, o);
  ASSERT_EQ(r.modes.size(), 1u);
  EXPECT_NEAR(r.modes[0].real, -0.5, 1e-9);
  EXPECT_NEAR(r.modes[0].imag, 3.0, 1e-9);
  EXPECT_EQ(r.offset[0], 0.0);
}

TEST(ResponseSynthetic, WindowSelectsSamplesAndReferenceTime) {
  // Before t = 1 s the record holds something else (a ramp): only the window is fitted.
  auto t = makeUniformTime(4.0, 0.005);
  std::vector<double> y;
  for (double ti : t)
    y.push_back(ti < 1.0 ? 5 * ti : 1.0 + 0.8 * std::exp(-0.9 * (ti - 1.0)) * std::cos(7.0 * (ti - 1.0) + 0.2));
  IdentificationOptions o;
  o.windowStart = 1.0;
  o.windowEnd = 3.5;
  const auto r = identifyModes(t, {y}, o);
  ASSERT_FALSE(r.modes.empty());
  EXPECT_NEAR(r.referenceTime, 1.0, 1e-12);
  EXPECT_NEAR(r.windowEnd, 3.5, 1e-12);
  EXPECT_NEAR(r.modes[0].real, -0.9, 1e-8);
  EXPECT_NEAR(r.modes[0].imag, 7.0, 1e-8);
  EXPECT_NEAR(r.modes[0].amplitude[0], 0.8, 1e-8);
  EXPECT_NEAR(r.modes[0].phase[0], 0.2, 1e-8);
}

TEST(ResponseSynthetic, JointFitOfSignalsWithDifferentScales) {
  // Roll rate (rad/s) and steer torque-like signal (x1000) share the modes; their noise is 2 % of each scale.
  const auto t = makeUniformTime(3.0, 0.005);
  const std::vector<TrueMode> second = {{-1.2, 5.4, 400.0, 2.0}, {-4.0, 45.0, 900.0, 0.5}};
  const auto y1 = makeSignal(t, kTwoModesOffset, kTwoModes, 0.02, 11);
  const auto y2 = makeSignal(t, -50.0, second, 20.0, 12);
  const auto joint = identifyModes(t, {y1, y2});
  const auto crb = calcCramerRao(t, kTwoModes, 0.02);  // bound of signal 1 alone; the joint fit does better
  EXPECT_EQ(joint.order, 4);
  for (size_t i = 0; i < kTwoModes.size(); ++i) {
    const auto& m = findNearest(joint, kTwoModes[i]);
    EXPECT_NEAR(m.real, kTwoModes[i].sigma, 5 * crb[i].first);
    EXPECT_NEAR(m.imag, kTwoModes[i].omega, 5 * crb[i].second);
    ASSERT_EQ(m.amplitude.size(), 2u);
  }
  const auto& wobble = findNearest(joint, kTwoModes[1]);
  EXPECT_NEAR(wobble.amplitude[1], 900.0, 900.0 * 0.05);
  EXPECT_NEAR(joint.offset[1], -50.0, 2.0);
}

TEST(ResponseSynthetic, FixedOrderIsHonoured) {
  const auto t = makeUniformTime(3.0, 0.005);
  IdentificationOptions o;
  o.fixedOrder = 2;
  const auto r = identifyModes(t, {makeSignal(t, kTwoModesOffset, kTwoModes, 0.0, 1)}, o);
  EXPECT_EQ(r.order, 2);
  ASSERT_EQ(r.modes.size(), 1u);
  EXPECT_NEAR(r.modes[0].imag, 5.4, 0.5);  // the dominant (weave) mode, biased by the unmodelled wobble
}

TEST(ResponseSynthetic, RejectsBadInput) {
  const auto t = makeUniformTime(1.0, 0.01);
  const auto y = makeSignal(t, 0.0, {{-1, 10, 1, 0}}, 0.0, 1);
  auto shortY = y;
  shortY.pop_back();
  EXPECT_THROW(identifyModes(t, {shortY}), motostab::io::InputError);
  EXPECT_THROW(identifyModes(t, {}), motostab::io::InputError);
  auto badT = t;
  badT[10] = badT[9];
  EXPECT_THROW(identifyModes(badT, {y}), motostab::io::InputError);
  IdentificationOptions o;
  o.windowStart = 0.5;
  o.windowEnd = 2.0;  // beyond the last sample (1 s)
  try {
    identifyModes(t, {y}, o);
    FAIL() << "no error";
  } catch (const motostab::io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("outside the data"), std::string::npos) << e.what();
  }
  o.windowStart = 0.5;
  o.windowEnd = 0.55;  // 6 samples
  EXPECT_THROW(identifyModes(t, {y}, o), motostab::io::InputError);
  EXPECT_THROW(identifyModes(t, {std::vector<double>(t.size(), 3.0)}), motostab::io::InputError);
}

}  // namespace
