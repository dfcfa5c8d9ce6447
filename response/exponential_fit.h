#pragma once
// Least-squares fits of sums of damped exponentials with shared poles to one or several signals.
#include <vector>

#include <Eigen/Dense>

namespace motostab::response {

/// A continuous-time pole: sigma +- i omega (1/s, rad/s). omega > 0 is a complex pair with basis
/// exp(sigma tau) cos(omega tau), exp(sigma tau) sin(omega tau); omega == 0 a real exponential exp(sigma tau).
struct ContinuousPole {
  double sigma = 0;  ///< 1/s
  double omega = 0;  ///< rad/s, >= 0
};

/// A fitted model: the basis columns are [1 if offset], then each pole's one or two columns.
struct ExponentialFit {
  std::vector<ContinuousPole> poles;
  bool offset = true;
  Eigen::MatrixXd coefficients;  ///< basis columns x signals, signal units
  double residualSumSquares = 0; ///< summed over samples and signals, signal units squared
};

/// Number of basis columns of `poles` (+1 with `offset`).
int getBasisSize(const std::vector<ContinuousPole>& poles, bool offset);

/// The N x getBasisSize() basis at times `tau` (s, relative to the reference time).
Eigen::MatrixXd calcBasis(const std::vector<ContinuousPole>& poles, bool offset, const Eigen::VectorXd& tau);

/// Linear least squares for the coefficients of fixed poles; `samples` is N x K (one signal per column).
ExponentialFit calcLinearFit(const std::vector<ContinuousPole>& poles, bool offset, const Eigen::VectorXd& tau,
                             const Eigen::MatrixXd& samples);

/// Refines the poles of `start` by variable projection (Golub & Pereyra 1973, Kaufman's Jacobian) with
/// Levenberg-Marquardt steps; the coefficients are eliminated by linear least squares. Returns the best
/// fit found (never worse than `start`). Steps that would make omega <= 0 or exceed `maxOmega` (rad/s)
/// are rejected.
ExponentialFit polishPoles(const ExponentialFit& start, const Eigen::VectorXd& tau, const Eigen::MatrixXd& samples,
                           double maxOmega, int maxIterations = 200);

}  // namespace motostab::response
