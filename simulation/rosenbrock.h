#pragma once
// Linearly implicit Rosenbrock-W stepper ROS34PW2 (Rang & Angermann, BIT 45 (2005) 761): order 3,
// L-stable, embedded order-2 error estimate, 4 stages, one LU of W = I - h gamma J per step. Being a
// W-method it keeps its order with any approximation J of the Jacobian, so J is reused over many
// steps; only stability depends on J capturing the stiff modes (tyre lags, swingarm compliance).
#include <Eigen/Dense>
#include <functional>
#include <vector>

namespace motostab::simulation {

/// The ROS34PW2 coefficients in Hairer-Wanner form: stage i evaluates f at y + sum_j alpha(i,j) k_j,
/// adds h J sum_j gammaOff(i,j) k_j; y1 = y + sum b_i k_i, error = sum (b_i - bHat_i) k_i.
struct RosenbrockTableau {
  double gamma = 0;
  Eigen::Matrix4d alpha, gammaOff;
  Eigen::Vector4d b, bHat;
};
const RosenbrockTableau& getRos34pw2Tableau();

struct RosenbrockOptions {
  double relativeTolerance = 1e-4;
  /// Absolute tolerance per component (same units as y); empty = relativeTolerance for all.
  Eigen::VectorXd absoluteTolerance;
  double initialStep = 1e-3;       ///< s
  double maxStep = 0.05;           ///< s
  double minStep = 1e-10;          ///< s; a smaller step needed is a failure
  double jacobianMaxAge = 5.0;     ///< s of simulated time before J is recomputed (also after two rejections)
  /// Components of y that f does not depend on (cyclic coordinates): their J columns are zero and
  /// cost no f call.
  std::vector<int> constantColumns;
};

/// Adaptive ROS34PW2 on dy/dt = f(t, y). The caller owns the model; this class owns the step logic.
class RosenbrockStepper {
 public:
  /// f(t, y, ydot) fills ydot (size of y).
  using Rhs = std::function<void(double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot)>;

  RosenbrockStepper(Rhs rhs, RosenbrockOptions options);

  /// Starts at (t, y); computes f and J there.
  void initialize(double t, const Eigen::VectorXd& y);
  /// Restarts after a discontinuity in f or y (new f; J and the step size are kept: a W-method needs
  /// no exact J, and a step that fails the error test is retried smaller).
  void reinitialize(double t, const Eigen::VectorXd& y);
  /// Takes one accepted step, ending no later than tStop (s, > getTime(), else std::logic_error).
  /// Throws std::runtime_error if the step size falls below minStep (naming a non-finite f if that
  /// was the cause) or f turns non-finite at an accepted point.
  void step(double tStop);

  double getTime() const { return t_; }
  const Eigen::VectorXd& getY() const { return y_; }
  const Eigen::VectorXd& getYDot() const { return f_; }  ///< f at the current (t, y)
  int getNumSteps() const { return numSteps_; }
  int getNumRejected() const { return numRejected_; }
  int getNumRhsCalls() const { return numRhs_; }
  int getNumJacobians() const { return numJacobians_; }

  /// Forward-difference Jacobian of f at (t, y) with f0 = f(t, y): one f call per column, none for
  /// the constant columns.
  void calcJacobian(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& f0, Eigen::MatrixXd& J);

 private:
  double calcErrorNorm(const Eigen::VectorXd& err, const Eigen::VectorXd& y0, const Eigen::VectorXd& y1) const;
  void callRhs(double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot);

  Rhs rhs_;
  RosenbrockOptions opt_;
  double t_ = 0, h_ = 0, jacobianTime_ = 0, previousError_ = 1;
  Eigen::VectorXd y_, f_;
  Eigen::MatrixXd J_, W_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::VectorXd k_[4], ys_, fs_, acc_, y1_, err_;  // step work vectors
  int numSteps_ = 0, numRejected_ = 0, numRhs_ = 0, numJacobians_ = 0;
};

}  // namespace motostab::simulation
