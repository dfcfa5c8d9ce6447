// The Levenberg-Marquardt iterations of core/levenberg_marquardt.h on problems with known answers: a
// noise-free exponential y = a exp(b t) with (a, b) drawn at random, recovered from a start far off,
// and the damped step against the normal equations solved here by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/levenberg_marquardt.h"
#include "core/portable_random.h"

namespace motostab::core {
namespace {

TEST(LevenbergMarquardt, RecoversADrawnExponentialFromAFarStart) {
  PortableRandom rng(1944);
  for (int trial = 0; trial < 20; ++trial) {
    const double a = rng.drawUniform(0.5, 3), b = rng.drawUniform(-2, -0.2);
    Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(40, 0, 4), y(40);
    for (int i = 0; i < 40; ++i) y(i) = a * std::exp(b * t(i));
    Eigen::Vector2d x(1, -1);  // the start: a = 1, b = -1
    auto residual = [&](const Eigen::Vector2d& p) {
      return ((p(0) * (p(1) * t.array()).exp()).matrix() - y).eval();
    };
    double cost = residual(x).squaredNorm();
    LevenbergMarquardtProblem p;
    p.linearize = [&](Eigen::MatrixXd& J, Eigen::VectorXd& r) {  // the exact Jacobian
      J.resize(40, 2);
      const Eigen::ArrayXd e = (x(1) * t.array()).exp();
      J.col(0) = e.matrix();
      J.col(1) = (x(0) * t.array() * e).matrix();
      r = residual(x);
    };
    p.scaleDamping = [](const Eigen::VectorXd& d) { return d.cwiseMax(1e-12).eval(); };
    double drop = 0;
    p.tryStep = [&](const Eigen::VectorXd& step) {
      const Eigen::Vector2d trialX = x + step;
      const double c = residual(trialX).squaredNorm();
      if (!(c < cost)) return LmTrial::Rejected;
      drop = cost - c;
      x = trialX, cost = c;
      return LmTrial::Accepted;
    };
    p.hasConverged = [&] { return drop <= 1e-14 * std::max(cost, 1e-300); };
    LevenbergMarquardtSettings s;
    s.maxIterations = 200;
    const LevenbergMarquardtSummary out = runLevenbergMarquardt(p, s);
    EXPECT_NE(out.stop, LmStop::IterationLimit) << trial;
    EXPECT_NEAR(x(0), a, 1e-8 * a) << trial;
    EXPECT_NEAR(x(1), b, 1e-8 * std::abs(b)) << trial;
  }
}

// (JtJ + mu diag(s)) dx = -g with parameter 1 held: dx_1 = 0 and the others solve the reduced system.
TEST(LevenbergMarquardt, DampedStepHoldsFrozenParameters) {
  PortableRandom rng(1963);
  Eigen::MatrixXd J(6, 3);
  for (int i = 0; i < J.size(); ++i) J.data()[i] = rng.drawUniform(-1, 1);
  Eigen::VectorXd g(3), s(3);
  for (int i = 0; i < 3; ++i) g(i) = rng.drawUniform(-1, 1), s(i) = rng.drawUniform(0.5, 2);
  const Eigen::MatrixXd JtJ = J.transpose() * J;
  const double mu = 0.1;
  const Eigen::VectorXd dx = solveDampedStep(JtJ, g, s, Eigen::Vector3i(0, 1, 0), mu);
  EXPECT_EQ(dx(1), 0);
  Eigen::Matrix2d H;  // rows and columns 0 and 2
  H << JtJ(0, 0) + mu * s(0), JtJ(0, 2), JtJ(2, 0), JtJ(2, 2) + mu * s(2);
  const Eigen::Vector2d want = H.inverse() * Eigen::Vector2d(-g(0), -g(2));
  EXPECT_NEAR(dx(0), want(0), 1e-12 * want.norm());
  EXPECT_NEAR(dx(2), want(1), 1e-12 * want.norm());
  // Nothing held: the full system.
  Eigen::MatrixXd Hf = JtJ;
  Hf.diagonal() += mu * s;
  EXPECT_LT((solveDampedStep(JtJ, g, s, Eigen::VectorXi(), mu) - Hf.inverse() * -g).norm(), 1e-12 * g.norm());
}

}  // namespace
}  // namespace motostab::core
