#include "diagnosis/least_squares.h"

#include <math.h>  // lgamma_r

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/levenberg_marquardt.h"

namespace motostab::diagnosis {
namespace {

Eigen::MatrixXd calcJacobian(const LeastSquaresProblem& p, const Eigen::VectorXd& x, const Eigen::VectorXd& r,
                             int& evaluations) {
  Eigen::MatrixXd J(r.size(), x.size());
  for (int i = 0; i < x.size(); ++i) {
    // Inside the box first; a rejected point (an unphysical vehicle) tries the other side; a
    // parameter rejected on both sides gets a zero column.
    const double h0 = (x(i) + p.step(i) <= p.upper(i)) ? p.step(i) : -p.step(i);
    J.col(i).setZero();
    for (double h : {h0, -h0}) {
      Eigen::VectorXd xp = x;
      xp(i) += h;
      ++evaluations;
      try {
        J.col(i) = (p.residual(xp) - r) / h;
        break;
      } catch (const std::exception&) {
      }
    }
  }
  return J;
}

// Parameters at a bound whose gradient pushes outwards are frozen for this step.
Eigen::VectorXi findFrozen(const LeastSquaresProblem& p, const Eigen::VectorXd& x, const Eigen::VectorXd& g) {
  Eigen::VectorXi frozen = Eigen::VectorXi::Zero(x.size());
  for (int i = 0; i < x.size(); ++i)
    frozen(i) = (x(i) <= p.lower(i) && g(i) > 0) || (x(i) >= p.upper(i) && g(i) < 0);
  return frozen;
}

void calcStatistics(const LeastSquaresProblem& p, const Eigen::MatrixXd& J, LeastSquaresResult& res) {
  const int n = p.numData > 0 ? p.numData : static_cast<int>(res.residual.size());
  const int np = static_cast<int>(res.x.size());
  const double s2 = n > np ? res.chi2 / (n - np) : 1.0;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(J.transpose() * J);
  res.covariance = s2 * cod.pseudoInverse();
  res.stderr_ = res.covariance.diagonal().cwiseMax(0).cwiseSqrt();
  res.correlation = Eigen::MatrixXd::Identity(np, np);
  for (int i = 0; i < np; ++i)
    for (int j = 0; j < np; ++j)
      if (i != j && res.stderr_(i) > 0 && res.stderr_(j) > 0)
        res.correlation(i, j) = res.covariance(i, j) / (res.stderr_(i) * res.stderr_(j));
  res.atBound = Eigen::VectorXi::Zero(np);
  for (int i = 0; i < np; ++i) res.atBound(i) = res.x(i) <= p.lower(i) || res.x(i) >= p.upper(i);
}

}  // namespace

LeastSquaresResult solveBoundedLeastSquares(const LeastSquaresProblem& p, const Eigen::VectorXd& x0,
                                            const LeastSquaresOptions& options) {
  LeastSquaresResult res;
  res.x = x0.cwiseMax(p.lower).cwiseMin(p.upper);
  res.residual = p.residual(res.x);
  res.chi2 = res.residual.squaredNorm();
  res.evaluations = 1;
  double drop = 0;  // fall of chi2 in the last accepted step
  core::LevenbergMarquardtProblem lm;
  lm.linearize = [&](Eigen::MatrixXd& J, Eigen::VectorXd& r) {
    J = calcJacobian(p, res.x, res.residual, res.evaluations);
    r = res.residual;
  };
  lm.scaleDamping = [](const Eigen::VectorXd& d) { return d.cwiseMax(1e-12).eval(); };
  lm.findFrozen = [&](const Eigen::VectorXd& g) { return findFrozen(p, res.x, g); };
  lm.tryStep = [&](const Eigen::VectorXd& step) {
    const Eigen::VectorXd x = (res.x + step).cwiseMax(p.lower).cwiseMin(p.upper);
    if ((x - res.x).norm() == 0) return core::LmTrial::NoMove;
    Eigen::VectorXd r;
    try {
      r = p.residual(x);
      ++res.evaluations;
    } catch (const std::exception&) {
      return core::LmTrial::Rejected;
    }
    const double chi2 = r.squaredNorm();
    if (!(std::isfinite(chi2) && chi2 < res.chi2)) return core::LmTrial::Rejected;
    drop = res.chi2 - chi2;
    res.x = x, res.residual = r, res.chi2 = chi2;
    return core::LmTrial::Accepted;
  };
  lm.hasConverged = [&] { return drop <= options.relativeTolerance * std::max(res.chi2, 1e-300); };
  core::LevenbergMarquardtSettings settings;  // mu from 1e-3, x10 per rejection, net /3 per acceptance
  settings.maxIterations = options.maxIterations;
  settings.maxTries = 12;
  settings.increase = 10;
  settings.decrease = 30, settings.minDamping = 1e-9, settings.rebound = 10;
  settings.jacobianAtSolution = options.statistics;
  const core::LevenbergMarquardtSummary s = core::runLevenbergMarquardt(lm, settings);
  res.iterations = s.iterations;
  // no descent left from the solution also counts as converged
  res.stop = s.stop == core::LmStop::IterationLimit ? "iteration limit" : "converged";
  if (options.statistics) calcStatistics(p, s.jacobian, res), res.jacobian = s.jacobian;
  else res.atBound = Eigen::VectorXi::Zero(res.x.size());
  return res;
}

namespace {

// ln Gamma(a) for a > 0. std::lgamma writes the global `signgam` (a data race between diagnosis
// threads, found by ThreadSanitizer); lgamma_r returns the sign instead.
double calcLogGamma(double a) {
  int sign = 0;
  return lgamma_r(a, &sign);
}

}  // namespace

double calcChiSquareSurvival(double x, int df) {
  if (x <= 0) return 1.0;
  const double a = 0.5 * df, z = 0.5 * x;
  if (z < a + 1) {  // series for P(a, z)
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 500; ++n) {
      term *= z / (a + n);
      sum += term;
      if (term < sum * 1e-16) break;
    }
    return 1.0 - sum * std::exp(-z + a * std::log(z) - calcLogGamma(a));
  }
  // continued fraction for Q(a, z) (modified Lentz)
  const double tiny = 1e-300;
  double b = z + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
  for (int i = 1; i < 500; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1 / d;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1) < 1e-16) break;
  }
  return std::exp(-z + a * std::log(z) - calcLogGamma(a)) * h;
}

}  // namespace motostab::diagnosis
