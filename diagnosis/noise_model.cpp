#include "diagnosis/noise_model.h"

#include <algorithm>
#include <cmath>

namespace motostab::diagnosis {
namespace {

// phi_{m,1..m} of every order m = 0..p from the reflection coefficients (Durbin-Levinson).
std::vector<std::vector<double>> calcPredictors(const std::vector<double>& k) {
  std::vector<std::vector<double>> phi(k.size() + 1);
  for (size_t m = 1; m <= k.size(); ++m) {
    phi[m].resize(m);
    for (size_t j = 0; j + 1 < m; ++j) phi[m][j] = phi[m - 1][j] - k[m - 1] * phi[m - 1][m - 2 - j];
    phi[m][m - 1] = k[m - 1];
  }
  return phi;
}

}  // namespace

double ArNoise::calcMarginalFactor() const {
  double prod = 1;
  for (double k : reflection) prod *= 1 - k * k;
  return 1 / std::sqrt(prod);
}

double ArNoise::calcLogDeterminant() const {
  // v_t / v_p = prod_{j=t+1..p} 1 / (1 - k_j^2)
  double sum = 0;
  for (size_t t = 0; t < reflection.size(); ++t)
    for (size_t j = t; j < reflection.size(); ++j) sum -= std::log(1 - reflection[j] * reflection[j]);
  return sum;
}

double NoiseState::calcChange(const NoiseState& o) const {
  double change = 0;
  for (size_t c = 0; c < sigma.size() && c < o.sigma.size(); ++c) change = std::max(change, std::abs(std::log(sigma[c] / o.sigma[c])));
  for (size_t c = 0; c < ar.size() && c < o.ar.size(); ++c) {
    if (ar[c].getOrder() != o.ar[c].getOrder()) return std::max(change, 1.0);
    for (int j = 0; j < ar[c].getOrder(); ++j)
      change = std::max(change, std::abs(std::atanh(ar[c].reflection[j]) - std::atanh(o.ar[c].reflection[j])));
  }
  return change;
}

ArNoise fitArNoise(const double* e, int n, double* innovationVariance, int maxOrder) {
  ArNoise best;
  double v = 0;
  for (int t = 0; t < n; ++t) v += e[t] * e[t];
  v /= std::max(n, 1);
  if (innovationVariance) *innovationVariance = v;
  const int pmax = n < 20 ? 0 : std::min(maxOrder, n / 10);
  std::vector<double> f(e, e + n), b(e, e + n), k;
  double bestScore = n * std::log(std::max(v, 1e-300)), bestV = v;
  for (int m = 1; m <= pmax && v > 0; ++m) {
    double num = 0, den = 0;
    for (int t = m; t < n; ++t) num += f[t] * b[t - 1], den += f[t] * f[t] + b[t - 1] * b[t - 1];
    if (!(den > 0)) break;
    const double km = std::clamp(2 * num / den, -0.9999, 0.9999);
    for (int t = n - 1; t >= m; --t) {  // backwards: b[t - 1] is still order m - 1's
      const double ft = f[t], bt = b[t - 1];
      f[t] = ft - km * bt;
      b[t] = bt - km * ft;
    }
    k.push_back(km);
    v *= 1 - km * km;
    const double score = n * std::log(std::max(v, 1e-300)) + m * std::log(static_cast<double>(n));
    if (score < bestScore) bestScore = score, bestV = v, best.reflection = k;
  }
  best.phi = calcPredictors(best.reflection).back();
  if (innovationVariance) *innovationVariance = bestV;
  return best;
}

void whitenSeries(const ArNoise& ar, const double* in, double* out, int n) {
  const int p = ar.getOrder();
  if (p == 0) {
    std::copy(in, in + n, out);
    return;
  }
  const std::vector<std::vector<double>> phi = calcPredictors(ar.reflection);
  for (int t = 0; t < n; ++t) {
    const int m = std::min(t, p);
    double pred = 0, scale = 1;  // scale: sqrt(v_p / v_m)
    for (int j = 0; j < m; ++j) pred += phi[m][j] * in[t - 1 - j];
    for (int j = m; j < p; ++j) scale *= 1 - ar.reflection[j] * ar.reflection[j];
    out[t] = (in[t] - pred) * std::sqrt(scale);
  }
}

}  // namespace motostab::diagnosis
