#include "analysis/trim.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tyres/rolling_no_slip.h"

namespace motostab::analysis {

using scenario::Scenario;
using scenario::WheelSpec;
using tyres::TorusContact;
using tyres::calcTorusContact;
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
    : std::runtime_error(trimMessage(v, r, it, phi, detail)), speed(v), residual(r), roll(phi) {}

TurnFigures calcTurnFigures(const VehicleModel& model, const SimTK::State& s) {
  model.getSystem().realize(s, SimTK::Stage::Velocity);
  const Scenario& sc = model.getScenario();
  const SimTK::MobilizedBody& wheel = model.getRearWheel();
  const SimTK::MobilizedBody& frame = model.getRearFrame();
  const TorusContact contact = calcTorusContact(wheel.getBodyRotation(s), wheel.getBodyAngularVelocity(s),
                                                sc.rearWheel.radius, sc.rearWheel.crownRadius);
  const SimTK::Vec3 p_GP = wheel.getBodyOriginLocation(s) + contact.r_CP_G;
  const SimTK::Vec3 p_GO = frame.getBodyOriginLocation(s);
  const SimTK::Vec3 v_GP = frame.getBodyOriginVelocity(s) + frame.getBodyAngularVelocity(s) % (p_GP - p_GO);
  TurnFigures f;
  f.speed = std::hypot(v_GP[0], v_GP[1]);
  f.yawRate = s.getU()[model.getIndices().yaw];
  f.pathRadius = f.yawRate == 0 ? INFINITY : f.speed / std::abs(f.yawRate);
  f.lateralAcceleration = f.speed * f.yawRate;
  return f;
}

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
  s.updQ()[ix.yaw] = 0;
  s.updQ()[ix.roll] = opt.roll;
  if (opt.condition == TurnCondition::Steer) s.updQ()[ix.steer] = opt.steer;
  if (opt.condition == TurnCondition::SteerTorque) model.setInput(s, Input::SteerTorque, opt.steerTorque);
}

void solveTrim(const VehicleModel& model, double speed, const TrimOptions& opt, TrimResult& res, bool warm);

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

// Heights (m) of the lowest points of both tyres' toroids (calcTorusContact), state realized to Position.
Eigen::Vector2d calcContactHeights(const VehicleModel& model, const SimTK::State& s) {
  model.getSystem().realize(s, SimTK::Stage::Position);
  Eigen::Vector2d z;
  int k = 0;
  for (const auto* w : {&model.getRearWheel(), &model.getFrontWheel()}) {
    const WheelSpec& spec = k == 0 ? model.getScenario().rearWheel : model.getScenario().frontWheel;
    const SimTK::Transform& X_GW = w->getBodyTransform(s);
    z[k++] = X_GW.p()[2] + calcTorusContact(X_GW.R(), SimTK::Vec3(0), spec.radius, spec.crownRadius).r_CP_G[2];
  }
  return z;
}

// Moves height and pitch so that both tyres' lowest points are back at `target` (m): a roll step
// otherwise lifts stiff tyres off the ground, where the residual has no gradient. Geometry only,
// whatever the contact model; a few Newton steps with differenced 2 x 2 Jacobians.
void restoreContactHeights(const VehicleModel& model, const Eigen::Vector2d& target, SimTK::State& s) {
  const CoordinateIndices& ix = model.getIndices();
  const int unknowns[2] = {ix.height, ix.pitch};
  for (int it = 0; it < 4; ++it) {
    const Eigen::Vector2d e = calcContactHeights(model, s) - target;
    if (e.lpNorm<Eigen::Infinity>() < 1e-13) return;
    Eigen::Matrix2d J;
    for (int j = 0; j < 2; ++j) {
      const double h = 1e-7, q0 = s.getQ()[unknowns[j]];
      s.updQ()[unknowns[j]] = q0 + h;
      J.col(j) = (calcContactHeights(model, s) - target - e) / h;
      s.updQ()[unknowns[j]] = q0;
    }
    const Eigen::Vector2d dq = J.fullPivLu().solve(-e);
    if (!dq.allFinite()) return;
    for (int j = 0; j < 2; ++j) s.updQ()[unknowns[j]] += dq[j];
  }
}

// A turn from `res` (a trim at another roll, or straight running: roll 0) to opt.roll, in roll steps of
// at most opt.rollStep at `speed`, each started from the last two by linear extrapolation (a failed step
// is retried from the last roll reached with half the step, at most four times); then the turn with
// opt's condition.
void continueTurn(const VehicleModel& model, double speed, const TrimOptions& opt, TrimResult& res) {
  const StateFunction fn(model);
  const CoordinateIndices& ix = model.getIndices();
  const double from = res.turn ? res.roll : 0.0;
  if (!res.turn) {  // straight running as a turn of radius infinity, heading along x
    SimTK::State& s = res.state;
    const double v = s.getU()[ix.x];
    s.updQ()[ix.yaw] = 0;
    s.updU()[ix.y] = 0;
    s.updU()[ix.yaw] = 0;
    res.speed = v;
  }
  TrimOptions step = opt;
  step.condition = TurnCondition::Speed;
  const double full = opt.roll - from;
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(full) / opt.rollStep - 1e-9)));
  const auto unknowns = getTrimUnknowns(model, step);
  const bool fromStraight = !res.turn;
  double h = full / n, done = 0, lastStep = 0;  // rad: the step, the roll stepped so far, the last step
  int halvings = 0, steps = 0;
  Eigen::VectorXd last, beforeLast;  // unknowns at the last two rolls reached
  SimTK::State saved;
  while (steps == 0 || std::abs(full - done) > 1e-15) {  // at least one trim as a turn (roll 0 too)
    const double next = std::abs(full - done) <= std::abs(h) * (1 + 1e-9) ? full : done + h;
    step.roll = from + next;
    SimTK::State& s = res.state;
    saved = s;
    const Eigen::Vector2d contactHeights = calcContactHeights(model, s);
    s.updQ()[ix.roll] = step.roll;
    if (beforeLast.size() > 0) {  // linear extrapolation from the last two rolls
      for (size_t j = 0; j < unknowns.size(); ++j)
        fn.set(s, unknowns[j], last[j] + (last[j] - beforeLast[j]) * (next - done) / lastStep);
    } else if (steps == 0 && fromStraight) {  // the point-mass turn: tan(roll) = -r V / g, steer ~ w r / V
      const double r = -model.getScenario().gravity * std::tan(step.roll) / std::max(speed, 0.5);
      s.updU()[ix.yaw] = r;
      s.updQ()[ix.steer] += model.getScenario().geometry.wheelbase * r / std::max(speed, 0.5);
    }
    restoreContactHeights(model, contactHeights, s);
    res.unknownsPerSpeed.resize(0), res.unknownsCurvature.resize(0);
    try {
      solveTrim(model, speed, step, res, true);
    } catch (const TrimError& e) {
      s = saved;  // back to the last roll reached, with half the step
      if (++halvings > 4) {
        std::ostringstream os;
        os << "stepping the roll from " << from * 180 / M_PI << " deg: failed at " << step.roll * 180 / M_PI
           << " deg with the step halved 4 times";
        throw TrimError(speed, e.residual, res.iterations, opt.roll, os.str());
      }
      h /= 2;
      res.jacobian.resize(0, 0);
      continue;
    }
    beforeLast.swap(last);
    last.resize(unknowns.size());
    for (size_t j = 0; j < unknowns.size(); ++j) last[j] = fn.get(s, unknowns[j]);
    lastStep = next - done, done = next, ++steps;
  }
  if (opt.condition != TurnCondition::Speed) solveTrim(model, speed, opt, res, true);
}

// A trim at `speed` from `res`: straight running, a turn at the warm start's roll, or a continuation
// in roll (continueTurn) otherwise.
void solveAny(const VehicleModel& model, double speed, const TrimOptions& opt, TrimResult& res, bool warm) {
  if (!opt.isTurn()) return solveTrim(model, speed, opt, res, warm);
  if (warm && res.turn && std::abs(res.roll - opt.roll) < 1e-12) return solveTrim(model, speed, opt, res, true);
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

namespace {

// Newton's method from `res` (a warm start when `warm`, else the default state) to the trim at `speed`.
void solveTrim(const VehicleModel& model, double speed, const TrimOptions& opt, TrimResult& res, bool warm) {
  const StateFunction fn(model);
  const auto unknowns = getTrimUnknowns(model, opt);
  const int n = static_cast<int>(unknowns.size());
  SimTK::State& s = res.state;
  const double oldSpeed = res.speed;
  Eigen::VectorXd oldUnknowns(n);
  for (int j = 0; j < n; ++j) oldUnknowns[j] = fn.get(s, unknowns[j]);
  const Eigen::VectorXd oldSlope = res.unknownsPerSpeed, oldCurvature = res.unknownsCurvature;
  const double oldSecantStart = res.secantStartSpeed;
  res.speed = speed;
  res.turn = opt.isTurn();
  res.roll = opt.roll;
  res.iterations = res.jacobianEvaluations = 0;
  res.unknownsPerSpeed.resize(0), res.unknownsCurvature.resize(0);
  setFixedPart(model, opt, speed, warm ? oldSpeed : 0.0, s);
  // Predictor: Newton interpolation through the last trims (residual O(dv^3) with three, O(dv^2)
  // with two), instead of the warm start itself (O(dv)).
  if (warm && oldSlope.size() == n) {
    const bool quadratic = oldCurvature.size() == n;
    for (int j = 0; j < n; ++j) {
      double x = oldUnknowns[j] + oldSlope[j] * (speed - oldSpeed);
      if (quadratic) x += oldCurvature[j] * (speed - oldSpeed) * (speed - oldSecantStart);
      fn.set(s, unknowns[j], x);
    }
  }
  auto residual = [&](const SimTK::State& st, Eigen::VectorXd& out) { calcResidual(fn, opt, speed, st, out); };

  if (!warm) settleHeightAndPitch(fn, model, s, opt.jacobianStep);
  Eigen::VectorXd r, rTrial, col;
  residual(s, r);
  Eigen::MatrixXd J;
  bool jacobianIsCurrent = false;  // computed at the current iterate
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> decomposition;
  bool factored = false;           // decomposition holds J
  bool refresh = false;            // slow convergence: differentiate again before the next step
  if (res.jacobian.cols() == n && res.jacobian.rows() == r.size()) {
    J.swap(res.jacobian);
    if (res.jacobianPerSpeed.rows() == J.rows() && res.jacobianPerSpeed.cols() == n)
      J += res.jacobianPerSpeed * (speed - oldSpeed);
  }
  res.jacobianPerSpeed.resize(0, 0);
  auto computeJacobian = [&]() {
    J.resize(r.size(), n);
    for (int j = 0; j < n; ++j) {
      const double h = opt.jacobianStep * std::max(1.0, std::abs(fn.get(s, unknowns[j])));
      fn.calcDirectionalDerivative(s, {{unknowns[j], 1.0}}, h, 2,
                                   residual, col);
      J.col(j) = col;
    }
    jacobianIsCurrent = true;
    factored = false;
    ++res.jacobianEvaluations;
  };

  int it = 0;
  double norm = r.lpNorm<Eigen::Infinity>();
  std::vector<double> x0(n);
  while (norm > opt.tolerance && it < opt.maxIterations) {
    ++it;
    if (J.size() == 0 || refresh) computeJacobian();
    refresh = false;
    if (!factored) decomposition.compute(J), factored = true;
    const Eigen::VectorXd dx = decomposition.solve(-r);
    for (int j = 0; j < n; ++j) x0[j] = fn.get(s, unknowns[j]);
    double step = 1.0, trialNorm = INFINITY;
    for (int ls = 0; ls < 30; ++ls, step *= 0.5) {
      for (int j = 0; j < n; ++j) fn.set(s, unknowns[j], x0[j] + step * dx[j]);
      residual(s, rTrial);
      trialNorm = rTrial.lpNorm<Eigen::Infinity>();
      if (std::isfinite(trialNorm) && trialNorm < (1 - 1e-4 * step) * norm) break;
    }
    if (!(trialNorm < norm)) {
      for (int j = 0; j < n; ++j) fn.set(s, unknowns[j], x0[j]);
      residual(s, r);
      if (jacobianIsCurrent) break;  // no descent even with a fresh Jacobian
      computeJacobian();
      continue;
    }
    // A Jacobian that no longer gives fast convergence is refreshed before the next step, if any.
    refresh = trialNorm > 0.25 * norm;
    jacobianIsCurrent = false;
    r = rTrial;
    norm = trialNorm;
  }
  res.iterations = it;
  res.residualNorm = norm;
  if (J.size() == 0 && norm <= opt.tolerance) computeJacobian();
  res.jacobian.swap(J);
  if (!(norm <= opt.tolerance)) throw TrimError(speed, norm, it, opt.roll);
  if (res.turn && opt.condition != TurnCondition::Speed) res.speed = calcTurnFigures(model, s).speed;
  if (warm && std::abs(speed - oldSpeed) > 1e-12) {
    res.unknownsPerSpeed.resize(n);
    for (int j = 0; j < n; ++j) res.unknownsPerSpeed[j] = (fn.get(s, unknowns[j]) - oldUnknowns[j]) / (speed - oldSpeed);
    res.secantStartSpeed = oldSpeed;
    if (oldSlope.size() == n && std::abs(speed - oldSecantStart) > 1e-12)
      res.unknownsCurvature = (res.unknownsPerSpeed - oldSlope) / (speed - oldSecantStart);
  }
}

}  // namespace

NoTurnError::NoTurnError(double phi, double lo, double hi, double tLo, double tHi)
    : std::runtime_error([&] {
        std::ostringstream os;
        os << "no hands-free turn at roll " << phi * 180 / M_PI << " deg between " << lo << " and " << hi
           << " m/s: the steer torque of steady turns is " << tLo << " N m at " << lo << " m/s and " << tHi
           << " N m at " << hi << " m/s, without a sign change";
        return os.str();
      }()),
      roll(phi), low(lo), high(hi) {}

TrimResult calcHandsFreeTrim(const VehicleModel& model, const std::vector<double>& speeds, const TrimOptions& opt,
                             double preferredSpeed) {
  TrimOptions fixedSpeed = opt;
  fixedSpeed.condition = TurnCondition::Speed;
  std::vector<TrimPoint> scan;  // descending speeds
  TrimResult work;
  for (auto v = speeds.rbegin(); v != speeds.rend(); ++v) {
    try {
      if (scan.empty()) work = calcTrim(model, *v, fixedSpeed);
      else updTrim(model, *v, fixedSpeed, work);
    } catch (const TrimError&) {
      if (scan.empty()) throw;
      break;  // too slow for this roll: the scan ends here
    }
    scan.push_back(makeTrimPoint(model, work));
  }
  const int torque = static_cast<int>(Input::SteerTorque);
  int best = -1;
  double bestSpeed = NAN;
  for (size_t k = 0; k + 1 < scan.size(); ++k) {
    const double t0 = scan[k].inputs[torque] - opt.steerTorque, t1 = scan[k + 1].inputs[torque] - opt.steerTorque;
    if (t0 * t1 > 0 || t0 == t1) continue;
    const double v = scan[k].speed + (scan[k + 1].speed - scan[k].speed) * t0 / (t0 - t1);
    const bool better = best < 0 || (std::isnan(preferredSpeed) ? v < bestSpeed
                                                                 : std::abs(v - preferredSpeed) < std::abs(bestSpeed - preferredSpeed));
    if (better) best = static_cast<int>(k), bestSpeed = v;
  }
  if (best < 0)
    throw NoTurnError(opt.roll, scan.back().speed, scan.front().speed, scan.back().inputs[torque], scan.front().inputs[torque]);
  TrimPoint start = scan[best];  // the bracket's turns interpolated to the estimated speed
  const double w = (bestSpeed - scan[best].speed) / (scan[best + 1].speed - scan[best].speed);
  start.y += w * (scan[best + 1].y - scan[best].y);
  start.inputs += w * (scan[best + 1].inputs - scan[best].inputs);
  start.speed = bestSpeed;
  TrimResult trim = restoreTrim(model, start);
  trim.unknownsPerSpeed.resize(0), trim.unknownsCurvature.resize(0), trim.jacobian.resize(0, 0);
  TrimOptions handsFree = opt;
  handsFree.condition = TurnCondition::SteerTorque;
  updTrim(model, bestSpeed, handsFree, trim);
  return trim;
}

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
  if (y.size() != point.y.size()) throw std::invalid_argument("restoreTrim: the point belongs to another model");
  for (int i = 0; i < y.size(); ++i) y[i] = point.y[i];
  for (int k = 0; k < kNumInputs; ++k) model.setInput(t.state, static_cast<Input>(k), point.inputs[k]);
  return t;
}

}  // namespace motostab::analysis
