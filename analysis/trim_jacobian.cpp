// The trim's Newton Jacobian read off a linear model's A and B (calcTrimJacobian).
#include "analysis/linearize.h"

namespace motostab::analysis {

using vehicle::VehicleModel;
using vehicle::kNumInputs;

Eigen::MatrixXd calcTrimJacobian(const VehicleModel& model, const LinearModel& lin, const Eigen::MatrixXd& previous,
                                 const TrimOptions& trimOptions) {
  const SimTK::State& s = model.getDefaultState();
  const bool hasB = lin.B.cols() == kNumInputs;
  if (s.getNQErr() + s.getNUErr() > 0) return {};
  std::vector<int> rows;  // residual rows: every udot, then every zdot
  for (Slot slot : {Slot::U, Slot::Z})
    for (int i = 0; i < (slot == Slot::U ? model.getNumU() : model.getNumZ()); ++i) {
      rows.push_back(lin.findState(StateEntry{slot, i}));
      if (rows.back() < 0) return {};
    }
  if (trimOptions.isTurn() != lin.headingFrame) return {};
  const auto unknowns = getTrimUnknowns(model, trimOptions);
  // A turn at a fixed speed has the speed equation as its last row, copied from `previous`.
  const bool speedRow = trimOptions.isTurn() && trimOptions.condition == TurnCondition::Speed;
  const Eigen::Index nr = static_cast<Eigen::Index>(rows.size()), nx = static_cast<Eigen::Index>(unknowns.size());
  const bool previousFits = previous.rows() == nr + (speedRow ? 1 : 0) && previous.cols() == nx;
  if ((!hasB || speedRow) && !previousFits) return {};
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(nr + (speedRow ? 1 : 0), nx);
  if (speedRow) J.row(nr) = previous.row(nr);
  for (size_t j = 0; j < unknowns.size(); ++j) {
    const StateEntry& e = unknowns[j];
    if (e.slot == Slot::Input) {
      for (size_t i = 0; i < rows.size(); ++i) J(i, j) = hasB ? lin.B(rows[i], e.index) : previous(i, j);
      continue;
    }
    const int c = lin.findState(e);
    if (c >= 0)
      for (size_t i = 0; i < rows.size(); ++i) J(i, j) = lin.A(rows[i], c);
  }
  return J;
}

}  // namespace motostab::analysis
