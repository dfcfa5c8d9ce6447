#include "modal/peak_picking.h"

#include <cmath>
#include <limits>

namespace motostab::modal {

std::vector<double> calcPowerIndicator(const std::vector<std::vector<std::complex<double>>>& h) {
  std::vector<double> ind(h.empty() ? 0 : h[0].size(), 0.0);
  for (const auto& c : h)
    for (size_t k = 0; k < c.size(); ++k) ind[k] += std::norm(c[k]);
  return ind;
}

std::vector<PeakEstimate> findHalfPowerPeaks(const std::vector<double>& f, const std::vector<double>& y, double fMin,
                                             double fMax, double windowDecayRate, double minRelative, int halfWidth) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double yMax = 0;
  for (size_t k = 0; k < f.size(); ++k)
    if (f[k] >= fMin && f[k] <= fMax) yMax = std::max(yMax, y[k]);
  std::vector<PeakEstimate> peaks;
  const long n = static_cast<long>(f.size());
  for (long k = 1; k + 1 < n; ++k) {
    if (f[k] < fMin || f[k] > fMax || y[k] < minRelative * yMax) continue;
    bool isMax = true;
    for (long j = std::max(0L, k - halfWidth); j <= std::min(n - 1, k + halfWidth) && isMax; ++j)
      if (j != k && (y[j] > y[k] || (y[j] == y[k] && j < k))) isMax = false;
    if (!isMax) continue;
    PeakEstimate p;
    const double df = f[k + 1] - f[k];
    const double a = y[k - 1], b = y[k], c = y[k + 1], den = a - 2 * b + c;
    p.frequencyHz = f[k] + (den != 0 ? 0.5 * (a - c) / den * df : 0.0);
    p.peakValue = b;
    const double half = 0.5 * b;
    double f1 = nan, f2 = nan;
    for (long j = k - 1; j >= 0 && y[j] <= b; --j)
      if (y[j] < half) { f1 = f[j] + (half - y[j]) / (y[j + 1] - y[j]) * (f[j + 1] - f[j]); break; }
    for (long j = k + 1; j < n && y[j] <= b; ++j)
      if (y[j] < half) { f2 = f[j - 1] + (y[j - 1] - half) / (y[j - 1] - y[j]) * (f[j] - f[j - 1]); break; }
    p.dampingRatio = (f2 - f1) / (2 * p.frequencyHz) - windowDecayRate / (2 * M_PI * p.frequencyHz);
    p.lossFactor = 2 * p.dampingRatio;
    peaks.push_back(p);
  }
  return peaks;
}

}  // namespace motostab::modal
