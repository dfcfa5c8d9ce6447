// Uncertainty studies on the Whipple benchmark (Meijaard et al. 2007): Monte Carlo spread against
// the first-order estimate computed here by the test's own central differences, zero sigmas,
// single-parameter shares, and reproducibility across threads.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include "core/portable_random.h"

#include "analysis/sweep.h"
#include "tests/uncertainty/test_support.h"
#include "uncertainty/distributed.h"
#include "uncertainty/sampling.h"
#include "uncertainty/uncertainty_summary.h"
#include "vehicle/vehicle_model.h"

namespace motostab::uncertainty {

using analysis::SweepOptions;
using analysis::SweepResult;
using analysis::runSweep;
using core::PortableRandom;
using scenario::ParameterUncertainty;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

constexpr double kStart = 3.5, kStop = 7.0, kStep = 0.5;  // brackets the weave (4.29) and capsize (6.02) speeds

UncertaintyOptions makeOptions(size_t samples, uint64_t seed) {
  UncertaintyOptions o;
  o.samples = samples, o.seed = seed, o.start = kStart, o.stop = kStop, o.step = kStep;
  return o;
}

std::vector<TaskResult> runAll(const UncertaintySetup& s, int threads) {
  std::vector<size_t> all(getTaskCount(s));
  for (size_t t = 0; t < all.size(); ++t) all[t] = t;
  return runTasks(s, all, threads);
}

// First weave and capsize crossings of the Whipple scenario with "path=value" overrides (the test's
// own sweep, outside the study code).
std::array<double, 2> calcCriticalSpeeds(const std::vector<std::string>& overrides) {
  const std::string file = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";
  const VehicleModel model(loadScenario(file, overrides));
  SweepOptions opt;
  opt.start = kStart, opt.stop = kStop, opt.step = kStep;
  const SweepResult r = runSweep(model, opt);
  std::array<double, 2> v{NAN, NAN};
  for (const auto& c : r.criticalSpeeds) {
    const int m = c.mode == analysis::ModeLabel::Weave ? 0 : c.mode == analysis::ModeLabel::Capsize ? 1 : -1;
    if (m >= 0 && !(c.speed >= v[m])) v[m] = c.speed;
  }
  return v;
}

std::string makeAssignment(const std::string& path, double value) {
  std::ostringstream s;
  s.precision(17);
  s << path << "=" << value;
  return s.str();
}

// Standard error of Jansen's first-order index S_i = 1 - D / (2 V) for parameter i and mode m, from
// the study's rows (task layout: nominal, 2 p derivative tasks, then per row A, B, A_B^1..A_B^p).
// D = mean over rows of d_j = (f(B_j) - f(A_B^i_j))^2; V = the variance of the pooled f(A), f(B).
// Delta method on the row means: S - E[S] ~ mean of psi_j = -(d_j - D) / (2 V) + D (v_j - V) / (2 V^2),
// v_j = ((f(A_j) - mu)^2 + (f(B_j) - mu)^2) / 2, so the standard error is sd(psi) / sqrt(N).
double calcJansenStandardError(const std::vector<TaskResult>& r, size_t rows, size_t p, size_t i, int m) {
  const size_t first = 1 + 2 * p;
  auto f = [&](size_t row, size_t k) { return r[first + row * (p + 2) + k].firstCrossing[m]; };
  double mu = 0, D = 0;
  for (size_t j = 0; j < rows; ++j) mu += (f(j, 0) + f(j, 1)) / (2.0 * rows), D += std::pow(f(j, 1) - f(j, 2 + i), 2) / rows;
  std::vector<double> v(rows);
  double V = 0;
  for (size_t j = 0; j < rows; ++j) {
    v[j] = (std::pow(f(j, 0) - mu, 2) + std::pow(f(j, 1) - mu, 2)) / 2;
    V += 2 * v[j] / (2.0 * rows - 1);
  }
  std::vector<double> psi(rows);
  double mean = 0, ss = 0;
  for (size_t j = 0; j < rows; ++j) {
    psi[j] = -(std::pow(f(j, 1) - f(j, 2 + i), 2) - D) / (2 * V) + D * (v[j] - V) / (2 * V * V);
    mean += psi[j] / rows;
  }
  for (double x : psi) ss += (x - mean) * (x - mean);
  return std::sqrt(ss / (rows - 1.0) / rows);
}

TEST(UncertaintyStudy, MonteCarloSpreadMatchesFirstOrderForSmallSigmas) {
  // Three parameters drawn at random with sigmas of 0.3-1 % of their nominal values; N = 4000.
  PortableRandom g(12);
  const std::vector<std::pair<std::string, double>> candidates{
      {"geometry.trail_m", 0.08}, {"geometry.wheelbase_m", 1.02}, {"rear_frame.mass_kg", 85},
      {"rear_frame.com_m[2]", 0.9}, {"front_frame.com_m[0]", 0.9}, {"rear_wheel.radius_m", 0.3}};
  std::vector<std::pair<std::string, double>> chosen;
  std::vector<double> nominal;
  for (size_t k = g.drawBits() % candidates.size(); chosen.size() < 3; k = (k + 1 + g.drawBits() % 2) % candidates.size()) {
    bool taken = false;
    for (const auto& c : chosen) taken = taken || c.first == candidates[k].first;
    if (taken) continue;
    chosen.push_back({candidates[k].first, candidates[k].second * g.drawUniform(0.003, 0.01)});
    nominal.push_back(candidates[k].second);
  }
  // The test's first-order estimate: central differences at +/- 0.1 sigma.
  std::array<double, 2> var{0, 0};
  for (size_t j = 0; j < chosen.size(); ++j) {
    const double h = 0.1 * chosen[j].second;
    const auto plus = calcCriticalSpeeds({makeAssignment(chosen[j].first, nominal[j] + h)});
    const auto minus = calcCriticalSpeeds({makeAssignment(chosen[j].first, nominal[j] - h)});
    for (int m = 0; m < 2; ++m) var[m] += std::pow((plus[m] - minus[m]) / (2 * h) * chosen[j].second, 2);
  }
  const std::string file = test::writeScenarioWith("whipple-benchmark.yaml", test::makeSection(chosen), "mc-first-order");
  const UncertaintySetup s = prepareUncertainty(file, {}, makeOptions(4000, g.drawBits()));
  const UncertaintySummary sum = summarizeUncertainty(s, runAll(s, 2));
  EXPECT_EQ(sum.succeeded, 4000u);
  for (int m = 0; m < 2; ++m) {
    const auto& c = sum.criticalSpeeds[m];
    EXPECT_EQ(c.fraction, 1.0) << c.mode;
    EXPECT_NEAR(c.std / std::sqrt(var[m]), 1.0, 0.05) << c.mode << " MC std " << c.std << ", first order " << std::sqrt(var[m]);
    EXPECT_NEAR(c.firstOrderStd / std::sqrt(var[m]), 1.0, 0.02) << c.mode;  // the study's own estimate agrees
  }
}

TEST(UncertaintyStudy, ZeroSigmaLeavesResultsUnchanged) {
  PortableRandom g(5);
  const double sigma = 0.08 * g.drawUniform(0.01, 0.03);
  const uint64_t seed = g.drawBits();
  const auto a = prepareUncertainty(test::writeScenarioWith("whipple-benchmark.yaml", test::makeSection({{"geometry.trail_m", sigma}}), "zero-a"),
                                    {}, makeOptions(6, seed));
  const auto b = prepareUncertainty(
      test::writeScenarioWith("whipple-benchmark.yaml",
                              test::makeSection({{"rear_frame.mass_kg", 0}, {"geometry.trail_m", sigma}, {"front_frame.inertia_kgm2.xz", 0}}),
                              "zero-b"),
      {}, makeOptions(6, seed));
  const auto ra = runAll(a, 1), rb = runAll(b, 1);
  const size_t firstA = 1 + 2 * a.params.size(), firstB = 1 + 2 * b.params.size();
  for (size_t i = 0; i < 6; ++i) {
    const TaskResult &x = ra[firstA + i], &y = rb[firstB + i];
    ASSERT_TRUE(x.ok && y.ok);
    EXPECT_EQ(x.parameters[0], y.parameters[1]);
    EXPECT_EQ(y.parameters[0], 85.0);
    EXPECT_EQ(std::memcmp(x.firstCrossing.data(), y.firstCrossing.data(), sizeof(double) * x.firstCrossing.size()), 0);
  }
  // Every sigma zero: every sample is the nominal scenario.
  const auto c = prepareUncertainty(test::writeScenarioWith("whipple-benchmark.yaml", test::makeSection({{"geometry.trail_m", 0}}), "zero-c"),
                                    {}, makeOptions(3, seed));
  const auto sc = summarizeUncertainty(c, runAll(c, 1));
  EXPECT_EQ(sc.criticalSpeeds[0].std, 0.0);
  EXPECT_EQ(sc.criticalSpeeds[0].mean, sc.criticalSpeeds[0].nominal);
  EXPECT_NEAR(sc.criticalSpeeds[0].nominal, 4.29238253, 1e-6);  // Meijaard et al. 2007, Table 2: weave speed
}

TEST(UncertaintyStudy, OneParameterAloneTakesTheFullShare) {
  PortableRandom g(8);
  const double sigma = 0.9 * g.drawUniform(0.005, 0.015);
  const std::string file = test::writeScenarioWith(
      "whipple-benchmark.yaml", test::makeSection({{"rear_frame.com_m[2]", sigma}, {"geometry.wheelbase_m", 0}}), "share");
  // Monte Carlo: standardised regression coefficient 1 with R^2 = 1 for the one varying parameter.
  const auto s = prepareUncertainty(file, {}, makeOptions(40, g.drawBits()));
  const auto mc = summarizeUncertainty(s, runAll(s, 2));
  for (int m = 0; m < 2; ++m) {
    EXPECT_GT(mc.criticalSpeeds[m].r2, 0.99);
    EXPECT_NEAR(std::abs(mc.criticalSpeeds[m].sensitivity[0]), 1.0, 0.01);
    EXPECT_EQ(mc.criticalSpeeds[m].sensitivity[1], 0.0);
  }
  // Sobol (Jansen): the varying parameter's index is exactly 1 (A_B^i = B), the zero-sigma one's
  // near 0 (A_B^i = A): its expectation is 0, and it may differ from 0 by the estimator's noise at
  // N = 24, bounded at 4 of the standard errors computed below from the same rows.
  UncertaintyOptions o = makeOptions(24, g.drawBits());
  o.method = SamplingMethod::Sobol;
  const auto so = prepareUncertainty(file, {}, o);
  const auto results = runAll(so, 2);
  const auto sob = summarizeUncertainty(so, results);
  for (int m = 0; m < 2; ++m) {
    EXPECT_NEAR(sob.criticalSpeeds[m].sensitivity[0], 1.0, 1e-12);
    const double se = calcJansenStandardError(results, 24, 2, 1, m);
    ASSERT_TRUE(se > 0 && se < 0.25) << "standard error " << se;  // a bound that can fail
    EXPECT_NEAR(sob.criticalSpeeds[m].sensitivity[1], 0.0, 4 * se) << "standard error " << se;
  }
}

TEST(UncertaintyStudy, ThreadsGiveIdenticalResults) {
  PortableRandom g(3);
  const std::string file = test::writeScenarioWith(
      "whipple-benchmark.yaml",
      test::makeSection({{"geometry.trail_m", 0.002}, {"rear_frame.inertia_kgm2.xz", 0.05}, {"front_wheel.mass_kg", 0.1}}), "threads");
  const auto s = prepareUncertainty(file, {}, makeOptions(8, g.drawBits()));
  const auto one = runAll(s, 1), two = runAll(s, 2);
  const size_t mv = getModeValueCount(s);
  for (size_t t = 0; t < one.size(); ++t) {
    const auto a = packResult(one[t], s.params.size(), mv), b = packResult(two[t], s.params.size(), mv);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), sizeof(double) * a.size()), 0) << "task " << t;
    EXPECT_EQ(packResultText(one[t]), packResultText(two[t]));
  }
}

TEST(UncertaintyStudy, PackedResultsRoundTrip) {
  PortableRandom g(4);
  TaskResult r;
  r.ok = true, r.redraws = 3, r.reason = "", r.crossings = "weave@4.2-;capsize@6+";
  for (int j = 0; j < 4; ++j) r.parameters.push_back(g.drawUniform(-1, 1));
  r.firstCrossing = {g.drawUniform(0, 10), NAN, g.drawUniform(0, 10)};
  for (int j = 0; j < 16; ++j) r.modeValues.push_back(j % 5 ? g.drawUniform(-5, 5) : NAN);
  const auto d = packResult(r, 4, 16);
  const TaskResult u = unpackResult(d.data(), 4, 16, packResultText(r).substr(0, packResultText(r).size() - 1));
  EXPECT_EQ(u.parameters, r.parameters);
  EXPECT_EQ(u.redraws, 3);
  EXPECT_EQ(u.crossings, r.crossings);
  const auto d2 = packResult(u, 4, 16);
  EXPECT_EQ(std::memcmp(d.data(), d2.data(), sizeof(double) * d.size()), 0);
}

TEST(UncertaintyStudy, PercentilesAndRegressionMatchHandCalculations) {
  // Hyndman and Fan (1996) definition 7 on 1..5: p05 = 1.2, p50 = 3, p95 = 4.8.
  const std::vector<double> v{1, 2, 3, 4, 5};
  EXPECT_DOUBLE_EQ(calcPercentile(v, 0.05), 1.2);
  EXPECT_DOUBLE_EQ(calcPercentile(v, 0.5), 3.0);
  EXPECT_DOUBLE_EQ(calcPercentile(v, 0.95), 4.8);
  // y = 3 x1 - x2 exactly with independent x: SRC_j = b_j sd_j / sd_y, R^2 = 1.
  PortableRandom g(6);
  std::vector<std::vector<double>> x;
  std::vector<double> y;
  for (int i = 0; i < 200; ++i) {
    const double a = g.drawUniform(-1, 1), b = g.drawUniform(-2, 2);
    x.push_back({a, b}), y.push_back(3 * a - b);
  }
  double r2 = 0;
  const auto src = calcStandardisedRegression(x, y, r2);
  auto sd = [](const std::vector<double>& c) {
    double m = 0, s = 0;
    for (double e : c) m += e;
    m /= c.size();
    for (double e : c) s += (e - m) * (e - m);
    return std::sqrt(s / (c.size() - 1));
  };
  std::vector<double> c0, c1;
  for (const auto& r : x) c0.push_back(r[0]), c1.push_back(r[1]);
  EXPECT_NEAR(r2, 1.0, 1e-12);
  EXPECT_NEAR(src[0], 3 * sd(c0) / sd(y), 1e-10);
  EXPECT_NEAR(src[1], -sd(c1) / sd(y), 1e-10);
}

}  // namespace
}  // namespace motostab::uncertainty

namespace motostab::uncertainty {
namespace {

TEST(UncertaintyStudy, UnphysicalDrawsAreRedrawnAndCounted) {
  // sigma = nominal mass: about 16 % of the normal draws are negative masses, which the loader rejects.
  PortableRandom g(21);
  const uint64_t seed = g.drawBits();
  const std::string file = test::writeScenarioWith("whipple-benchmark.yaml", test::makeSection({{"rear_frame.mass_kg", 85}}), "redraw");
  UncertaintyOptions o = makeOptions(12, seed);
  o.start = 4, o.stop = 4.5, o.step = 0.5;
  ParameterUncertainty p;
  p.path = "rear_frame.mass_kg", p.sigma = 85;
  size_t expectedRedraws = 0, expectedFailures = 0;
  for (uint64_t i = 0; i < 12; ++i) {
    for (uint64_t a = 0; drawParameters(seed, i, a, {p}, {85})[0] <= 0; ++a) ++expectedRedraws;
    if (drawParameters(seed, i, 0, {p}, {85})[0] <= 0) ++expectedFailures;
  }
  ASSERT_GT(expectedFailures, 0u) << "choose another seed: no negative draw among 12";
  const auto s = prepareUncertainty(file, {}, o);
  const auto r = runAll(s, 2);
  const auto sum = summarizeUncertainty(s, r);
  EXPECT_EQ(sum.redraws, expectedRedraws);
  for (size_t t = 1 + 2 * s.params.size(); t < r.size(); ++t) EXPECT_GT(r[t].parameters[0], 0);
  // One attempt only: the unphysical samples are recorded as failed, with the reason.
  o.maxAttempts = 1;
  const auto s1 = prepareUncertainty(file, {}, o);
  const auto r1 = runAll(s1, 2);
  size_t failed = 0;
  for (size_t t = 1 + 2 * s1.params.size(); t < r1.size(); ++t)
    if (!r1[t].ok) {
      ++failed;
      EXPECT_NE(r1[t].reason.find("rear_frame.mass_kg: must be positive"), std::string::npos) << r1[t].reason;
    }
  EXPECT_EQ(failed, expectedFailures);
  EXPECT_EQ(summarizeUncertainty(s1, r1).failed, expectedFailures);
}

}  // namespace
}  // namespace motostab::uncertainty
