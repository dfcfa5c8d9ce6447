// The mirror check (y -> -y) that lets a lateral column group be differenced from one evaluation.
#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/linearize_detail.h"

namespace motostab::analysis {

using vehicle::Input;
using vehicle::VehicleModel;
namespace detail {
namespace {

// Mirror sign of pattern row r: the state's, or for a removed state's row that of the columns it
// touches (-1 if any is lateral).
int getRowSign(const ColumnGrouping& g, size_t r) {
  if (r < g.mirror.size()) return g.mirror[r];
  for (size_t j = 0; j < g.mirror.size(); ++j)
    if (g.pattern(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(j)) && g.mirror[j] == -1) return -1;
  return 1;
}

}  // namespace

bool isLateralGroup(const ColumnGrouping& g, const std::vector<int>& group) {
  if (g.mirror.empty()) return false;
  return std::all_of(group.begin(), group.end(), [&](int j) { return g.mirror[j] == -1; });
}

// A trim symmetric to 1e-9 of the difference steps: every lateral state, the steer and the roll torque
// below that (the mirror identity is then off by at most that fraction of a column).
bool isTrimSymmetric(const LinearizeContext& c, const ColumnGrouping& g, const LinearModel& lin,
                     const std::vector<int>& linearIndexOf) {
  for (size_t r = 0; r < g.states.size(); ++r) {
    const StateEntry& e = lin.states[linearIndexOf[r]].entry;
    if (g.mirror[r] == -1 && std::abs(c.fn.get(c.s, e)) > 1e-9 * c.stepFor(e)) return false;
  }
  for (Input in : {Input::SteerTorque, Input::RollTorque})
    if (std::abs(c.model.getInput(c.s, in)) > 1e-9 * c.opt.step) return false;
  return true;
}

// Mirror signs of the rows of ydot: getRowSign on the pattern's rows, +1 on the others.
Eigen::VectorXd calcRowMirror(const LinearizeContext& c, const ColumnGrouping& g, const LinearModel& lin,
                              const std::vector<int>& linearIndexOf) {
  Eigen::VectorXd sign = Eigen::VectorXd::Ones(c.nq + c.nu + c.nz);
  for (size_t r = 0; r < linearIndexOf.size(); ++r) sign[c.rowOf(lin.states[linearIndexOf[r]].entry)] = getRowSign(g, r);
  return sign;
}

}  // namespace detail

bool checkMirrorSymmetry(const VehicleModel& model, TrimResult& trim, const LinearizeOptions& opt,
                         ColumnGrouping& g, double tolerance, double* defect) {
  using namespace detail;
  if (defect) *defect = INFINITY;
  g.useMirror = false;
  if (g.mirror.empty() || trim.state.getNQErr() + trim.state.getNUErr() > 0) return false;
  const LinearizeContext c(model, trim.state, opt);
  const ConstraintJacobian cj;  // no constraints: the tangent space is every state
  const TangentSpace tangent;
  LinearModel lin;
  lin.states = listIndependentStates(c, tangent);
  const std::vector<int> idx = mapGroupingStates(g, lin);
  if (std::find(idx.begin(), idx.end(), -1) != idx.end() || !isTrimSymmetric(c, g, lin, idx)) return false;
  const Eigen::VectorXd rowMirror = calcRowMirror(c, g, lin, idx);
  auto yDot = [&](const SimTK::State& st, Eigen::VectorXd& out) { c.fn.calcYDot(st, out); };
  const std::vector<std::vector<int>> groups = planMirrorGroups(g);
  double worst = 0;
  Eigen::VectorXd fp, fm;
  for (const auto& group : groups) {
    if (!isLateralGroup(g, group)) continue;
    const Direction dir = makeGroupDirection(c, cj, tangent, lin, idx, group);
    c.fn.calcDisplaced(c.s, dir, 1.0, yDot, fp);
    c.fn.calcDisplaced(c.s, dir, -1.0, yDot, fm);
    double h = INFINITY;  // the defect in units of A: divided by the smallest step of the group
    for (int j : group) h = std::min(h, c.stepFor(lin.states[idx[j]].entry));
    for (size_t r = 0; r < idx.size(); ++r) {
      const int row = c.rowOf(lin.states[idx[r]].entry);
      const double d = std::abs(fm[row] - rowMirror[row] * fp[row]) / (2 * h);
      worst = std::max(worst, d == 0 ? 0.0 : d / std::max(g.rowScale[r], std::numeric_limits<double>::min()));
    }
  }
  if (defect) *defect = worst;
  if (!(worst <= tolerance)) return false;
  g.groups = groups;
  g.useMirror = true;
  return true;
}

}  // namespace motostab::analysis
