#pragma once
// Bounded nonlinear least squares (the Levenberg-Marquardt iterations of core/levenberg_marquardt.h,
// with the box handled by clamping the step and freezing parameters held at a bound by the gradient,
// and a forward-difference Jacobian) and the statistics of
// its solution: covariance s^2 (J'J)^-1 with s^2 = chi2 / (n - p), standard errors, correlation.
#include <Eigen/Dense>
#include <functional>
#include <string>

namespace motostab::diagnosis {

struct LeastSquaresProblem {
  /// Weighted residuals (dimensionless) at parameters x; throws to reject x (treated as a failed step).
  std::function<Eigen::VectorXd(const Eigen::VectorXd& x)> residual;
  Eigen::VectorXd lower, upper;  ///< bounds of x
  Eigen::VectorXd step;          ///< forward-difference steps of the Jacobian, per parameter
  int numData = 0;               ///< residuals counted in n for s^2 (the rest are priors); 0: all
};

struct LeastSquaresOptions {
  int maxIterations = 30;
  double relativeTolerance = 1e-8;  ///< stop when chi2 falls by less than this fraction
  /// Compute the covariance at the solution (one more Jacobian); without it the result's
  /// covariance, stderr_ and correlation are empty (cross-validation folds need only x).
  bool statistics = true;
};

struct LeastSquaresResult {
  Eigen::VectorXd x;
  Eigen::VectorXd residual;
  double chi2 = 0;                  ///< sum of squared residuals
  Eigen::MatrixXd covariance;       ///< s^2 (J'J)^-1 (pseudo-inverse), x units squared
  Eigen::VectorXd stderr_;          ///< sqrt of the covariance diagonal
  Eigen::MatrixXd correlation;
  Eigen::MatrixXd jacobian;         ///< d residual / d x at the solution (with statistics)
  Eigen::VectorXi atBound;          ///< 1 where x sits at a bound
  int iterations = 0, evaluations = 0;
  std::string stop;                 ///< converged, iteration limit, step too small
};

/// Minimises |r(x)|^2 over lower <= x <= upper from x0 (clamped into the box; r(x0) must not throw).
LeastSquaresResult solveBoundedLeastSquares(const LeastSquaresProblem& problem, const Eigen::VectorXd& x0,
                                            const LeastSquaresOptions& options = {});

/// Upper tail Q(df/2, x/2) of the chi-square distribution with df degrees of freedom at x.
double calcChiSquareSurvival(double x, int df);

}  // namespace motostab::diagnosis
