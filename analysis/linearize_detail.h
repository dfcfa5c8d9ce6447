#pragma once
// Internal stages of the linearisation shared by linearize.cpp, column_grouping.cpp and mirror_symmetry.cpp.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "analysis/linearize.h"
#include "analysis/state_function.h"

namespace motostab::analysis::detail {

using Direction = std::vector<std::pair<StateEntry, double>>;

// What every stage of linearizeInPlace reads: the model, its state function, the trim state (perturbed
// and restored in place) and the options.
struct LinearizeContext {
  const vehicle::VehicleModel& model;
  const StateFunction fn;
  SimTK::State& s;
  const LinearizeOptions& opt;
  const int nq, nu, nz;
  const bool turn;  ///< a steady turn: heading-frame velocities, yaw cyclic (addHeadingFrameTerms)
  const std::vector<int> cyclic;
  double yawRate = 0, vx = 0, vy = 0, ax = 0, ay = 0;  ///< the trim's r, xdot, ydot, xddot, yddot
  LinearizeContext(const vehicle::VehicleModel& m, SimTK::State& state, const LinearizeOptions& o, bool isTurn = false)
      : model(m), fn(m), s(state), opt(o), nq(m.getNumQ()), nu(m.getNumU()), nz(m.getNumZ()), turn(isTurn),
        cyclic(makeCyclic(m, isTurn)) {
    if (!turn) return;
    const vehicle::CoordinateIndices& ix = m.getIndices();
    Eigen::VectorXd ydot;
    fn.calcYDot(s, ydot);
    yawRate = s.getU()[ix.yaw], vx = s.getU()[ix.x], vy = s.getU()[ix.y];
    ax = ydot[nq + ix.x], ay = ydot[nq + ix.y];
  }
  static std::vector<int> makeCyclic(const vehicle::VehicleModel& m, bool isTurn) {
    std::vector<int> out = m.getCyclicQ();
    if (isTurn) out.push_back(m.getIndices().yaw);
    return out;
  }
  double stepFor(const StateEntry& e) const { return opt.step * std::max(1.0, std::abs(fn.get(s, e))); }
  bool isCyclicQ(const StateEntry& e) const {
    return e.slot == Slot::Q && std::find(cyclic.begin(), cyclic.end(), e.index) != cyclic.end();
  }
  // Row of a q, u or z in ydot.
  int rowOf(const StateEntry& e) const { return e.slot == Slot::Q ? e.index : e.slot == Slot::U ? nq + e.index : nq + nu + e.index; }
};

// The constraint Jacobian G = d[qerr; uerr]/d[q; u] at the trim, and the count of its position rows.
struct ConstraintJacobian {
  Eigen::MatrixXd G;
  int m = 0, mp = 0;
};

// The tangent space of the constraints: dependent q and u, and the solve for their increments.
struct TangentSpace {
  std::vector<int> depQ, depU, depCols;  ///< depCols: q index, or nq + u index
  Eigen::PartialPivLU<Eigen::MatrixXd> GdepLU;
};

// Independent states in model order: q, u, z (linearize.cpp).
std::vector<LinearState> listIndependentStates(const LinearizeContext& c, const TangentSpace& t);
// The group's direction with each column's step (linearize.cpp).
Direction makeGroupDirection(const LinearizeContext& c, const ConstraintJacobian& cj, const TangentSpace& t,
                             const LinearModel& lin, const std::vector<int>& linearIndexOf, const std::vector<int>& group);

// Grouping pattern row -> lin.states index, -1 where lin lacks the state (column_grouping.cpp).
std::vector<int> mapGroupingStates(const ColumnGrouping& g, const LinearModel& lin);
// Groups for one-evaluation lateral columns (column_grouping.cpp).
std::vector<std::vector<int>> planMirrorGroups(const ColumnGrouping& g);

// Whether every column of `group` is lateral (mirror sign -1) (mirror_symmetry.cpp).
bool isLateralGroup(const ColumnGrouping& g, const std::vector<int>& group);
// A trim symmetric to 1e-9 of the difference steps (mirror_symmetry.cpp).
bool isTrimSymmetric(const LinearizeContext& c, const ColumnGrouping& g, const LinearModel& lin,
                     const std::vector<int>& linearIndexOf);
// Mirror signs of the rows of ydot (mirror_symmetry.cpp).
Eigen::VectorXd calcRowMirror(const LinearizeContext& c, const ColumnGrouping& g, const LinearModel& lin,
                              const std::vector<int>& linearIndexOf);

}  // namespace motostab::analysis::detail
