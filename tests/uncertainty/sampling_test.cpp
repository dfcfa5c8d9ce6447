// Counter-based draws: moments of the three distributions (checked against their definitions),
// and independence of a parameter's draws from the other parameters of the section.
#include <gtest/gtest.h>

#include <cmath>
#include "core/portable_random.h"

#include "tests/uncertainty/test_support.h"
#include "uncertainty/sampling.h"

namespace motostab::uncertainty {

using core::PortableRandom;
using scenario::ParameterUncertainty;

namespace {

using D = ParameterUncertainty::Distribution;

struct Moments {
  double mean = 0, std = 0;
};

Moments calcMoments(const std::vector<double>& v) {
  Moments m;
  for (double x : v) m.mean += x;
  m.mean /= v.size();
  for (double x : v) m.std += (x - m.mean) * (x - m.mean);
  m.std = std::sqrt(m.std / (v.size() - 1));
  return m;
}

TEST(Sampling, EachDistributionHasTheStatedMeanAndStandardDeviation) {
  PortableRandom g(20261124);
  const uint64_t seed = g.drawBits();
  const int n = 40000;
  for (D d : {D::Normal, D::Uniform, D::Lognormal}) {
    ParameterUncertainty p;
    p.path = "rear_frame.mass_kg";
    p.distribution = d;
    const double mu = g.drawUniform(1, 100);
    p.sigma = mu * g.drawUniform(0.01, 0.3);
    std::vector<double> x(n);
    for (int i = 0; i < n; ++i) x[i] = drawParameters(seed, static_cast<uint64_t>(i), 0, {p}, {mu})[0];
    const Moments m = calcMoments(x);
    // Standard errors: sigma / sqrt(n) for the mean, about sigma / sqrt(2 n) for the std (x5 margin).
    EXPECT_NEAR(m.mean, mu, 5 * p.sigma / std::sqrt(n)) << static_cast<int>(d);
    EXPECT_NEAR(m.std, p.sigma, 5 * p.sigma * std::sqrt(2.0 / n) * (d == D::Lognormal ? 2 : 1)) << static_cast<int>(d);
    if (d == D::Uniform) {
      for (double v : x) ASSERT_LE(std::abs(v - mu), std::sqrt(3.0) * p.sigma);
    }
    if (d == D::Lognormal) {
      for (double v : x) ASSERT_GT(v, 0);
    }
  }
}

TEST(Sampling, StandardNormalTailsMatchTheNormalDistribution) {
  // P(|z| > 1.96) = 0.05 (two-sided 95 % quantile of the standard normal).
  const int n = 100000;
  int outside = 0;
  for (int i = 0; i < n; ++i) outside += std::abs(drawStandardNormal(7, static_cast<uint64_t>(i), 3, 0)) > 1.959964 ? 1 : 0;
  EXPECT_NEAR(outside / static_cast<double>(n), 0.05, 5 * std::sqrt(0.05 * 0.95 / n));
}

TEST(Sampling, DrawsDependOnlyOnSeedSampleAndPath) {
  PortableRandom g(99);
  const uint64_t seed = g.drawBits(), sample = g.drawBits() % 100000;
  auto make = [](const std::string& path, double sigma) {
    ParameterUncertainty p;
    p.path = path, p.sigma = sigma;
    return p;
  };
  const ParameterUncertainty a = make("geometry.trail_m", 0.002), b = make("rear_frame.com_m[2]", 0.01),
                             c = make("rear_frame.mass_kg", 1.5);
  const auto alone = drawParameters(seed, sample, 0, {a}, {0.08});
  const auto three = drawParameters(seed, sample, 0, {c, b, a}, {85, 0.9, 0.08});
  EXPECT_EQ(alone[0], three[2]);  // bit for bit
  EXPECT_NE(drawParameters(seed, sample + 1, 0, {a}, {0.08})[0], alone[0]);
  EXPECT_NE(drawParameters(seed + 1, sample, 0, {a}, {0.08})[0], alone[0]);
  EXPECT_NE(drawParameters(seed, sample, 1, {a}, {0.08})[0], alone[0]);  // a redraw differs
}

}  // namespace
}  // namespace motostab::uncertainty
