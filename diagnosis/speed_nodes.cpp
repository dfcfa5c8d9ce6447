#include "diagnosis/speed_nodes.h"

#include <algorithm>
#include <cmath>

namespace motostab::diagnosis {

std::vector<double> getEvaluationSpeeds(const MeasuredEigenvalue& row) {
  if (!row.hasRange || row.speedMax - row.speedMin < 1e-9) return {row.speed};
  const double m = 0.5 * (row.speedMin + row.speedMax), h = 0.5 * (row.speedMax - row.speedMin);
  return {m - h / std::sqrt(3.0), m + h / std::sqrt(3.0)};
}

std::vector<double> makeChebyshevNodes(double lo, double hi, int n) {
  std::vector<double> nodes;
  for (int j = n - 1; j >= 0; --j) nodes.push_back(0.5 * (lo + hi) + 0.5 * (hi - lo) * std::cos(M_PI * j / (n - 1)));
  return nodes;
}

std::complex<double> interpolateChebyshev(const std::vector<double>& x, const std::vector<std::complex<double>>& f,
                                          double v) {
  std::complex<double> num = 0;
  double den = 0;
  const size_t n = x.size();
  for (size_t j = 0; j < n; ++j) {
    if (v == x[j]) return f[j];
    const double w = ((j % 2) ? -1.0 : 1.0) * ((j == 0 || j + 1 == n) ? 0.5 : 1.0) / (v - x[j]);
    num += w * f[j];
    den += w;
  }
  return num / den;
}

std::vector<double> makeSortedUnique(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

size_t findSpeed(const std::vector<double>& speeds, double v) {
  return std::lower_bound(speeds.begin(), speeds.end(), v) - speeds.begin();
}

}  // namespace motostab::diagnosis
