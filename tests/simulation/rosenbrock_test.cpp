// ROS34PW2 stepper: the tableau against the order conditions (Hairer & Wanner, Solving ODEs II,
// sec. IV.7, Table 7.1), third-order convergence with a frozen, deliberately wrong Jacobian (the
// W-method property, Rang & Angermann 2005), and L-stable behaviour on the stiff Prothero-Robinson
// problem. Exact solutions are closed forms, independent of the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "simulation/rosenbrock.h"

namespace motostab::simulation {
namespace {

TEST(Rosenbrock, TableauSatisfiesOrderConditions) {
  const RosenbrockTableau& t = getRos34pw2Tableau();
  const Eigen::Matrix4d beta = t.alpha + t.gammaOff;  // off-diagonal beta_ij
  Eigen::Vector4d a = t.alpha.rowwise().sum(), bp = beta.rowwise().sum();
  const double g = t.gamma;
  EXPECT_NEAR(t.b.sum(), 1.0, 1e-14);
  EXPECT_NEAR(t.b.dot(bp), 0.5 - g, 1e-14);
  EXPECT_NEAR(t.b.dot(a.cwiseProduct(a)), 1.0 / 3, 1e-14);
  EXPECT_NEAR(t.b.dot(beta * bp), 1.0 / 6 - g + g * g, 1e-14);
  // The embedded solution is of order 2.
  EXPECT_NEAR(t.bHat.sum(), 1.0, 1e-14);
  EXPECT_NEAR(t.bHat.dot(bp), 0.5 - g, 1e-14);
  // W-method conditions of order 3 (J arbitrary; Hairer & Wanner II, sec. IV.7, with Gamma holding
  // the diagonal gamma): alpha and Gamma enter separately.
  const Eigen::Matrix4d G = t.gammaOff + g * Eigen::Matrix4d::Identity();
  const Eigen::Vector4d one = Eigen::Vector4d::Ones();
  EXPECT_NEAR(t.b.dot(t.alpha * one), 0.5, 1e-14);
  EXPECT_NEAR(t.b.dot(G * one), 0.0, 1e-14);
  EXPECT_NEAR(t.b.dot(t.alpha * t.alpha * one), 1.0 / 6, 1e-14);
  EXPECT_NEAR(t.b.dot(t.alpha * G * one), 0.0, 1e-14);
  EXPECT_NEAR(t.b.dot(G * t.alpha * one), 0.0, 1e-14);
  EXPECT_NEAR(t.b.dot(G * G * one), 0.0, 1e-14);
}

// y' = -y^2 + cos t + (2 + sin t)^2, exact y = 2 + sin t. Fixed steps h (tolerance never binds).
double calcEndError(double h, bool wrongJacobian) {
  RosenbrockOptions o;
  o.relativeTolerance = 1e3;
  o.initialStep = o.maxStep = h;
  o.jacobianMaxAge = wrongJacobian ? 1e9 : 0;
  RosenbrockStepper::Rhs f = [](double t, const Eigen::VectorXd& y, Eigen::VectorXd& d) {
    d.resize(1);
    d[0] = -y[0] * y[0] + std::cos(t) + std::pow(2 + std::sin(t), 2);
  };
  RosenbrockStepper s(f, o);
  Eigen::VectorXd y0(1);
  y0[0] = 2;
  s.initialize(0, y0);
  const double tEnd = 2;
  while (s.getTime() < tEnd - 1e-12) s.step(tEnd);
  return std::abs(s.getY()[0] - (2 + std::sin(tEnd)));
}

TEST(Rosenbrock, ThirdOrderConvergenceEvenWithAFrozenJacobian) {
  for (bool frozen : {false, true}) {
    const double e1 = calcEndError(0.02, frozen), e2 = calcEndError(0.01, frozen);
    const double order = std::log2(e1 / e2);
    EXPECT_GT(order, 2.7) << (frozen ? "frozen J" : "fresh J") << " errors " << e1 << " " << e2;
    EXPECT_LT(order, 3.4) << (frozen ? "frozen J" : "fresh J");
    EXPECT_LT(e2, 1e-5);
  }
}

// Prothero-Robinson, y' = -1e6 (y - sin t) + cos t, exact sin t: explicit methods would need
// h < 3e-6; an L-stable method follows the smooth solution with steps set by accuracy alone.
TEST(Rosenbrock, StiffProtheroRobinsonWithLargeSteps) {
  RosenbrockOptions o;
  o.relativeTolerance = 1e-6;
  o.maxStep = 1;
  RosenbrockStepper s([](double t, const Eigen::VectorXd& y, Eigen::VectorXd& d) {
    d.resize(1);
    d[0] = -1e6 * (y[0] - std::sin(t)) + std::cos(t);
  }, o);
  s.initialize(0, Eigen::VectorXd::Zero(1));
  double worst = 0;
  while (s.getTime() < 10 - 1e-12) {
    s.step(10);
    worst = std::max(worst, std::abs(s.getY()[0] - std::sin(s.getTime())));
  }
  EXPECT_LT(worst, 1e-5);
  EXPECT_LT(s.getNumSteps(), 2000);  // an explicit method needs more than 3e6
}

// Damped oscillator x'' + 2 zeta w x' + w^2 x = 0 against its closed form, adaptive steps.
TEST(Rosenbrock, AdaptiveStepsMeetTheTolerance) {
  const double w = 2 * M_PI * 5, zeta = 0.05, wd = w * std::sqrt(1 - zeta * zeta);
  for (double tol : {1e-4, 1e-6}) {
    RosenbrockOptions o;
    o.relativeTolerance = tol;
    RosenbrockStepper s([&](double, const Eigen::VectorXd& y, Eigen::VectorXd& d) {
      d.resize(2);
      d << y[1], -2 * zeta * w * y[1] - w * w * y[0];
    }, o);
    Eigen::VectorXd y0(2);
    y0 << 1, 0;
    s.initialize(0, y0);
    double worst = 0;
    while (s.getTime() < 1 - 1e-12) {
      s.step(1);
      const double t = s.getTime();
      const double exact = std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
      worst = std::max(worst, std::abs(s.getY()[0] - exact));
    }
    // Local control: the global error stays within a small multiple of the tolerance.
    EXPECT_LT(worst, 50 * tol) << "tolerance " << tol;
    EXPECT_GT(worst, 1e-3 * tol) << "suspiciously exact";
  }
}

TEST(Rosenbrock, NonFiniteDerivativeIsAnError) {
  RosenbrockOptions o;
  RosenbrockStepper s([](double t, const Eigen::VectorXd& y, Eigen::VectorXd& d) {
    d.resize(1);
    d[0] = t > 0.5 ? NAN : -y[0];
  }, o);
  s.initialize(0, Eigen::VectorXd::Ones(1));
  try {
    while (s.getTime() < 1) s.step(1);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
    EXPECT_LE(s.getTime(), 0.5);
  }
  EXPECT_THROW(s.step(s.getTime()), std::logic_error);  // the stop time must lie ahead (a caller's bug)
}

// Landing on many stop times (output samples, pulse switches) must not throttle the step size.
TEST(Rosenbrock, StopTimesDoNotShrinkTheStep) {
  auto countSteps = [](int stops) {
    RosenbrockOptions o;
    o.relativeTolerance = 1e-6;
    RosenbrockStepper s([](double, const Eigen::VectorXd& y, Eigen::VectorXd& d) {
      d.resize(2);
      d << y[1], -std::pow(2 * M_PI * 5, 2) * y[0];
    }, o);
    Eigen::VectorXd y0(2);
    y0 << 1, 0;
    s.initialize(0, y0);
    for (int k = 1; k <= stops; ++k)
      while (s.getTime() < k * 1.0 / stops - 1e-12) s.step(k * 1.0 / stops);
    return s.getNumSteps() - stops;  // steps beyond one landing step per stop
  };
  const int free = countSteps(1), stopped = countSteps(50);
  std::cout << "5 Hz oscillator over 1 s: " << free << " steps, " << stopped << " beyond the 50 landing steps\n";
  EXPECT_LE(stopped, free * 1.005);
}

}  // namespace
}  // namespace motostab::simulation
