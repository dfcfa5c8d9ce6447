#include "uncertainty/uncertainty_summary.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/sweep.h"

namespace motostab::uncertainty {

using analysis::makeSpeedGrid;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool isDistributionSample(TaskKind k) {
  return k == TaskKind::Sample || k == TaskKind::SobolA || k == TaskKind::SobolB;
}

// Mean, sample standard deviation and the 5/50/95 % percentiles of `v` (sorted in place).
void fillMoments(std::vector<double>& v, CriticalSpeedStats& c) {
  c.count = v.size();
  c.mean = c.std = c.p05 = c.p50 = c.p95 = kNaN;
  if (v.empty()) return;
  double sum = 0;
  for (double x : v) sum += x;
  c.mean = sum / v.size();
  if (v.size() > 1) {
    double ss = 0;
    for (double x : v) ss += (x - c.mean) * (x - c.mean);
    c.std = std::sqrt(ss / (v.size() - 1.0));
  }
  std::sort(v.begin(), v.end());
  c.p05 = calcPercentile(v, 0.05), c.p50 = calcPercentile(v, 0.5), c.p95 = calcPercentile(v, 0.95);
}

// dv/dx_j by central differences of the neighbour tasks and sqrt(J Sigma J^T).
void fillFirstOrder(const UncertaintySetup& s, const std::vector<TaskResult>& r, size_t m, CriticalSpeedStats& c) {
  const size_t p = s.params.size();
  c.derivatives.assign(p, kNaN);
  c.nominal = r[0].ok ? r[0].firstCrossing[m] : kNaN;
  double var = 0;
  for (size_t j = 0; j < p; ++j) {
    const double sigma = s.params[j].sigma;
    if (sigma == 0) continue;  // no contribution
    const TaskResult &plus = r[1 + 2 * j], &minus = r[2 + 2 * j];
    const double h = s.options.derivativeStep * sigma;
    if (plus.ok && minus.ok) c.derivatives[j] = (plus.firstCrossing[m] - minus.firstCrossing[m]) / (2 * h);
    var += c.derivatives[j] * c.derivatives[j] * sigma * sigma;  // NaN propagates
  }
  c.firstOrderStd = std::sqrt(var);
}

// Standardised regression coefficients of the crossing on the sampled parameters (mc).
void fillRegression(const std::vector<TaskResult>& samples, size_t m, CriticalSpeedStats& c) {
  std::vector<std::vector<double>> x;
  std::vector<double> y;
  for (const auto& t : samples)
    if (t.ok && !std::isnan(t.firstCrossing[m])) x.push_back(t.parameters), y.push_back(t.firstCrossing[m]);
  c.sensitivity = calcStandardisedRegression(x, y, c.r2);
  if (x.empty()) c.sensitivity.assign(samples.empty() ? 0 : samples[0].parameters.size(), kNaN);
}

// First-order Sobol indices with Jansen's estimator (Saltelli et al. 2010, Table 2 (f); Jansen 1999):
// S_i = 1 - mean((f(B) - f(A_B^i))^2) / (2 Var(f)), Var over f(A) and f(B), over the rows whose every
// evaluation has the crossing. Differences of outputs, unlike products, do not lose the spread to
// cancellation when the mean is much larger than the standard deviation.
void fillSobol(const UncertaintySetup& s, const std::vector<TaskResult>& r, size_t m, CriticalSpeedStats& c) {
  const size_t p = s.params.size(), rows = s.options.samples, first = 1 + 2 * p;
  auto f = [&](size_t t) { return r[t].ok ? r[t].firstCrossing[m] : kNaN; };
  std::vector<size_t> good;
  for (size_t j = 0; j < rows; ++j) {
    bool all = true;
    for (size_t k = 0; k < p + 2; ++k) all = all && !std::isnan(f(first + j * (p + 2) + k));
    if (all) good.push_back(first + j * (p + 2));
  }
  c.r2 = kNaN;
  c.sensitivity.assign(p, kNaN);
  if (good.size() < 2) return;
  double sum = 0, ss = 0;
  for (size_t t : good) sum += f(t) + f(t + 1);
  const double mean = sum / (2.0 * good.size());
  for (size_t t : good) ss += (f(t) - mean) * (f(t) - mean) + (f(t + 1) - mean) * (f(t + 1) - mean);
  const double var = ss / (2.0 * good.size() - 1);
  for (size_t i = 0; i < p; ++i) {
    double v = 0;
    for (size_t t : good) v += (f(t + 1) - f(t + 2 + i)) * (f(t + 1) - f(t + 2 + i));
    c.sensitivity[i] = var > 0 ? 1 - v / (2.0 * good.size() * var) : kNaN;
  }
}

// Per-speed 5/50/95 % percentiles of one fan mode's real part and frequency.
ModeQuantiles calcModeQuantiles(const std::vector<TaskResult>& samples, size_t m, size_t n) {
  ModeQuantiles q;
  q.mode = analysis::toString(kFanModes[m]);
  q.count.assign(n, 0);
  q.real.assign(n, {kNaN, kNaN, kNaN});
  q.frequency = q.real;
  std::vector<double> re, fr;
  for (size_t k = 0; k < n; ++k) {
    re.clear(), fr.clear();
    for (const auto& t : samples) {
      if (!t.ok || std::isnan(t.modeValues[2 * (m * n + k)])) continue;
      re.push_back(t.modeValues[2 * (m * n + k)]);
      fr.push_back(t.modeValues[2 * (m * n + k) + 1]);
    }
    q.count[k] = re.size();
    if (re.empty()) continue;
    std::sort(re.begin(), re.end()), std::sort(fr.begin(), fr.end());
    q.real[k] = {calcPercentile(re, 0.05), calcPercentile(re, 0.5), calcPercentile(re, 0.95)};
    q.frequency[k] = {calcPercentile(fr, 0.05), calcPercentile(fr, 0.5), calcPercentile(fr, 0.95)};
  }
  return q;
}

}  // namespace

UncertaintySummary summarizeUncertainty(const UncertaintySetup& s, const std::vector<TaskResult>& r) {
  UncertaintySummary out;
  out.method = s.options.method;
  out.speeds = makeSpeedGrid(s.options.start, s.options.stop, s.options.step);
  out.tasks = r.size();
  std::vector<TaskResult> samples;  // the draws of the parameters' distribution (mc samples, Sobol A and B)
  for (size_t t = 1 + 2 * s.params.size(); t < r.size(); ++t) {
    if (!r[t].ok) ++out.failed;
    if (!isDistributionSample(getTask(s, t).kind)) continue;
    samples.push_back(r[t]);
    out.redraws += static_cast<size_t>(r[t].redraws);
    if (r[t].ok) ++out.succeeded;
  }
  out.samples = samples.size();
  for (size_t m = 0; m < kUncertainModes.size(); ++m) {
    CriticalSpeedStats c;
    c.mode = analysis::toString(kUncertainModes[m]);
    std::vector<double> v;
    for (const auto& t : samples)
      if (t.ok && !std::isnan(t.firstCrossing[m])) v.push_back(t.firstCrossing[m]);
    fillMoments(v, c);
    c.fraction = out.succeeded > 0 ? static_cast<double>(c.count) / out.succeeded : kNaN;
    fillFirstOrder(s, r, m, c);
    if (s.options.method == SamplingMethod::Sobol) fillSobol(s, r, m, c);
    else fillRegression(samples, m, c);
    out.criticalSpeeds.push_back(c);
  }
  for (size_t m = 0; m < kFanModes.size(); ++m) {
    ModeQuantiles q = calcModeQuantiles(samples, m, out.speeds.size());
    if (std::any_of(q.count.begin(), q.count.end(), [](size_t c) { return c > 0; })) out.modes.push_back(q);
  }
  return out;
}

double calcPercentile(const std::vector<double>& v, double q) {
  if (v.empty()) return kNaN;
  const double h = (static_cast<double>(v.size()) - 1) * q;
  const size_t lo = static_cast<size_t>(std::floor(h)), hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (h - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

std::vector<double> calcStandardisedRegression(const std::vector<std::vector<double>>& x, const std::vector<double>& y,
                                               double& r2) {
  const size_t n = y.size(), p = x.empty() ? 0 : x[0].size();
  std::vector<double> src(p, kNaN);
  r2 = kNaN;
  if (n < p + 2) return src;
  Eigen::MatrixXd X(n, p + 1);
  Eigen::VectorXd Y(n);
  for (size_t i = 0; i < n; ++i) {
    X(i, 0) = 1;
    for (size_t j = 0; j < p; ++j) X(i, j + 1) = x[i][j];
    Y(i) = y[i];
  }
  auto sd = [&](const Eigen::VectorXd& c) { return std::sqrt((c.array() - c.mean()).square().sum() / (n - 1.0)); };
  const double sy = sd(Y);
  std::vector<Eigen::Index> active{0};  // intercept and the columns that vary
  for (size_t j = 0; j < p; ++j)
    if (X.col(j + 1).maxCoeff() > X.col(j + 1).minCoeff()) active.push_back(static_cast<Eigen::Index>(j + 1));
    else src[j] = 0;
  Eigen::MatrixXd Xa(n, active.size());
  for (size_t c = 0; c < active.size(); ++c) Xa.col(c) = X.col(active[c]);
  const Eigen::VectorXd b = Xa.colPivHouseholderQr().solve(Y);
  const double ssTot = (Y.array() - Y.mean()).square().sum();
  r2 = ssTot > 0 ? 1 - (Y - Xa * b).squaredNorm() / ssTot : kNaN;
  for (size_t c = 1; c < active.size(); ++c) src[active[c] - 1] = sy > 0 ? b(c) * sd(X.col(active[c])) / sy : kNaN;
  return src;
}

}  // namespace motostab::uncertainty
