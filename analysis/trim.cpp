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

TrimResult calcTrim(const VehicleModel& model, double speed, const TrimOptions& opt, const TrimResult* warm) {
  const StateFunction fn(model);
  const CoordinateIndices& ix = model.getIndices();
  const auto unknowns = getTrimUnknowns(model);
  const int n = static_cast<int>(unknowns.size());

  TrimResult res;
  res.speed = speed;
  res.state = warm ? warm->state : model.getDefaultState();
  SimTK::State& s = res.state;
  // Fixed part of straight running: every rate zero but the forward speed and the wheel spins.
  s.updU() = 0;
  s.updU()[ix.x] = speed;
  const double oldSpeed = warm ? warm->speed : 0;
  for (int w : {ix.rearSpin, ix.frontSpin}) {
    const double R = (w == ix.rearSpin ? model.getScenario().rearWheel : model.getScenario().frontWheel).radius;
    const double old = warm ? warm->state.getU()[w] : 0;
    s.updU()[w] = (warm && std::abs(oldSpeed) > 1e-9) ? old * speed / oldSpeed : speed / R;
  }
  for (int i : model.getCyclicQ()) s.updQ()[i] = 0;
  model.setInput(s, Input::RollTorque, 0);
  // Predictor: Newton interpolation through the last trims (residual O(dv^3) with three, O(dv^2)
  // with two), instead of the warm start itself (O(dv)).
  if (warm && warm->unknownsPerSpeed.size() == n) {
    const bool quadratic = warm->unknownsCurvature.size() == n;
    for (int j = 0; j < n; ++j) {
      double x = fn.get(warm->state, unknowns[j]) + warm->unknownsPerSpeed[j] * (speed - oldSpeed);
      if (quadratic) x += warm->unknownsCurvature[j] * (speed - oldSpeed) * (speed - warm->secantStartSpeed);
      fn.set(s, unknowns[j], x);
    }
  }

  Eigen::VectorXd r, rTrial, col;
  fn.calcTrimResidual(s, r);
  Eigen::MatrixXd J;
  bool jacobianIsCurrent = false;  // computed at the current iterate
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> decomposition;
  bool factored = false;           // decomposition holds J
  bool refresh = false;            // slow convergence: differentiate again before the next step
  if (warm && warm->jacobian.cols() == n) J = warm->jacobian;
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
  if (!(norm <= opt.tolerance)) throw TrimError(speed, norm, it);
  if (J.size() == 0) computeJacobian();
  res.jacobian = J;
  if (warm && std::abs(speed - oldSpeed) > 1e-12) {
    res.unknownsPerSpeed.resize(n);
    for (int j = 0; j < n; ++j)
      res.unknownsPerSpeed[j] = (fn.get(s, unknowns[j]) - fn.get(warm->state, unknowns[j])) / (speed - oldSpeed);
    res.secantStartSpeed = oldSpeed;
    if (warm->unknownsPerSpeed.size() == n && std::abs(speed - warm->secantStartSpeed) > 1e-12)
      res.unknownsCurvature = (res.unknownsPerSpeed - warm->unknownsPerSpeed) / (speed - warm->secantStartSpeed);
  }
  return res;
}

}  // namespace motostab
