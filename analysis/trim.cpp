// Trims: Newton's method (straight running, or a turn at a fixed roll), the entry points and trim points.
#include "analysis/trim.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <vector>

#include "analysis/trim_detail.h"
#include "io/number.h"

namespace motostab::analysis {

using vehicle::CoordinateIndices;
using vehicle::Input;
using vehicle::VehicleModel;
using vehicle::kNumInputs;


namespace {
std::string trimMessage(double speed, double residual, int iterations, double roll, const std::string& detail) {
  std::ostringstream os;
  os << "trim failed at speed " << speed << " m/s";
  if (std::isfinite(roll)) os << ", roll " << roll * 180 / M_PI << " deg";
  os << ": residual norm " << residual << " after " << iterations << " iterations";
  if (!detail.empty()) os << " (" << detail << ")";
  return os.str();
}
}  // namespace

TrimError::TrimError(double v, double r, int it, double phi, const std::string& detail)
    : io::ResultError(trimMessage(v, r, it, phi, detail)), speed(v), residual(r), roll(phi) {}

TrimError::TrimError(const std::string& what, const TrimError& first)
    : io::ResultError(what + "; first: " + first.what()), speed(first.speed), residual(first.residual), roll(first.roll) {}

TrimError::TrimError(const std::string& what, double v, double phi)
    : io::ResultError(what + " (from " + io::formatNumber(v, 6) + " m/s)"), speed(v), residual(NAN), roll(phi) {}

std::vector<StateEntry> getTrimUnknowns(const VehicleModel& model) {
  std::vector<StateEntry> out;
  const auto cyclic = model.getCyclicQ();
  for (int i = 0; i < model.getNumQ(); ++i)
    if (std::find(cyclic.begin(), cyclic.end(), i) == cyclic.end()) out.push_back({Slot::Q, i});
  out.push_back({Slot::U, model.getIndices().rearSpin});
  out.push_back({Slot::U, model.getIndices().frontSpin});
  for (int i = 0; i < model.getNumZ(); ++i) out.push_back({Slot::Z, i});
  out.push_back({Slot::Input, static_cast<int>(Input::SteerTorque)});
  out.push_back({Slot::Input, static_cast<int>(Input::DriveTorque)});
  return out;
}

std::vector<StateEntry> getTrimUnknowns(const VehicleModel& model, const TrimOptions& opt) {
  if (!opt.isTurn()) return getTrimUnknowns(model);
  const CoordinateIndices& ix = model.getIndices();
  std::vector<int> fixedQ = model.getCyclicQ();
  fixedQ.insert(fixedQ.end(), {ix.yaw, ix.roll});
  if (opt.condition == TurnCondition::Steer) fixedQ.push_back(ix.steer);
  std::vector<StateEntry> out;
  for (int i = 0; i < model.getNumQ(); ++i)
    if (std::find(fixedQ.begin(), fixedQ.end(), i) == fixedQ.end()) out.push_back({Slot::Q, i});
  for (int i : {ix.yaw, ix.x, ix.y, ix.rearSpin, ix.frontSpin}) out.push_back({Slot::U, i});
  for (int i = 0; i < model.getNumZ(); ++i) out.push_back({Slot::Z, i});
  if (opt.condition != TurnCondition::SteerTorque) out.push_back({Slot::Input, static_cast<int>(Input::SteerTorque)});
  out.push_back({Slot::Input, static_cast<int>(Input::DriveTorque)});
  return out;
}

namespace {

using detail::continueTurn;
using detail::solveTrim;

// The residual of the trim `opt` asks for at `speed` (trim.h): [udot; zdot; qerr; uerr], in a turn with
// the centripetal terms of the rear wheel centre's acceleration and, fixing the speed, V_P - V.
void calcResidual(const StateFunction& fn, const TrimOptions& opt, double speed, const SimTK::State& s,
                  Eigen::VectorXd& r) {
  fn.calcTrimResidual(s, r);
  if (!opt.isTurn()) return;
  const CoordinateIndices& ix = fn.getModel().getIndices();
  const SimTK::Vector& u = s.getU();
  r[ix.x] += u[ix.yaw] * u[ix.y];
  r[ix.y] -= u[ix.yaw] * u[ix.x];
  if (opt.condition == TurnCondition::Speed) {
    r.conservativeResize(r.size() + 1);
    r[r.size() - 1] = calcTurnFigures(fn.getModel(), s).speed - speed;
  }
}

// The fixed part of the state. Straight running: every rate zero but the forward speed and the
// wheel spins. A turn: yaw 0, the roll (and steer) fixed, every rate zero but the yaw rate, xdot,
// ydot and the spins, which a warm start from `oldSpeed` (> 0) scales to `speed`.
void setFixedPart(const VehicleModel& model, const TrimOptions& opt, double speed, double oldSpeed, SimTK::State& s) {
  const CoordinateIndices& ix = model.getIndices();
  const SimTK::Vector oldU = s.getU();
  const bool scaled = std::abs(oldSpeed) > 1e-9 && (!opt.isTurn() || opt.condition == TurnCondition::Speed);
  const double scale = scaled ? speed / oldSpeed : 1.0;
  s.updU() = 0;
  for (int i : model.getCyclicQ()) s.updQ()[i] = 0;
  model.setInput(s, Input::RollTorque, 0);
  if (!opt.isTurn()) {
    s.updU()[ix.x] = speed;
    for (int w : {ix.rearSpin, ix.frontSpin}) {
      const double R = (w == ix.rearSpin ? model.getScenario().rearWheel : model.getScenario().frontWheel).radius;
      s.updU()[w] = scaled ? oldU[w] * scale : speed / R;
    }
    return;
  }
  for (int i : {ix.x, ix.y, ix.rearSpin, ix.frontSpin}) s.updU()[i] = oldU[i] * scale;
  s.updU()[ix.yaw] = oldU[ix.yaw] / scale;
  // At a fixed roll the path curvature goes as 1/V^2 (point-mass turn, g tan(roll) = V^2 / R) and the
  // steer with it: kept as it was, a tight turn's steer (26 deg at 4 m/s and 35 deg) would start the
  // next speed's Newton iteration far enough away to reach another, unstable equilibrium. A predictor
  // with a secant slope (predictUnknowns) overrides this.
  if (scaled && ix.steer >= 0) s.updQ()[ix.steer] /= scale * scale;
  s.updQ()[ix.yaw] = 0;
  s.updQ()[ix.roll] = opt.roll;
  if (opt.condition == TurnCondition::Steer) s.updQ()[ix.steer] = opt.steer;
  if (opt.condition == TurnCondition::SteerTorque) model.setInput(s, Input::SteerTorque, opt.steerTorque);
}

// A cold start begins at the design pose, where force-based tyres carry no load: every tyre force
// and its derivative vanish, and a tyre with forces at zero slip (Magic Formula shifts) couples the
// height to lateral rows whose own columns are zero, so the first full Newton step is unbounded.
// Gauss-Newton on height and pitch alone first loads the tyres (a few steps; nothing happens for
// rolling constraints, whose pose already holds). Only the cold start uses it.
void settleHeightAndPitch(const StateFunction& fn, const VehicleModel& model, SimTK::State& s, double step) {
  const std::vector<StateEntry> sub{{Slot::Q, model.getIndices().height}, {Slot::Q, model.getIndices().pitch}};
  Eigen::VectorXd r, rTrial, col;
  fn.calcTrimResidual(s, r);
  for (int it = 0; it < 20; ++it) {
    Eigen::MatrixXd J(r.size(), 2);
    for (int j = 0; j < 2; ++j) {
      fn.calcDirectionalDerivative(s, {{sub[j], 1.0}}, step, 2,
                                   [&](const SimTK::State& st, Eigen::VectorXd& out) { fn.calcTrimResidual(st, out); },
                                   col);
      J.col(j) = col;
    }
    const Eigen::VectorXd dx = J.completeOrthogonalDecomposition().solve(-r);
    const double x0[2] = {fn.get(s, sub[0]), fn.get(s, sub[1])};
    double lambda = 1;
    bool better = false;
    for (int ls = 0; ls < 20 && !better; ++ls, lambda *= 0.5) {
      for (int j = 0; j < 2; ++j) fn.set(s, sub[j], x0[j] + lambda * dx[j]);
      fn.calcTrimResidual(s, rTrial);
      better = std::isfinite(rTrial.norm()) && rTrial.norm() < (1 - 1e-4 * lambda) * r.norm();
    }
    if (!better) {
      for (int j = 0; j < 2; ++j) fn.set(s, sub[j], x0[j]);
      return;
    }
    const bool slow = rTrial.norm() > 0.999 * r.norm();
    r = rTrial;
    if (slow) return;
  }
}

// The warm start's speed, unknowns and secant data, kept before a solve overwrites them.
struct WarmStart {
  double speed, secantStart;
  Eigen::VectorXd unknowns, slope, curvature;
};

WarmStart recordWarmStart(const StateFunction& fn, const std::vector<StateEntry>& unknowns, const TrimResult& res) {
  const int n = static_cast<int>(unknowns.size());
  WarmStart w;
  w.speed = res.speed;
  w.unknowns.resize(n);
  for (int j = 0; j < n; ++j) w.unknowns[j] = fn.get(res.state, unknowns[j]);
  w.slope = res.unknownsPerSpeed, w.curvature = res.unknownsCurvature;
  w.secantStart = res.secantStartSpeed;
  return w;
}

// Predictor: Newton interpolation through the last trims (residual O(dv^3) with three, O(dv^2)
// with two), instead of the warm start itself (O(dv)). Nothing without a secant slope.
void predictUnknowns(const StateFunction& fn, const std::vector<StateEntry>& unknowns, const WarmStart& w, double speed,
                     SimTK::State& s) {
  const int n = static_cast<int>(unknowns.size());
  if (w.slope.size() != n) return;
  const bool quadratic = w.curvature.size() == n;
  for (int j = 0; j < n; ++j) {
    double x = w.unknowns[j] + w.slope[j] * (speed - w.speed);
    if (quadratic) x += w.curvature[j] * (speed - w.speed) * (speed - w.secantStart);
    fn.set(s, unknowns[j], x);
  }
}

// The secant slope (and, with the warm start's own slope, the curvature) of the unknowns over speed
// from the warm start `w` to the trim in `res`, for the next predictor.
void updateSecant(const StateFunction& fn, const std::vector<StateEntry>& unknowns, const WarmStart& w, double speed,
                  TrimResult& res) {
  const int n = static_cast<int>(unknowns.size());
  res.unknownsPerSpeed.resize(n);
  for (int j = 0; j < n; ++j) res.unknownsPerSpeed[j] = (fn.get(res.state, unknowns[j]) - w.unknowns[j]) / (speed - w.speed);
  res.secantStartSpeed = w.speed;
  if (w.slope.size() == n && std::abs(speed - w.secantStart) > 1e-12)
    res.unknownsCurvature = (res.unknownsPerSpeed - w.slope) / (speed - w.secantStart);
}

// Damped Newton iteration on the trim unknowns at `speed` from res.state. The Jacobian is kept across
// steps (and across trims through TrimResult::jacobian), factored only when it changes, and
// differentiated again when convergence slows or a step finds no descent.
class TrimNewton {
 public:
  TrimNewton(const StateFunction& fn, const std::vector<StateEntry>& unknowns, const TrimOptions& opt, double speed,
             TrimResult& res)
      : fn_(fn), unknowns_(unknowns), opt_(opt), speed_(speed), res_(res), s_(res.state),
        n_(static_cast<int>(unknowns.size())),
        residual_([this](const SimTK::State& st, Eigen::VectorXd& out) { calcResidual(fn_, opt_, speed_, st, out); }) {}

  // The starting residual, and the warm start's Jacobian (moved along its speed derivative from
  // `oldSpeed`) when its shape fits.
  void begin(double oldSpeed) {
    residual_(s_, r_);
    if (res_.jacobian.cols() == n_ && res_.jacobian.rows() == r_.size()) {
      J_.swap(res_.jacobian);
      if (res_.jacobianPerSpeed.rows() == J_.rows() && res_.jacobianPerSpeed.cols() == n_)
        J_ += res_.jacobianPerSpeed * (speed_ - oldSpeed);
    }
    res_.jacobianPerSpeed.resize(0, 0);
  }

  // Steps until the residual's infinity norm is at most opt.tolerance or opt.maxIterations are spent;
  // stores the iterations, the norm and the Jacobian in res; TrimError if it did not converge.
  void iterate() {
    int it = 0;
    double norm = r_.lpNorm<Eigen::Infinity>();
    bool converged = false;
    std::vector<double> x0(n_);
    Eigen::VectorXd rTrial;
    while (norm > opt_.tolerance && it < opt_.maxIterations) {
      ++it;
      if (J_.size() == 0 || refresh_) computeJacobian();
      refresh_ = false;
      const bool fresh = jacobianIsCurrent_;
      if (!factored_) decomposition_.compute(J_), factored_ = true;
      const Eigen::VectorXd dx = decomposition_.solve(-r_);
      for (int j = 0; j < n_; ++j) x0[j] = fn_.get(s_, unknowns_[j]);
      double step = 1.0, trialNorm = INFINITY;
      for (int ls = 0; ls < 30; ++ls, step *= 0.5) {
        for (int j = 0; j < n_; ++j) fn_.set(s_, unknowns_[j], x0[j] + step * dx[j]);
        residual_(s_, rTrial);
        trialNorm = rTrial.lpNorm<Eigen::Infinity>();
        if (std::isfinite(trialNorm) && trialNorm < (1 - 1e-4 * step) * norm) break;
      }
      if (!(trialNorm < norm)) {
        for (int j = 0; j < n_; ++j) fn_.set(s_, unknowns_[j], x0[j]);
        residual_(s_, r_);
        if (jacobianIsCurrent_) {  // no descent even with a fresh Jacobian: done if at the round-off floor
          converged = norm <= calcRoundOffFloor(x0);
          break;
        }
        computeJacobian();
        continue;
      }
      // A Jacobian that no longer gives fast convergence is refreshed before the next step, if any.
      refresh_ = trialNorm > 0.25 * norm;
      jacobianIsCurrent_ = false;
      // A step of a fresh Jacobian that no longer halves the residual, ending at its round-off floor:
      // what is left is rounding, which further steps only shuffle.
      const bool stalled = fresh && trialNorm > 0.5 * norm;
      r_ = rTrial;
      norm = trialNorm;
      if (stalled && norm > opt_.tolerance) {
        for (int j = 0; j < n_; ++j) x0[j] = fn_.get(s_, unknowns_[j]);
        if (norm <= calcRoundOffFloor(x0)) {
          converged = true;
          break;
        }
      }
    }
    res_.iterations = it;
    res_.residualNorm = norm;
    if (J_.size() == 0 && norm <= opt_.tolerance) computeJacobian();
    res_.jacobian.swap(J_);
    if (!(norm <= opt_.tolerance) && !converged) throw TrimError(speed_, norm, it, opt_.roll);
  }

 private:
  // The residual's round-off floor at the unknowns x (J_ differentiated near x): the largest change of
  // a residual row when every unknown moves by its rounding error, eps max_i sum_j |J_ij| |x_j|. Stiff
  // tyres put it above opt.tolerance (Sharp's radial 1e7 N/m: about 2e-10 against 1e-11); it is used
  // only when Newton stops descending, or stops converging, with a fresh Jacobian.
  double calcRoundOffFloor(const std::vector<double>& x) const {
    double floor = 0;
    for (Eigen::Index i = 0; i < J_.rows(); ++i) {
      double row = 0;
      for (int j = 0; j < n_; ++j) row += std::abs(J_(i, j)) * std::abs(x[j]);
      floor = std::max(floor, row);
    }
    return std::numeric_limits<double>::epsilon() * floor;
  }

  // Central differences of the residual along each unknown at the current iterate.
  void computeJacobian() {
    J_.resize(r_.size(), n_);
    for (int j = 0; j < n_; ++j) {
      const double h = opt_.jacobianStep * std::max(1.0, std::abs(fn_.get(s_, unknowns_[j])));
      fn_.calcDirectionalDerivative(s_, {{unknowns_[j], 1.0}}, h, 2, residual_, col_);
      J_.col(j) = col_;
    }
    jacobianIsCurrent_ = true;
    factored_ = false;
    ++res_.jacobianEvaluations;
  }

  const StateFunction& fn_;
  const std::vector<StateEntry>& unknowns_;
  const TrimOptions& opt_;
  const double speed_;
  TrimResult& res_;
  SimTK::State& s_;
  const int n_;
  const std::function<void(const SimTK::State&, Eigen::VectorXd&)> residual_;
  Eigen::VectorXd r_, col_;
  Eigen::MatrixXd J_;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> decomposition_;
  bool jacobianIsCurrent_ = false;  // computed at the current iterate
  bool factored_ = false;           // decomposition_ holds J_
  bool refresh_ = false;            // slow convergence: differentiate again before the next step
};

// A trim at `speed` from `res`: straight running, a turn at the warm start's roll, or a continuation
// in roll (continueTurn) otherwise.
void solveAny(const VehicleModel& model, double speed, const TrimOptions& opt, TrimResult& res, bool warm) {
  if (!opt.isTurn()) return solveTrim(model, speed, opt, res, warm);
  if (warm && res.turn && std::abs(res.roll - opt.roll) < 1e-12) {
    solveTrim(model, speed, opt, res, true);
    return detail::checkWheelsOnGround(model, speed, opt, res);
  }
  if (!warm) {
    TrimOptions straight = opt;
    straight.roll = NAN;
    solveTrim(model, speed, straight, res, false);
  }
  continueTurn(model, speed, opt, res);
}

}  // namespace

TrimResult calcTrim(const VehicleModel& model, double speed, const TrimOptions& opt, const TrimResult* warm) {
  TrimResult res;
  if (warm) {
    res = *warm;
  } else {
    res.state = model.getDefaultState();
  }
  solveAny(model, speed, opt, res, warm != nullptr);
  return res;
}

void updTrim(const VehicleModel& model, double speed, const TrimOptions& opt, TrimResult& trim) {
  solveAny(model, speed, opt, trim, true);
}

namespace detail {

// Newton's method from `res` (a warm start when `warm`, else the default state) to the trim at `speed`.
void solveTrim(const VehicleModel& model, double speed, const TrimOptions& opt, TrimResult& res, bool warm) {
  const StateFunction fn(model);
  const auto unknowns = getTrimUnknowns(model, opt);
  SimTK::State& s = res.state;
  const WarmStart old = recordWarmStart(fn, unknowns, res);
  res.speed = speed;
  res.turn = opt.isTurn();
  res.roll = opt.roll;
  res.iterations = res.jacobianEvaluations = 0;
  res.unknownsPerSpeed.resize(0), res.unknownsCurvature.resize(0);
  setFixedPart(model, opt, speed, warm ? old.speed : 0.0, s);
  if (warm) predictUnknowns(fn, unknowns, old, speed, s);
  if (!warm) settleHeightAndPitch(fn, model, s, opt.jacobianStep);
  TrimNewton newton(fn, unknowns, opt, speed, res);
  newton.begin(old.speed);
  newton.iterate();
  if (res.turn && opt.condition != TurnCondition::Speed) res.speed = calcTurnFigures(model, s).speed;
  if (warm && std::abs(speed - old.speed) > 1e-12) updateSecant(fn, unknowns, old, speed, res);
}

}  // namespace detail

TrimPoint makeTrimPoint(const VehicleModel& model, const TrimResult& trim) {
  TrimPoint p;
  static_cast<TrimSummary&>(p) = trim;
  const SimTK::Vector& y = trim.state.getY();
  p.y.resize(y.size());
  for (int i = 0; i < y.size(); ++i) p.y[i] = y[i];
  p.inputs.resize(kNumInputs);
  for (int k = 0; k < kNumInputs; ++k) p.inputs[k] = model.getInput(trim.state, static_cast<Input>(k));
  return p;
}

TrimResult restoreTrim(const VehicleModel& model, const TrimPoint& point) {
  TrimResult t;
  static_cast<TrimSummary&>(t) = point;
  t.state = model.getDefaultState();
  SimTK::Vector& y = t.state.updY();
  if (y.size() != point.y.size()) throw std::logic_error("restoreTrim: the point belongs to another model");
  for (int i = 0; i < y.size(); ++i) y[i] = point.y[i];
  for (int k = 0; k < kNumInputs; ++k) model.setInput(t.state, static_cast<Input>(k), point.inputs[k]);
  return t;
}

}  // namespace motostab::analysis
