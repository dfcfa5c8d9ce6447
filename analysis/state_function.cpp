#include "analysis/state_function.h"

namespace motostab::analysis {

using vehicle::Input;


void StateFunction::calcYDot(const SimTK::State& s, Eigen::VectorXd& ydot) const {
  model_.getSystem().realize(s, SimTK::Stage::Acceleration);
  const SimTK::Vector& yd = s.getYDot();
  ydot.resize(yd.size());
  for (int i = 0; i < yd.size(); ++i) ydot[i] = yd[i];
}

void StateFunction::calcConstraintErrors(const SimTK::State& s, Eigen::VectorXd& err) const {
  model_.getSystem().realize(s, SimTK::Stage::Velocity);
  const SimTK::Vector& qe = s.getQErr();
  const SimTK::Vector& ue = s.getUErr();
  err.resize(qe.size() + ue.size());
  for (int i = 0; i < qe.size(); ++i) err[i] = qe[i];
  for (int i = 0; i < ue.size(); ++i) err[qe.size() + i] = ue[i];
}

void StateFunction::calcTrimResidual(const SimTK::State& s, Eigen::VectorXd& r) const {
  model_.getSystem().realize(s, SimTK::Stage::Acceleration);
  const int nq = s.getNQ(), nu = s.getNU(), nz = s.getNZ();
  const SimTK::Vector& yd = s.getYDot();
  const SimTK::Vector& qe = s.getQErr();
  const SimTK::Vector& ue = s.getUErr();
  r.resize(nu + nz + qe.size() + ue.size());
  int k = 0;
  for (int i = 0; i < nu + nz; ++i) r[k++] = yd[nq + i];
  for (int i = 0; i < qe.size(); ++i) r[k++] = qe[i];
  for (int i = 0; i < ue.size(); ++i) r[k++] = ue[i];
}

double StateFunction::get(const SimTK::State& s, const StateEntry& e) const {
  switch (e.slot) {
    case Slot::Q: return s.getQ()[e.index];
    case Slot::U: return s.getU()[e.index];
    case Slot::Z: return s.getZ()[e.index];
    case Slot::Input: return model_.getInput(s, static_cast<Input>(e.index));
  }
  return 0;
}

void StateFunction::set(SimTK::State& s, const StateEntry& e, double value) const {
  switch (e.slot) {
    case Slot::Q: s.updQ()[e.index] = value; break;
    case Slot::U: s.updU()[e.index] = value; break;
    case Slot::Z: s.updZ()[e.index] = value; break;
    case Slot::Input: model_.setInput(s, static_cast<Input>(e.index), value); break;
  }
}

void StateFunction::calcDisplaced(SimTK::State& s, const std::vector<std::pair<StateEntry, double>>& dir,
                                  double step, const std::function<void(const SimTK::State&, Eigen::VectorXd&)>& fn,
                                  Eigen::VectorXd& out) const {
  std::vector<double> base(dir.size());
  for (size_t k = 0; k < dir.size(); ++k) base[k] = get(s, dir[k].first);
  for (size_t k = 0; k < dir.size(); ++k) set(s, dir[k].first, base[k] + step * dir[k].second);
  fn(s, out);
  for (size_t k = 0; k < dir.size(); ++k) set(s, dir[k].first, base[k]);
}

void StateFunction::calcDirectionalDerivative(
    SimTK::State& s, const std::vector<std::pair<StateEntry, double>>& dir, double h, int order,
    const std::function<void(const SimTK::State&, Eigen::VectorXd&)>& fn, Eigen::VectorXd& out) const {
  Eigen::VectorXd fp, fm;
  calcDisplaced(s, dir, h, fn, fp);
  calcDisplaced(s, dir, -h, fn, fm);
  out = (fp - fm) / (2 * h);
  if (order >= 4) {
    Eigen::VectorXd fp2, fm2;
    calcDisplaced(s, dir, 2 * h, fn, fp2);
    calcDisplaced(s, dir, -2 * h, fn, fm2);
    out = (8 * (fp - fm) - (fp2 - fm2)) / (12 * h);
  }
}

}  // namespace motostab::analysis
