#pragma once
// Autocorrelated noise of a response signal: a stationary autoregressive process of order p,
//   e_t = phi_1 e_{t-1} + ... + phi_p e_{t-p} + a_t,   a_t white with variance sigma_a^2,
// estimated from a fit's residual series by Burg's method (reflection coefficients k_m; Brockwell &
// Davis 2002, Introduction to Time Series and Forecasting, 2nd ed., sect. 5.1.2), the order chosen by
// the Schwarz criterion n ln v_m + m ln n (Schwarz 1978) over m = 0..kMaxArOrder.
//
// Prewhitening: the exact innovations of the Gaussian AR(p) likelihood (Brockwell & Davis 2002, sect.
// 2.5.1, the Durbin-Levinson algorithm): for t < p the best linear predictor uses the t samples seen so
// far, phi_{t,j} from the reflection coefficients (phi_{m,m} = k_m, phi_{m,j} = phi_{m-1,j} -
// k_m phi_{m-1,m-j}), with prediction error variance v_t = v_0 prod_{j<=t} (1 - k_j^2); for t >= p it is
// the full filter. Each innovation is scaled to the variance v_p = sigma_a^2, so the whitened series
// w_t = (e_t - sum_j phi_{t,j} e_{t-j}) / sqrt(v_t / v_p) is white with variance sigma_a^2 and
//   -2 ln L = n ln(2 pi sigma_a^2) + sum_t ln(v_t / v_p) + sum_t w_t^2 / sigma_a^2    (eq. 1)
// (the log-determinant of the AR correlation matrix relative to sigma_a^2 is sum_{t<p} ln(v_t / v_p)).
// A trace of n samples with AR(1) noise of correlation rho thus weighs in the likelihood roughly as
// n (1 - rho) / (1 + rho) independent samples would.
#include <vector>

namespace motostab::diagnosis {

/// Highest AR order tried.
constexpr int kMaxArOrder = 8;

/// One signal's AR(p) noise (p = 0: white).
struct ArNoise {
  std::vector<double> reflection;  ///< k_1..k_p (partial autocorrelations), |k| < 1
  std::vector<double> phi;         ///< phi_1..phi_p of the full filter
  /// Marginal sigma over innovation sigma: 1 / sqrt(prod (1 - k_j^2)).
  double calcMarginalFactor() const;
  /// sum_{t<p} ln(v_t / v_p), the log-determinant term of eq. 1 (independent of sigma_a).
  double calcLogDeterminant() const;
  int getOrder() const { return static_cast<int>(reflection.size()); }
};

/// The noise of every component of a diagnosis' fit problem for one model: each unknown component's
/// sigma (the innovation sigma of AR ones) and each response series' AR noise (order 0 elsewhere).
/// Each model is scored with its own (diagnosis/model_fit.h).
struct NoiseState {
  std::vector<double> sigma;
  std::vector<ArNoise> ar;
  /// Largest change from `o`: |ln sigma ratio| and |atanh k - atanh k'| of the reflection coefficients
  /// (atanh: a change near |k| = 1 weighs as it does in the likelihood); an order change counts 1.
  double calcChange(const NoiseState& o) const;
};

/// Burg estimate of AR(p) noise from a residual series (mean not removed: the fits hold an offset),
/// order by the Schwarz criterion up to min(kMaxArOrder, n / 10); `innovationVariance` gets v_p
/// (the series' unit squared). A series shorter than 20 samples gets p = 0.
ArNoise fitArNoise(const double* e, int n, double* innovationVariance = nullptr, int maxOrder = kMaxArOrder);

/// Whitens `in` (n samples) into `out` (eq. 1's w_t; out may not alias in). Unit of in.
void whitenSeries(const ArNoise& ar, const double* in, double* out, int n);

}  // namespace motostab::diagnosis
