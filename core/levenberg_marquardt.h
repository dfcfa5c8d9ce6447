#pragma once
// Levenberg-Marquardt iterations for nonlinear least squares (Levenberg 1944; Marquardt 1963, J. SIAM
// 11:431): the damped normal equations (J'J + mu diag(s)) dx = -J'r, mu raised after a rejected trial
// and lowered after an accepted one. The problem owns its parameters, its Jacobian and its test of a
// trial, so bounded finite-difference fits (diagnosis/least_squares) and variable projection
// (response/exponential_fit) share one set of iterations.
#include <Eigen/Dense>
#include <functional>

namespace motostab::core {

/// What a trial step did: the problem moved to it, refused it (worse, invalid, or it threw), or the
/// step moves nothing (the iteration then ends without descent).
enum class LmTrial { Accepted, Rejected, NoMove };

/// Why the iterations ended.
enum class LmStop { Converged, NoDescent, IterationLimit };

struct LevenbergMarquardtSettings {
  int maxIterations = 30;
  int maxTries = 12;             ///< damped trials per iteration before it ends without descent
  double initialDamping = 1e-3;  ///< mu at the start (dimensionless, relative to the scale s)
  double increase = 10;          ///< mu *= increase after a rejected trial
  /// After an accepted trial mu = max(mu / decrease, minDamping) * rebound.
  double decrease = 3, minDamping = 1e-12, rebound = 1;
  /// Linearise once more at the solution (a covariance from J there); otherwise the last Jacobian
  /// may belong to the point before the last step.
  bool jacobianAtSolution = false;
};

struct LevenbergMarquardtProblem {
  /// J (residuals x parameters) and the residual r at the current parameters.
  std::function<void(Eigen::MatrixXd& jacobian, Eigen::VectorXd& residual)> linearize;
  /// The damping weights s from diag(J'J), one per parameter (> 0).
  std::function<Eigen::VectorXd(const Eigen::VectorXd& diagonal)> scaleDamping;
  /// Optional: 1 for a parameter held in this iteration, from the gradient J'r.
  std::function<Eigen::VectorXi(const Eigen::VectorXd& gradient)> findFrozen;
  /// Tries the current parameters + step; on LmTrial::Accepted the problem has moved there.
  std::function<LmTrial(const Eigen::VectorXd& step)> tryStep;
  /// After an accepted trial: whether the iterations have converged.
  std::function<bool()> hasConverged;
};

struct LevenbergMarquardtSummary {
  int iterations = 0;  ///< index of the iteration that ended the loop (maxIterations at the limit)
  LmStop stop = LmStop::IterationLimit;
  Eigen::MatrixXd jacobian;  ///< the last linearisation (see jacobianAtSolution)
};

/// Iterates from the problem's current parameters (linearised first).
LevenbergMarquardtSummary runLevenbergMarquardt(const LevenbergMarquardtProblem& problem,
                                                const LevenbergMarquardtSettings& settings);

/// The damped step dx of (JtJ + mu diag(scale)) dx = -g with dx_i = 0 where frozen(i) (frozen may be
/// empty: none held).
Eigen::VectorXd solveDampedStep(const Eigen::MatrixXd& JtJ, const Eigen::VectorXd& g, const Eigen::VectorXd& scale,
                                const Eigen::VectorXi& frozen, double mu);

}  // namespace motostab::core
