#include "analysis/trim.h"

#include <cmath>
#include <sstream>

namespace motostab {

namespace {
std::string trimMessage(double speed, double residual, int iterations) {
  std::ostringstream os;
  os << "trim failed at speed " << speed << " m/s: residual norm " << residual << " after " << iterations
     << " iterations";
  return os.str();
}
}  // namespace

TrimError::TrimError(double v, double r, int it) : std::runtime_error(trimMessage(v, r, it)), speed(v), residual(r) {}

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

namespace {
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
}  // namespace

TrimResult calcTrim(const VehicleModel& model, double speed, const TrimOptions& opt, const TrimResult* warm) {
  TrimResult res;
  if (warm) {
    res = *warm;
  } else {
    res.state = model.getDefaultState();
  }
  solveTrim(model, speed, opt, res, warm != nullptr);
  return res;
}

void updTrim(const VehicleModel& model, double speed, const TrimOptions& opt, TrimResult& trim) {
  solveTrim(model, speed, opt, trim, true);
}

namespace {

// Newton's method from `res` (a warm start when `warm`, else the default state) to the trim at `speed`.
void solveTrim(const VehicleModel& model, double speed, const TrimOptions& opt, TrimResult& res, bool warm) {
  const StateFunction fn(model);
  const CoordinateIndices& ix = model.getIndices();
  const auto unknowns = getTrimUnknowns(model);
  const int n = static_cast<int>(unknowns.size());
  SimTK::State& s = res.state;
  const double oldSpeed = res.speed;
  Eigen::VectorXd oldUnknowns(n);
  for (int j = 0; j < n; ++j) oldUnknowns[j] = fn.get(s, unknowns[j]);
  const Eigen::VectorXd oldSlope = res.unknownsPerSpeed, oldCurvature = res.unknownsCurvature;
  const double oldSecantStart = res.secantStartSpeed;
  res.speed = speed;
  res.iterations = res.jacobianEvaluations = 0;
  res.unknownsPerSpeed.resize(0), res.unknownsCurvature.resize(0);
  // Fixed part of straight running: every rate zero but the forward speed and the wheel spins.
  const SimTK::Vector oldU = s.getU();
  s.updU() = 0;
  s.updU()[ix.x] = speed;
  for (int w : {ix.rearSpin, ix.frontSpin}) {
    const double R = (w == ix.rearSpin ? model.getScenario().rearWheel : model.getScenario().frontWheel).radius;
    s.updU()[w] = (warm && std::abs(oldSpeed) > 1e-9) ? oldU[w] * speed / oldSpeed : speed / R;
  }
  for (int i : model.getCyclicQ()) s.updQ()[i] = 0;
  model.setInput(s, Input::RollTorque, 0);
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

  if (!warm) settleHeightAndPitch(fn, model, s, opt.jacobianStep);
  Eigen::VectorXd r, rTrial, col;
  fn.calcTrimResidual(s, r);
  Eigen::MatrixXd J;
  bool jacobianIsCurrent = false;  // computed at the current iterate
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> decomposition;
  bool factored = false;           // decomposition holds J
  bool refresh = false;            // slow convergence: differentiate again before the next step
  if (res.jacobian.cols() == n) {
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
                                   [&](const SimTK::State& st, Eigen::VectorXd& out) { fn.calcTrimResidual(st, out); },
                                   col);
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
      fn.calcTrimResidual(s, rTrial);
      trialNorm = rTrial.lpNorm<Eigen::Infinity>();
      if (std::isfinite(trialNorm) && trialNorm < (1 - 1e-4 * step) * norm) break;
    }
    if (!(trialNorm < norm)) {
      for (int j = 0; j < n; ++j) fn.set(s, unknowns[j], x0[j]);
      fn.calcTrimResidual(s, r);
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
  if (!(norm <= opt.tolerance)) throw TrimError(speed, norm, it);
  if (warm && std::abs(speed - oldSpeed) > 1e-12) {
    res.unknownsPerSpeed.resize(n);
    for (int j = 0; j < n; ++j) res.unknownsPerSpeed[j] = (fn.get(s, unknowns[j]) - oldUnknowns[j]) / (speed - oldSpeed);
    res.secantStartSpeed = oldSpeed;
    if (oldSlope.size() == n && std::abs(speed - oldSecantStart) > 1e-12)
      res.unknownsCurvature = (res.unknownsPerSpeed - oldSlope) / (speed - oldSecantStart);
  }
}

}  // namespace

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

}  // namespace motostab
