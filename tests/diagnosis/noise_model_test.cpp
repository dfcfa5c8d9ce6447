// AR noise (diagnosis/noise_model.h): Burg's estimate of a drawn AR(1) coefficient, and the
// prewhitening against the exact Gaussian AR(2) likelihood computed here independently from the
// process's autocovariances (Brockwell & Davis 2002, Example 3.2.4: rho_1 = phi_1 / (1 - phi_2),
// rho_k = phi_1 rho_{k-1} + phi_2 rho_{k-2}; gamma_0 = sigma_a^2 (1 - phi_2) / ((1 + phi_2)((1 - phi_2)^2 - phi_1^2)))
// with a dense Cholesky factor.
#include "diagnosis/noise_model.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/portable_random.h"

namespace motostab::diagnosis {

using core::PortableRandom;

namespace {

TEST(NoiseModel, BurgRecoversAnAr1Coefficient) {
  PortableRandom rng(20261125);
  for (int trial = 0; trial < 5; ++trial) {
    const double rho = rng.drawUniform(0.8, 0.98), sigmaA = rng.drawUniform(0.01, 1.0);
    const int n = 4000;
    std::vector<double> e(n);
    e[0] = sigmaA / std::sqrt(1 - rho * rho) * rng.drawNormal();
    for (int t = 1; t < n; ++t) e[t] = rho * e[t - 1] + sigmaA * rng.drawNormal();
    double v = 0;
    const ArNoise ar = fitArNoise(e.data(), n, &v);
    ASSERT_GE(ar.getOrder(), 1);
    // Large-sample standard error of phi_1: sqrt((1 - rho^2) / n) (Brockwell & Davis 2002, sect. 5.1.1).
    EXPECT_NEAR(ar.phi[0], rho, 4 * std::sqrt((1 - rho * rho) / n) + 0.01 * (ar.getOrder() > 1)) << "rho " << rho;
    EXPECT_NEAR(std::sqrt(v), sigmaA, 0.05 * sigmaA);
    // The whitened series is white: lag-1 autocorrelation within 4 / sqrt(n).
    std::vector<double> w(n);
    whitenSeries(ar, e.data(), w.data(), n);
    double c0 = 0, c1 = 0;
    for (int t = 0; t < n; ++t) c0 += w[t] * w[t], c1 += t ? w[t] * w[t - 1] : 0.0;
    EXPECT_LT(std::abs(c1 / c0), 4 / std::sqrt(double(n)));
  }
}

TEST(NoiseModel, WhiteNoiseGetsOrderZeroMostly) {
  PortableRandom rng(77);
  int white = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> e(400);
    for (double& x : e) x = rng.drawNormal();
    white += fitArNoise(e.data(), 400).getOrder() == 0;
  }
  EXPECT_GE(white, 16);  // the Schwarz criterion rarely adds a spurious order
}

TEST(NoiseModel, WhiteningIsTheExactAr2Likelihood) {
  PortableRandom rng(4242);
  const double phi2 = rng.drawUniform(-0.6, 0.3), phi1 = rng.drawUniform(0.2, 0.95) * (1 - phi2);
  ArNoise ar;
  // Moved in whole, not assigned from a braced list: GCC 12's -Wnonnull misreads the latter's copy
  // into the empty vector.
  ar.reflection = std::vector<double>{phi1 / (1 - phi2), phi2};  // partial autocorrelations of an AR(2)
  ar.phi = std::vector<double>{phi1, phi2};
  const int n = 40;
  std::vector<double> rhoK(n);
  rhoK[0] = 1, rhoK[1] = phi1 / (1 - phi2);
  for (int k = 2; k < n; ++k) rhoK[k] = phi1 * rhoK[k - 1] + phi2 * rhoK[k - 2];
  const double gamma0 = (1 - phi2) / ((1 + phi2) * ((1 - phi2) * (1 - phi2) - phi1 * phi1));  // sigma_a = 1
  Eigen::MatrixXd S(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) S(i, j) = gamma0 * rhoK[std::abs(i - j)];
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x(i) = rng.drawNormal();
  const Eigen::LLT<Eigen::MatrixXd> llt(S);
  const double quad = x.dot(llt.solve(x));
  double logDet = 0;
  for (int i = 0; i < n; ++i) logDet += 2 * std::log(Eigen::MatrixXd(llt.matrixL())(i, i));
  std::vector<double> w(n);
  whitenSeries(ar, x.data(), w.data(), n);
  double ww = 0;
  for (double v : w) ww += v * v;
  EXPECT_NEAR(ww, quad, 1e-10 * quad);
  EXPECT_NEAR(ar.calcLogDeterminant(), logDet, 1e-10);
  EXPECT_NEAR(ar.calcMarginalFactor(), std::sqrt(gamma0), 1e-12);
}

// The convergence measure of the per-model noise iteration (diagnosis/model_fit.h): the largest
// |ln sigma ratio| or |atanh k - atanh k'|, an order change counting 1; values drawn.
TEST(NoiseModel, NoiseStateChangeIsTheLargestLogSigmaOrAtanhStep) {
  PortableRandom rng(77);
  for (int i = 0; i < 20; ++i) {
    const double s1 = rng.drawUniform(0.1, 2), s2 = rng.drawUniform(0.1, 2), k1 = rng.drawUniform(0.8, 0.98), k2 = rng.drawUniform(0.8, 0.98);
    ArNoise a, b;
    a.reflection = std::vector<double>{k1}, b.reflection = std::vector<double>{k2};
    const NoiseState x{{1.0, s1}, {ArNoise(), a}}, y{{1.0, s2}, {ArNoise(), b}};
    const double expected = std::max(std::abs(std::log(s1 / s2)), std::abs(0.5 * std::log((1 + k1) / (1 - k1)) - 0.5 * std::log((1 + k2) / (1 - k2))));
    EXPECT_NEAR(x.calcChange(y), expected, 1e-12);
    const NoiseState white{{1.0, s1}, {ArNoise(), ArNoise()}};
    EXPECT_GE(x.calcChange(white), 1.0);
  }
}

}  // namespace
}  // namespace motostab::diagnosis
