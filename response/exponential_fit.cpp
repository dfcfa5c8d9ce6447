#include "response/exponential_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/levenberg_marquardt.h"

namespace motostab::response {
namespace {

// Parameters of the poles as one vector: sigma (real pole) or sigma, omega (pair).
Eigen::VectorXd packPoles(const std::vector<ContinuousPole>& poles) {
  std::vector<double> p;
  for (const auto& pole : poles) {
    p.push_back(pole.sigma);
    if (pole.omega > 0) p.push_back(pole.omega);
  }
  return Eigen::Map<Eigen::VectorXd>(p.data(), static_cast<Eigen::Index>(p.size()));
}

std::vector<ContinuousPole> unpackPoles(const std::vector<ContinuousPole>& shape, const Eigen::VectorXd& p) {
  std::vector<ContinuousPole> poles = shape;
  int i = 0;
  for (auto& pole : poles) {
    pole.sigma = p(i++);
    if (pole.omega > 0) pole.omega = p(i++);
  }
  return poles;
}

}  // namespace

int getBasisSize(const std::vector<ContinuousPole>& poles, bool offset) {
  int n = offset ? 1 : 0;
  for (const auto& pole : poles) n += pole.omega > 0 ? 2 : 1;
  return n;
}

Eigen::MatrixXd calcBasis(const std::vector<ContinuousPole>& poles, bool offset, const Eigen::VectorXd& tau) {
  Eigen::MatrixXd basis(tau.size(), getBasisSize(poles, offset));
  int c = 0;
  if (offset) basis.col(c++).setOnes();
  for (const auto& pole : poles) {
    const Eigen::ArrayXd decay = (pole.sigma * tau.array()).exp();
    if (pole.omega > 0) {
      basis.col(c++) = decay * (pole.omega * tau.array()).cos();
      basis.col(c++) = decay * (pole.omega * tau.array()).sin();
    } else {
      basis.col(c++) = decay;
    }
  }
  return basis;
}

ExponentialFit calcLinearFit(const std::vector<ContinuousPole>& poles, bool offset, const Eigen::VectorXd& tau,
                             const Eigen::MatrixXd& samples) {
  ExponentialFit fit;
  fit.poles = poles;
  fit.offset = offset;
  const Eigen::MatrixXd basis = calcBasis(poles, offset, tau);
  if (!basis.allFinite()) {
    fit.coefficients = Eigen::MatrixXd::Zero(basis.cols(), samples.cols());
    fit.residualSumSquares = std::numeric_limits<double>::infinity();
    return fit;
  }
  fit.coefficients = basis.colPivHouseholderQr().solve(samples);
  fit.residualSumSquares = (samples - basis * fit.coefficients).squaredNorm();
  return fit;
}

namespace {

// Kaufman's variable-projection Jacobian of the residual at `fit`: J_j = -P_perp (dPhi/dp_j) c, stacked
// over the signals.
Eigen::MatrixXd calcProjectedJacobian(const ExponentialFit& fit, const Eigen::MatrixXd& basis, const Eigen::VectorXd& tau,
                                      int np) {
  const int n = static_cast<int>(tau.size());
  const int k = static_cast<int>(fit.coefficients.cols());
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(basis);
  const int rank = static_cast<int>(qr.rank());
  const Eigen::MatrixXd q = (qr.householderQ() * Eigen::MatrixXd::Identity(n, basis.cols())).leftCols(rank);
  Eigen::MatrixXd jac(static_cast<Eigen::Index>(n) * k, np);
  int col = fit.offset ? 1 : 0, j = 0;
  const Eigen::ArrayXd t = tau.array();
  for (const auto& pole : fit.poles) {
    const Eigen::ArrayXd decay = (pole.sigma * t).exp();
    if (pole.omega > 0) {
      const Eigen::ArrayXd cw = decay * (pole.omega * t).cos(), sw = decay * (pole.omega * t).sin();
      for (int s = 0; s < k; ++s) {
        const double a = fit.coefficients(col, s), b = fit.coefficients(col + 1, s);
        Eigen::VectorXd dSigma = (t * (a * cw + b * sw)).matrix();
        Eigen::VectorXd dOmega = (t * (-a * sw + b * cw)).matrix();
        dSigma -= q * (q.transpose() * dSigma);
        dOmega -= q * (q.transpose() * dOmega);
        jac.block(static_cast<Eigen::Index>(s) * n, j, n, 1) = -dSigma;
        jac.block(static_cast<Eigen::Index>(s) * n, j + 1, n, 1) = -dOmega;
      }
      col += 2;
      j += 2;
    } else {
      for (int s = 0; s < k; ++s) {
        Eigen::VectorXd dSigma = (t * fit.coefficients(col, s) * decay).matrix();
        dSigma -= q * (q.transpose() * dSigma);
        jac.block(static_cast<Eigen::Index>(s) * n, j, n, 1) = -dSigma;
      }
      col += 1;
      j += 1;
    }
  }
  return jac;
}

}  // namespace

ExponentialFit polishPoles(const ExponentialFit& start, const Eigen::VectorXd& tau, const Eigen::MatrixXd& samples,
                           double maxOmega, int maxIterations) {
  ExponentialFit best = calcLinearFit(start.poles, start.offset, tau, samples);
  if (best.poles.empty() || !std::isfinite(best.residualSumSquares)) return best;
  Eigen::VectorXd p = packPoles(best.poles);
  const int np = static_cast<int>(p.size());
  double gain = 0, stepNorm = 0;  // of the last accepted step
  core::LevenbergMarquardtProblem lm;
  lm.linearize = [&](Eigen::MatrixXd& jac, Eigen::VectorXd& r) {
    const Eigen::MatrixXd basis = calcBasis(best.poles, best.offset, tau);
    jac = calcProjectedJacobian(best, basis, tau, np);
    const Eigen::MatrixXd residual = samples - basis * best.coefficients;
    r = Eigen::Map<const Eigen::VectorXd>(residual.data(), residual.size());
  };
  lm.scaleDamping = [](const Eigen::VectorXd& d) { return d.cwiseMax(1e-12 * std::max(1.0, d.maxCoeff())).eval(); };
  lm.tryStep = [&](const Eigen::VectorXd& step) {
    const Eigen::VectorXd trial = p + step;
    const auto poles = unpackPoles(best.poles, trial);
    bool valid = step.allFinite();
    for (size_t m = 0; m < poles.size(); ++m)
      if (poles[m].omega < 0 || poles[m].omega > maxOmega || (best.poles[m].omega > 0 && poles[m].omega <= 0))
        valid = false;
    if (!valid) return core::LmTrial::Rejected;
    ExponentialFit fit = calcLinearFit(poles, best.offset, tau, samples);
    if (!(fit.residualSumSquares < best.residualSumSquares)) return core::LmTrial::Rejected;
    gain = (best.residualSumSquares - fit.residualSumSquares) / best.residualSumSquares;
    stepNorm = step.norm();
    best = std::move(fit);
    p = trial;
    return core::LmTrial::Accepted;
  };
  lm.hasConverged = [&] { return gain < 1e-12 || stepNorm < 1e-13 * (1 + p.norm()); };
  core::LevenbergMarquardtSettings settings;  // mu from 1e-3, x4 per rejection, /3 per acceptance
  settings.maxIterations = maxIterations;
  settings.maxTries = 20;
  settings.increase = 4;
  settings.decrease = 3, settings.minDamping = 1e-12, settings.rebound = 1;
  core::runLevenbergMarquardt(lm, settings);
  return best;
}

}  // namespace motostab::response
