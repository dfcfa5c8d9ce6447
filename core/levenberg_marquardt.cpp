#include "core/levenberg_marquardt.h"

#include <algorithm>

namespace motostab::core {

Eigen::VectorXd solveDampedStep(const Eigen::MatrixXd& JtJ, const Eigen::VectorXd& g, const Eigen::VectorXd& scale,
                                const Eigen::VectorXi& frozen, double mu) {
  Eigen::MatrixXd H = JtJ;
  Eigen::VectorXd rhs = -g;
  for (int i = 0; i < H.rows(); ++i) {
    H(i, i) += mu * scale(i);
    if (frozen.size() > 0 && frozen(i)) {
      H.row(i).setZero();
      H.col(i).setZero();
      H(i, i) = 1;
      rhs(i) = 0;
    }
  }
  return H.ldlt().solve(rhs);
}

LevenbergMarquardtSummary runLevenbergMarquardt(const LevenbergMarquardtProblem& p,
                                                const LevenbergMarquardtSettings& s) {
  LevenbergMarquardtSummary out;
  Eigen::VectorXd r;
  p.linearize(out.jacobian, r);
  double mu = s.initialDamping;
  for (out.iterations = 0; out.iterations < s.maxIterations; ++out.iterations) {
    const Eigen::MatrixXd& J = out.jacobian;
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    const Eigen::VectorXd scale = p.scaleDamping(JtJ.diagonal());
    const Eigen::VectorXi frozen = p.findFrozen ? p.findFrozen(g) : Eigen::VectorXi();
    bool improved = false;
    for (int tries = 0; tries < s.maxTries && !improved; ++tries) {
      const LmTrial t = p.tryStep(solveDampedStep(JtJ, g, scale, frozen, mu));
      if (t == LmTrial::NoMove) break;
      if (t == LmTrial::Accepted) {
        mu = std::max(mu / s.decrease, s.minDamping) * s.rebound;
        improved = true;
      } else {
        mu *= s.increase;
      }
    }
    if (!improved) {
      out.stop = LmStop::NoDescent;
      return out;
    }
    const bool converged = p.hasConverged();
    const bool last = out.iterations + 1 == s.maxIterations;
    if ((converged || last) && !s.jacobianAtSolution) {
      if (converged) out.stop = LmStop::Converged;
      else ++out.iterations;
      return out;
    }
    p.linearize(out.jacobian, r);
    if (converged) {
      out.stop = LmStop::Converged;
      return out;
    }
  }
  return out;
}

}  // namespace motostab::core
