#include "simulation/rosenbrock.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace motostab::simulation {

const RosenbrockTableau& getRos34pw2Tableau() {
  static const RosenbrockTableau tab = [] {
    RosenbrockTableau t;
    t.gamma = 4.3586652150845900e-01;
    t.alpha.setZero();
    t.gammaOff.setZero();
    t.alpha(1, 0) = 8.7173304301691801e-01;
    t.alpha(2, 0) = 8.4457060015369423e-01;
    t.alpha(2, 1) = -1.1299064236484185e-01;
    t.alpha(3, 2) = 1.0;
    t.gammaOff(1, 0) = -8.7173304301691801e-01;
    t.gammaOff(2, 0) = -9.0338057013044082e-01;
    t.gammaOff(2, 1) = 5.4180672388095326e-02;
    t.gammaOff(3, 0) = 2.4212380706095346e-01;
    t.gammaOff(3, 1) = -1.2232505839045147e+00;
    t.gammaOff(3, 2) = 5.4526025533510214e-01;
    t.b << 2.4212380706095346e-01, -1.2232505839045147e+00, 1.5452602553351020e+00, 4.3586652150845900e-01;
    t.bHat << 3.7810903145819369e-01, -9.6042292212423178e-02, 5.0e-01, 2.1793326075422950e-01;
    return t;
  }();
  return tab;
}

RosenbrockStepper::RosenbrockStepper(Rhs rhs, RosenbrockOptions options) : rhs_(std::move(rhs)), opt_(std::move(options)) {
  if (!(opt_.relativeTolerance > 0)) throw std::logic_error("Rosenbrock: relative tolerance must be > 0");
  if (!(opt_.maxStep > 0 && opt_.initialStep > 0)) throw std::logic_error("Rosenbrock: steps must be > 0");
}

void RosenbrockStepper::callRhs(double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
  ++numRhs_;
  rhs_(t, y, ydot);
}

void RosenbrockStepper::calcJacobian(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& f0, Eigen::MatrixXd& J) {
  const int n = static_cast<int>(y.size());
  J.resize(n, n);
  Eigen::VectorXd yp = y, fp(n);
  for (int j = 0; j < n; ++j) {
    if (std::find(opt_.constantColumns.begin(), opt_.constantColumns.end(), j) != opt_.constantColumns.end()) {
      J.col(j).setZero();
      continue;
    }
    const double d = 1e-7 * std::max(1.0, std::abs(y[j]));
    yp[j] = y[j] + d;
    callRhs(t, yp, fp);
    J.col(j) = (fp - f0) / d;
    yp[j] = y[j];
  }
  ++numJacobians_;
}

void RosenbrockStepper::initialize(double t, const Eigen::VectorXd& y) {
  t_ = t;
  y_ = y;
  f_.resize(y.size());
  callRhs(t_, y_, f_);
  if (!f_.allFinite()) throw std::runtime_error("Rosenbrock: the derivative is non-finite at the start");
  calcJacobian(t_, y_, f_, J_);
  jacobianTime_ = t_;
  h_ = std::min(opt_.initialStep, opt_.maxStep);
  previousError_ = 1;
}

void RosenbrockStepper::reinitialize(double t, const Eigen::VectorXd& y) {
  if (J_.rows() != y.size()) return initialize(t, y);
  t_ = t;
  y_ = y;
  callRhs(t_, y_, f_);
  if (!f_.allFinite()) throw std::runtime_error("Rosenbrock: the derivative is non-finite at the restart");
}

double RosenbrockStepper::calcErrorNorm(const Eigen::VectorXd& err, const Eigen::VectorXd& y0,
                                        const Eigen::VectorXd& y1) const {
  double sum = 0;
  const bool perComponent = opt_.absoluteTolerance.size() == err.size();
  for (int i = 0; i < err.size(); ++i) {
    const double atol = perComponent ? opt_.absoluteTolerance[i] : opt_.relativeTolerance;
    const double sc = atol + opt_.relativeTolerance * std::max(std::abs(y0[i]), std::abs(y1[i]));
    sum += (err[i] / sc) * (err[i] / sc);
  }
  return std::sqrt(sum / std::max<Eigen::Index>(1, err.size()));
}

void RosenbrockStepper::step(double tStop) {
  if (!(tStop > t_)) throw std::logic_error("Rosenbrock: the stop time must lie ahead of the current time");
  const RosenbrockTableau& tab = getRos34pw2Tableau();
  const int n = static_cast<int>(y_.size());
  Eigen::VectorXd(&k)[4] = k_;  // work vectors kept between steps: no allocation per step
  Eigen::VectorXd &ys = ys_, &fs = fs_, &acc = acc_, &y1 = y1_, &err = err_;
  for (Eigen::VectorXd* v : {&k[0], &k[1], &k[2], &k[3], &ys, &fs, &acc, &y1, &err}) v->resize(n);
  bool rejectedHere = false;
  for (;;) {
    bool nonFinite = false;
    if (t_ - jacobianTime_ > opt_.jacobianMaxAge) {
      calcJacobian(t_, y_, f_, J_);
      jacobianTime_ = t_;
    }
    const double remaining = tStop - t_;
    double h = std::min(h_, opt_.maxStep);
    const bool last = h >= remaining * (1 - 1e-12);
    if (last) h = remaining;
    W_ = -(h * tab.gamma) * J_;
    W_.diagonal().array() += 1.0;
    lu_.compute(W_);
    const Eigen::PartialPivLU<Eigen::MatrixXd>& lu = lu_;
    k[0] = lu.solve(h * f_);
    for (int i = 1; i < 4; ++i) {
      ys = y_;
      acc.setZero();
      double c = 0;
      for (int j = 0; j < i; ++j) {
        if (tab.alpha(i, j) != 0) ys += tab.alpha(i, j) * k[j];
        acc += tab.gammaOff(i, j) * k[j];
        c += tab.alpha(i, j);
      }
      callRhs(t_ + c * h, ys, fs);
      if (!fs.allFinite()) nonFinite = true;
      k[i] = lu.solve(h * fs + h * (J_ * acc));
    }
    y1 = y_;
    err.setZero();
    for (int i = 0; i < 4; ++i) {
      y1 += tab.b[i] * k[i];
      err += (tab.b[i] - tab.bHat[i]) * k[i];
    }
    if (!y1.allFinite()) nonFinite = true;
    const double e = nonFinite ? HUGE_VAL : calcErrorNorm(err, y_, y1);
    if (e <= 1) {
      t_ = last ? tStop : t_ + h;
      y_ = y1;
      callRhs(t_, y_, f_);
      if (!f_.allFinite()) throw std::runtime_error("Rosenbrock: the derivative became non-finite");
      ++numSteps_;
      // A step shortened to land on tStop says little about the next one: keep h_ and the history.
      if (last && h < h_) return;
      // Gustafsson-style PI control on the order-2 estimate (local error ~ h^3).
      double factor = 0.9 * std::pow(std::max(e, 1e-10), -0.7 / 3) * std::pow(std::max(previousError_, 1e-10), 0.4 / 3);
      factor = std::clamp(factor, 0.2, rejectedHere ? 1.0 : 5.0);
      h_ = h * factor;
      previousError_ = e;
      return;
    }
    ++numRejected_;
    if (rejectedHere && jacobianTime_ < t_) {  // rejected twice: a stale J may be the cause
      calcJacobian(t_, y_, f_, J_);
      jacobianTime_ = t_;
    }
    rejectedHere = true;
    h_ = h * (std::isfinite(e) ? std::clamp(0.9 * std::pow(e, -1.0 / 3), 0.2, 0.9) : 0.2);
    if (h_ < opt_.minStep) {
      std::ostringstream os;
      os << "Rosenbrock: step size " << h_ << " s below the minimum at t = " << t_ << " s"
         << (nonFinite ? " (the derivative is non-finite in every trial step)" : "");
      throw std::runtime_error(os.str());
    }
  }
}

}  // namespace motostab::simulation
