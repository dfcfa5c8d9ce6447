#pragma once
// Speeds at which a diagnosis linearises: the measured rows' evaluation speeds (a speed range by
// two-point Gauss-Legendre quadrature), and Chebyshev points for the fast (interpolated) predictions
// with their barycentric interpolation (Berrut & Trefethen 2004, SIAM Review 46:501).
#include <complex>
#include <vector>

#include "diagnosis/measured_data.h"

namespace motostab::diagnosis {

/// The speeds at which a row is evaluated, m/s: its speed, or for a speed range [a, b] the two
/// Gauss-Legendre nodes m -/+ h/sqrt(3) (m, h: the range's middle and half width), whose mean of the
/// eigenvalue is the range's mean, exact for a cubic in speed.
std::vector<double> getEvaluationSpeeds(const MeasuredEigenvalue& row);

/// `n` Chebyshev points of the second kind on [lo, hi], increasing, m/s.
std::vector<double> makeChebyshevNodes(double lo, double hi, int n);

/// The barycentric interpolant of values f at Chebyshev points x (second kind: weights (-1)^j,
/// halved at the ends), at v.
std::complex<double> interpolateChebyshev(const std::vector<double>& x, const std::vector<std::complex<double>>& f, double v);

/// `v` sorted with duplicates removed.
std::vector<double> makeSortedUnique(std::vector<double> v);

/// Index of speed v in sorted `speeds` (the first not below v).
size_t findSpeed(const std::vector<double>& speeds, double v);

}  // namespace motostab::diagnosis
