#include "response/exponential_fit.h"

#include <cmath>
#include <limits>

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

ExponentialFit polishPoles(const ExponentialFit& start, const Eigen::VectorXd& tau, const Eigen::MatrixXd& samples,
                           double maxOmega, int maxIterations) {
  const int n = static_cast<int>(tau.size());
  const int k = static_cast<int>(samples.cols());
  ExponentialFit best = calcLinearFit(start.poles, start.offset, tau, samples);
  if (best.poles.empty() || !std::isfinite(best.residualSumSquares)) return best;
  Eigen::VectorXd p = packPoles(best.poles);
  const int np = static_cast<int>(p.size());
  double mu = 1e-3;
  for (int iter = 0; iter < maxIterations; ++iter) {
    // Kaufman's variable-projection Jacobian: J_j = -P_perp (dPhi/dp_j) c, stacked over the signals.
    const Eigen::MatrixXd basis = calcBasis(best.poles, best.offset, tau);
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(basis);
    const int rank = static_cast<int>(qr.rank());
    const Eigen::MatrixXd q = (qr.householderQ() * Eigen::MatrixXd::Identity(n, basis.cols())).leftCols(rank);
    const Eigen::MatrixXd residual = samples - basis * best.coefficients;
    Eigen::MatrixXd jac(static_cast<Eigen::Index>(n) * k, np);
    int col = best.offset ? 1 : 0, j = 0;
    const Eigen::ArrayXd t = tau.array();
    for (const auto& pole : best.poles) {
      const Eigen::ArrayXd decay = (pole.sigma * t).exp();
      if (pole.omega > 0) {
        const Eigen::ArrayXd cw = decay * (pole.omega * t).cos(), sw = decay * (pole.omega * t).sin();
        for (int s = 0; s < k; ++s) {
          const double a = best.coefficients(col, s), b = best.coefficients(col + 1, s);
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
          Eigen::VectorXd dSigma = (t * best.coefficients(col, s) * decay).matrix();
          dSigma -= q * (q.transpose() * dSigma);
          jac.block(static_cast<Eigen::Index>(s) * n, j, n, 1) = -dSigma;
        }
        col += 1;
        j += 1;
      }
    }
    const Eigen::VectorXd r = Eigen::Map<const Eigen::VectorXd>(residual.data(), residual.size());
    const Eigen::MatrixXd jtj = jac.transpose() * jac;
    const Eigen::VectorXd jtr = jac.transpose() * r;
    Eigen::VectorXd scale = jtj.diagonal().cwiseMax(1e-12 * std::max(1.0, jtj.diagonal().maxCoeff()));
    bool improved = false;
    for (int tries = 0; tries < 20 && !improved; ++tries) {
      Eigen::MatrixXd lhs = jtj;
      lhs.diagonal() += mu * scale;
      const Eigen::VectorXd step = -lhs.ldlt().solve(jtr);
      const Eigen::VectorXd trial = p + step;
      const auto poles = unpackPoles(best.poles, trial);
      bool valid = step.allFinite();
      for (const auto& pole : poles)
        if (pole.omega < 0 || pole.omega > maxOmega) valid = false;
      for (size_t m = 0; m < poles.size(); ++m)
        if (best.poles[m].omega > 0 && poles[m].omega <= 0) valid = false;
      if (valid) {
        ExponentialFit fit = calcLinearFit(poles, best.offset, tau, samples);
        if (fit.residualSumSquares < best.residualSumSquares) {
          const double gain = (best.residualSumSquares - fit.residualSumSquares) / best.residualSumSquares;
          best = std::move(fit);
          p = trial;
          mu = std::max(mu / 3, 1e-12);
          improved = true;
          if (gain < 1e-12 || step.norm() < 1e-13 * (1 + p.norm())) return best;
          break;
        }
      }
      mu *= 4;
    }
    if (!improved) break;
  }
  return best;
}

}  // namespace motostab::response
