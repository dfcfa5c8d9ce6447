// Steady turns: their figures, the continuation in roll from straight running, and hands-free turns.
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "analysis/sweep.h"
#include "analysis/trim_detail.h"

namespace motostab::analysis {

using plugins::ContactPoint;
using plugins::WheelSide;
using vehicle::CoordinateIndices;
using vehicle::Input;
using vehicle::VehicleModel;

TurnFigures calcTurnFigures(const VehicleModel& model, const SimTK::State& s) {
  model.getSystem().realize(s, SimTK::Stage::Velocity);
  const SimTK::MobilizedBody& wheel = model.getRearWheel();
  const SimTK::MobilizedBody& frame = model.getRearFrame();
  const ContactPoint contact = model.calcContactPoint(s, WheelSide::Rear);
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

namespace {

// Heights (m) of both contact points (the contact model's, VehicleModel::calcContactPoint), state
// realized to Position.
Eigen::Vector2d calcContactHeights(const VehicleModel& model, const SimTK::State& s) {
  model.getSystem().realize(s, SimTK::Stage::Position);
  Eigen::Vector2d z;
  int k = 0;
  for (const auto& [w, side] : {std::pair{&model.getRearWheel(), WheelSide::Rear}, {&model.getFrontWheel(), WheelSide::Front}})
    z[k++] = w->getBodyTransform(s).p()[2] + model.calcContactPoint(s, side).r_CP_G[2];
  return z;
}

// Moves height and pitch so that both contact points are back at `target` (m): a roll step
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

}  // namespace

namespace detail {

// Newton's method from a roll step can land on an equilibrium with a wheel in the air (Sharp's stiff
// radial tyres at 6 m/s and 15 deg: the rear frame pitched by -63 deg, the front tyre unloaded, the
// residual zero), and so can a warm start at the next speed of a sweep (Sharp's machine at 8 m/s and
// 35 deg from 7 m/s). Not a turn of the vehicle: a wheel whose lowest point is above the ground by more
// than the trim's residual allows fails the trim (TrimError); a roll step is then retried with half the
// step, a sweep's speed from cold.
void checkWheelsOnGround(const VehicleModel& model, double speed, const TrimOptions& opt, const TrimResult& res) {
  const Eigen::Vector2d z = calcContactHeights(model, res.state);
  const double allowed = std::max(opt.tolerance, res.residualNorm);
  for (int k = 0; k < 2; ++k)
    if (!(z[k] <= allowed))
      throw TrimError(speed, res.residualNorm, res.iterations, opt.roll,
                      std::string(k == 0 ? "rear" : "front") + " wheel off the ground");
}

// A turn from `res` (a trim at another roll, or straight running: roll 0) to opt.roll, in roll steps of
// at most opt.rollStep at `speed`, each started from the last two by linear extrapolation. A failed step
// is retried from the last roll reached with half the step, at most four times in a row; a step that
// succeeds doubles the step again (up to the first), so one hard stretch of roll (where the Jacobian is
// nearly singular) does not spend the halvings of the others. Then the turn with opt's condition.
void continueTurn(const VehicleModel& model, double speed, const TrimOptions& opt, TrimResult& res, bool stepWithCondition) {
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
  if (!stepWithCondition) step.condition = TurnCondition::Speed;
  const double full = opt.roll - from;
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(full) / opt.rollStep - 1e-9)));
  const auto unknowns = getTrimUnknowns(model, step);
  const bool fromStraight = !res.turn;
  const double h0 = full / n;
  double h = h0, done = 0, lastStep = 0;  // rad: the step, the roll stepped so far, the last step
  int halvings = 0, steps = 0, failures = 0;
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
      checkWheelsOnGround(model, speed, step, res);
    } catch (const TrimError& e) {
      s = saved;  // back to the last roll reached, with half the step
      if (++halvings > 4 || ++failures > 4 * (n + 1)) {
        std::ostringstream os;
        os << "stepping the roll from " << from * 180 / M_PI << " deg: failed at " << step.roll * 180 / M_PI
           << (halvings > 4 ? " deg with the step halved 4 times" : " deg after too many halved steps");
        throw TrimError(speed, e.residual, res.iterations, opt.roll, os.str());
      }
      h /= 2;
      res.jacobian.resize(0, 0);
      continue;
    }
    if (halvings > 0 || std::abs(h) < std::abs(h0)) h = std::abs(2 * h) > std::abs(h0) ? h0 : 2 * h;
    halvings = 0;
    beforeLast.swap(last);
    last.resize(unknowns.size());
    for (size_t j = 0; j < unknowns.size(); ++j) last[j] = fn.get(s, unknowns[j]);
    lastStep = next - done, done = next, ++steps;
  }
  if (step.condition != opt.condition) {
    solveTrim(model, speed, opt, res, true);
    checkWheelsOnGround(model, speed, opt, res);
  }
}

}  // namespace detail

NoTurnError::NoTurnError(double phi, double lo, double hi, double tLo, double tHi)
    : io::ResultError([&] {
        std::ostringstream os;
        os << "no hands-free turn at roll " << phi * 180 / M_PI << " deg between " << lo << " and " << hi
           << " m/s: the steer torque of steady turns is " << tLo << " N m at " << lo << " m/s and " << tHi
           << " N m at " << hi << " m/s, without a sign change";
        return os.str();
      }()),
      roll(phi), low(lo), high(hi) {}

namespace {

// Fixed-speed turns at opt.roll on `speeds` (ascending), trimmed from the top down and stopping below
// the first that fails; descending speeds.
std::vector<TrimPoint> scanFixedSpeedTurns(const VehicleModel& model, const std::vector<double>& speeds, const TrimOptions& opt) {
  TrimOptions fixedSpeed = opt;
  fixedSpeed.condition = TurnCondition::Speed;
  std::vector<TrimPoint> scan;
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
  return scan;
}

// The hands-free turn of the bracket scan[k], scan[k + 1] (a sign change of the steer torque less
// opt.steerTorque): their turns interpolated to the estimated speed, then TurnCondition::SteerTorque.
TrimResult solveBracket(const VehicleModel& model, const std::vector<TrimPoint>& scan, size_t k, const TrimOptions& opt) {
  const int torque = static_cast<int>(Input::SteerTorque);
  const double t0 = scan[k].inputs[torque] - opt.steerTorque, t1 = scan[k + 1].inputs[torque] - opt.steerTorque;
  const double w = t0 / (t0 - t1);
  TrimPoint start = scan[k];
  start.y += w * (scan[k + 1].y - scan[k].y);
  start.inputs += w * (scan[k + 1].inputs - scan[k].inputs);
  start.speed = scan[k].speed + w * (scan[k + 1].speed - scan[k].speed);
  TrimResult trim = restoreTrim(model, start);
  trim.unknownsPerSpeed.resize(0), trim.unknownsCurvature.resize(0), trim.jacobian.resize(0, 0);
  TrimOptions handsFree = opt;
  handsFree.condition = TurnCondition::SteerTorque;
  updTrim(model, start.speed, handsFree, trim);
  return trim;
}

// Roll (rad) of the hands-free turns near upright from which the turns continuing from straight
// running are followed in roll: 0.5 deg, or the turn's own roll when that is smaller.
constexpr double kNearUprightRoll = 0.5 * M_PI / 180;

// The speeds (m/s) where a real root of straight running crosses zero on `speeds`: there a hands-free
// turn branches off straight running (docs/cornering.md).
std::vector<double> findStraightRunningBranchPoints(const VehicleModel& model, const std::vector<double>& speeds) {
  SweepOptions o;
  o.keepFailedSpeeds = true;
  std::vector<double> out;
  try {
    for (const CriticalSpeed& c : runSweep(model, speeds, o).criticalSpeeds)
      if (c.frequency == 0 && c.refined) out.push_back(c.speed);
  } catch (const TrimError&) {  // no straight running at all: no branch point
  }
  return out;
}

// The hands-free turn at opt.roll reached from straight running at branch point v0 (m/s): the hands-free
// turn near upright (kNearUprightRoll) started from the fixed-speed turn at v0, followed in roll.
TrimResult continueFromStraightRunning(const VehicleModel& model, double v0, const TrimOptions& opt) {
  TrimOptions near = opt;
  near.roll = std::copysign(std::min(kNearUprightRoll, std::abs(opt.roll)), opt.roll);
  near.condition = TurnCondition::Speed;
  TrimResult trim = calcTrim(model, v0, near);
  near.condition = TurnCondition::SteerTorque;
  trim.unknownsPerSpeed.resize(0), trim.unknownsCurvature.resize(0), trim.jacobian.resize(0, 0);
  updTrim(model, v0, near, trim);
  if (near.roll != opt.roll) {
    TrimOptions handsFree = opt;
    handsFree.condition = TurnCondition::SteerTorque;
    detail::continueTurn(model, trim.speed, handsFree, trim, true);
  }
  return trim;
}

// Adds `trim` to `turns` unless a turn within 1e-6 of its speed is there; returns its index.
size_t addTurn(const VehicleModel& model, const TrimResult& trim, std::vector<HandsFreeTurn>& turns) {
  for (size_t i = 0; i < turns.size(); ++i)
    if (std::abs(turns[i].trim.speed - trim.speed) <= 1e-6 * std::max(1.0, trim.speed)) return i;
  turns.push_back({makeTrimPoint(model, trim), false});
  return turns.size() - 1;
}

}  // namespace

std::vector<HandsFreeTurn> calcHandsFreeTurns(const VehicleModel& model, const std::vector<double>& speeds,
                                              const TrimOptions& opt) {
  if (speeds.size() < 2 || !std::is_sorted(speeds.begin(), speeds.end()))
    throw std::logic_error("calcHandsFreeTurns needs at least two speeds in ascending order");
  const std::vector<TrimPoint> scan = scanFixedSpeedTurns(model, speeds, opt);
  const int torque = static_cast<int>(Input::SteerTorque);
  std::vector<HandsFreeTurn> turns;
  std::optional<TrimError> firstFailure;
  for (size_t k = 0; k + 1 < scan.size(); ++k) {
    const double t0 = scan[k].inputs[torque] - opt.steerTorque, t1 = scan[k + 1].inputs[torque] - opt.steerTorque;
    if (t0 * t1 > 0 || t0 == t1) continue;
    try {
      addTurn(model, solveBracket(model, scan, k, opt), turns);
    } catch (const TrimError& e) {
      if (!firstFailure) firstFailure = e;
    }
  }
  for (double v0 : findStraightRunningBranchPoints(model, speeds)) {
    try {
      turns[addTurn(model, continueFromStraightRunning(model, v0, opt), turns)].continuesFromStraight = true;
    } catch (const TrimError&) {  // the branch folds back or ends before this roll
    }
  }
  if (turns.empty()) {
    if (firstFailure) throw *firstFailure;
    throw NoTurnError(opt.roll, scan.back().speed, scan.front().speed, scan.back().inputs[torque], scan.front().inputs[torque]);
  }
  std::sort(turns.begin(), turns.end(), [](const HandsFreeTurn& a, const HandsFreeTurn& b) { return a.trim.speed < b.trim.speed; });
  return turns;
}

size_t chooseHandsFreeTurn(const std::vector<HandsFreeTurn>& turns, double preferredSpeed) {
  if (turns.empty()) throw std::logic_error("chooseHandsFreeTurn: no turn");
  size_t best = 0;
  for (size_t i = 1; i < turns.size(); ++i) {
    const double d = std::abs(turns[i].trim.speed - preferredSpeed), dBest = std::abs(turns[best].trim.speed - preferredSpeed);
    const bool better = std::isnan(preferredSpeed) ? turns[i].continuesFromStraight && !turns[best].continuesFromStraight
                                                   : d < dBest;
    if (better) best = i;
  }
  return best;
}

TrimResult calcHandsFreeTrim(const VehicleModel& model, const std::vector<double>& speeds, const TrimOptions& opt,
                             double preferredSpeed) {
  const std::vector<HandsFreeTurn> turns = calcHandsFreeTurns(model, speeds, opt);
  TrimResult trim = restoreTrim(model, turns[chooseHandsFreeTurn(turns, preferredSpeed)].trim);
  return trim;
}

}  // namespace motostab::analysis
