// Bounded Levenberg-Marquardt and the chi-square tail against independent calculations.
#include "core/portable_random.h"
#include "diagnosis/least_squares.h"

#include <gtest/gtest.h>

#include <cmath>

namespace motostab::diagnosis {

using core::PortableRandom;

namespace {

// y = a exp(-b t) + noise: the fit must return a and b near the truth, with the standard errors of
// the linearised model computed here independently, (J'J)^-1 s^2.
TEST(LeastSquares, ExponentialDecayAndStandardErrors) {
  PortableRandom g(11);
  const double a = 1 + g.drawUniform(), b = 0.5 + g.drawUniform(), sigma = 0.01;
  std::vector<double> t, y;
  for (int i = 0; i < 60; ++i) {
    t.push_back(0.05 * i);
    const double u1 = std::max(g.drawUniform(), 1e-300), u2 = g.drawUniform();
    y.push_back(a * std::exp(-b * t.back()) + sigma * std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2));
  }
  LeastSquaresProblem p;
  p.residual = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd r(t.size());
    for (size_t i = 0; i < t.size(); ++i) r(i) = (y[i] - x(0) * std::exp(-x(1) * t[i])) / sigma;
    return r;
  };
  p.lower = Eigen::Vector2d(0, 0);
  p.upper = Eigen::Vector2d(10, 10);
  p.step = Eigen::Vector2d(1e-7, 1e-7);
  const LeastSquaresResult r = solveBoundedLeastSquares(p, Eigen::Vector2d(0.5, 2));
  EXPECT_EQ(r.stop, "converged");
  Eigen::MatrixXd J(t.size(), 2);
  for (size_t i = 0; i < t.size(); ++i)
    J.row(i) << std::exp(-r.x(1) * t[i]) / sigma, -r.x(0) * t[i] * std::exp(-r.x(1) * t[i]) / sigma;
  const Eigen::MatrixXd cov = (J.transpose() * J).inverse() * (r.chi2 / (t.size() - 2));
  EXPECT_NEAR(r.stderr_(0), std::sqrt(cov(0, 0)), 1e-3 * std::sqrt(cov(0, 0)));
  EXPECT_NEAR(r.stderr_(1), std::sqrt(cov(1, 1)), 1e-3 * std::sqrt(cov(1, 1)));
  EXPECT_NEAR(r.x(0), a, 4 * r.stderr_(0));
  EXPECT_NEAR(r.x(1), b, 4 * r.stderr_(1));
  EXPECT_NEAR(r.correlation(0, 1), cov(0, 1) / std::sqrt(cov(0, 0) * cov(1, 1)), 1e-3);
}

TEST(LeastSquares, StopsAtABound) {
  LeastSquaresProblem p;
  p.residual = [](const Eigen::VectorXd& x) { return Eigen::VectorXd::Constant(1, x(0) + 1.0); };  // minimum at -1
  p.lower = Eigen::VectorXd::Zero(1);
  p.upper = Eigen::VectorXd::Constant(1, 5);
  p.step = Eigen::VectorXd::Constant(1, 1e-6);
  const LeastSquaresResult r = solveBoundedLeastSquares(p, Eigen::VectorXd::Constant(1, 3));
  EXPECT_DOUBLE_EQ(r.x(0), 0);
  EXPECT_EQ(r.atBound(0), 1);
}

// Q(x; 1) = erfc(sqrt(x/2)); Q(x; 2) = exp(-x/2); Q(x; 3) = erfc(sqrt(x/2)) + sqrt(2x/pi) exp(-x/2).
TEST(LeastSquares, ChiSquareSurvival) {
  for (double x : {0.01, 0.5, 2.0, 3.841458820694124, 10.0, 40.0}) {
    EXPECT_NEAR(calcChiSquareSurvival(x, 1), std::erfc(std::sqrt(x / 2)), 1e-10 * std::erfc(std::sqrt(x / 2)) + 1e-15);
    EXPECT_NEAR(calcChiSquareSurvival(x, 2), std::exp(-x / 2), 1e-12);
    EXPECT_NEAR(calcChiSquareSurvival(x, 3), std::erfc(std::sqrt(x / 2)) + std::sqrt(2 * x / M_PI) * std::exp(-x / 2), 1e-12);
  }
  EXPECT_NEAR(calcChiSquareSurvival(3.841458820694124, 1), 0.05, 1e-12);
}

}  // namespace
}  // namespace motostab::diagnosis
