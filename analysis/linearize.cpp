#include "analysis/linearize.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace motostab::analysis {

using vehicle::CoordinateIndices;
using vehicle::Input;
using vehicle::VehicleModel;
using vehicle::kNumInputs;

int LinearModel::findState(const std::string& name) const {
  for (size_t i = 0; i < states.size(); ++i)
    if (states[i].name == name) return static_cast<int>(i);
  return -1;
}

Eigen::RowVectorXd LinearModel::getRateRow(const std::string& name) const {
  const int k = findState(name);
  if (k >= 0) return A.row(k);
  for (const auto& r : removedRows)
    if (r.first == name) return r.second;
  return {};
}

std::vector<int> chooseDependentColumns(const Eigen::MatrixXd& G, const std::vector<int>& priority) {
  std::vector<int> dep;
  const int m = static_cast<int>(G.rows());
  for (int c : priority) {
    if (static_cast<int>(dep.size()) == m) break;
    Eigen::MatrixXd sub(m, dep.size() + 1);
    for (size_t k = 0; k < dep.size(); ++k) sub.col(k) = G.col(dep[k]);
    sub.col(dep.size()) = G.col(c);
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(sub);
    qr.setThreshold(1e-9);
    if (qr.rank() == static_cast<int>(dep.size()) + 1) dep.push_back(c);
  }
  return dep;
}

namespace {

std::vector<int> withPriority(const std::vector<int>& first, int n) {
  std::vector<int> out;
  for (int i : first)
    if (i >= 0) out.push_back(i);
  for (int i = 0; i < n; ++i)
    if (std::find(out.begin(), out.end(), i) == out.end()) out.push_back(i);
  return out;
}

// Column indices with coordinates first, then rates, then auxiliary states (only those with
// mirror sign `side`, if given).
std::vector<int> orderBySlot(const std::vector<Slot>& slots, const std::vector<int>& mirror, int side = 0) {
  std::vector<int> order;
  for (Slot slot : {Slot::Q, Slot::U, Slot::Z})
    for (size_t j = 0; j < slots.size(); ++j)
      if (slots[j] == slot && (side == 0 || mirror[j] == side)) order.push_back(static_cast<int>(j));
  return order;
}

// Greedy grouping (Curtis, Powell & Reid 1974) of the columns in `order`: each joins the first group
// whose rows it does not touch. Singletons included.
std::vector<std::vector<int>> colourColumns(const Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic>& pattern,
                                            const std::vector<int>& order) {
  const Eigen::Index n = pattern.rows();
  std::vector<std::vector<int>> groups;
  std::vector<Eigen::Matrix<bool, Eigen::Dynamic, 1>> rows;  // union of the rows each group touches
  for (int j : order) {
    size_t k = 0;
    while (k < groups.size() && (rows[k].array() && pattern.col(j).array()).any()) ++k;
    if (k == groups.size()) groups.emplace_back(), rows.emplace_back(Eigen::Matrix<bool, Eigen::Dynamic, 1>::Constant(n, false));
    groups[k].push_back(j);
    rows[k] = rows[k].array() || pattern.col(j).array();
  }
  return groups;
}

// The pattern's connected block holding roll as mirror signs (-1 in it, +1 elsewhere); empty without
// roll or when the block is everything.
std::vector<int> proposeMirror(const ColumnGrouping& g) {
  const int n = static_cast<int>(g.states.size());
  const auto roll = std::find(g.states.begin(), g.states.end(), "roll");
  if (roll == g.states.end()) return {};
  std::vector<int> sign(n, 1), stack{static_cast<int>(roll - g.states.begin())};
  sign[stack.back()] = -1;
  int count = 1;
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    for (int j = 0; j < n; ++j)
      if (sign[j] == 1 && (g.pattern(i, j) || g.pattern(j, i))) sign[j] = -1, ++count, stack.push_back(j);
  }
  return count == n ? std::vector<int>{} : sign;
}

}  // namespace

Eigen::MatrixXd calcTrimJacobian(const VehicleModel& model, const LinearModel& lin, const Eigen::MatrixXd& previous,
                                 const TrimOptions& trimOptions) {
  const SimTK::State& s = model.getDefaultState();
  const bool hasB = lin.B.cols() == kNumInputs;
  if (s.getNQErr() + s.getNUErr() > 0) return {};
  std::vector<int> rows;  // residual rows: every udot, then every zdot
  for (const auto* names : {&model.getUNames(), &model.getZNames()})
    for (const auto& name : *names) {
      rows.push_back(lin.findState(name));
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
    const auto& names = e.slot == Slot::Q ? model.getQNames() : e.slot == Slot::U ? model.getUNames() : model.getZNames();
    const int c = lin.findState(names[e.index]);
    if (c >= 0)
      for (size_t i = 0; i < rows.size(); ++i) J(i, j) = lin.A(rows[i], c);
  }
  return J;
}

ColumnGrouping calcColumnGrouping(const std::vector<const LinearModel*>& samples, double tolerance) {
  ColumnGrouping g;
  if (samples.empty()) return g;
  const LinearModel& first = *samples.front();
  const int n = static_cast<int>(first.states.size()), nr = static_cast<int>(first.removedRows.size());
  for (const LinearModel* m : samples) {
    if (static_cast<int>(m->states.size()) != n || m->A.rows() != n || static_cast<int>(m->removedRows.size()) != nr)
      return {};
    for (int i = 0; i < n; ++i)
      if (m->states[i].name != first.states[i].name) return {};
    for (int k = 0; k < nr; ++k)
      if (m->removedRows[k].first != first.removedRows[k].first || m->removedRows[k].second.size() != n) return {};
  }
  for (const auto& st : first.states) g.states.push_back(st.name);
  for (const auto& r : first.removedRows) g.removedStates.push_back(r.first);
  g.pattern.setConstant(n + nr, n, false);
  g.rowScale.assign(n + nr, 0.0);
  for (const LinearModel* m : samples)
    for (int i = 0; i < n + nr; ++i) {
      const Eigen::RowVectorXd row = i < n ? Eigen::RowVectorXd(m->A.row(i)) : m->removedRows[i - n].second;
      const double rowMax = row.cwiseAbs().maxCoeff();
      g.rowScale[i] = std::max(g.rowScale[i], rowMax);
      for (int j = 0; j < n; ++j) g.pattern(i, j) = g.pattern(i, j) || std::abs(row[j]) > tolerance * rowMax;
    }
  g.mirror = proposeMirror(g);
  for (const auto& st : first.states) g.slots.push_back(st.entry.slot);
  const std::vector<std::vector<int>> groups = colourColumns(g.pattern, orderBySlot(g.slots, {}));
  for (auto& grp : groups)
    if (grp.size() > 1) g.groups.push_back(grp);
  return g;
}

LinearModel linearize(const VehicleModel& model, const TrimResult& trim, const LinearizeOptions& opt) {
  TrimResult work;
  work.speed = trim.speed;
  work.turn = trim.turn;
  work.roll = trim.roll;
  work.state = trim.state;
  return linearizeInPlace(model, work, opt);
}

namespace {

using Direction = std::vector<std::pair<StateEntry, double>>;

// What every stage of linearizeInPlace reads: the model, its state function, the trim state (perturbed
// and restored in place) and the options.
struct LinearizeContext {
  const VehicleModel& model;
  const StateFunction fn;
  SimTK::State& s;
  const LinearizeOptions& opt;
  const int nq, nu, nz;
  const bool turn;  ///< a steady turn: heading-frame velocities, yaw cyclic (addHeadingFrameTerms)
  const std::vector<int> cyclic;
  double yawRate = 0, vx = 0, vy = 0, ax = 0, ay = 0;  ///< the trim's r, xdot, ydot, xddot, yddot
  LinearizeContext(const VehicleModel& m, SimTK::State& state, const LinearizeOptions& o, bool isTurn = false)
      : model(m), fn(m), s(state), opt(o), nq(m.getNumQ()), nu(m.getNumU()), nz(m.getNumZ()), turn(isTurn),
        cyclic(makeCyclic(m, isTurn)) {
    if (!turn) return;
    const CoordinateIndices& ix = m.getIndices();
    Eigen::VectorXd ydot;
    fn.calcYDot(s, ydot);
    yawRate = s.getU()[ix.yaw], vx = s.getU()[ix.x], vy = s.getU()[ix.y];
    ax = ydot[nq + ix.x], ay = ydot[nq + ix.y];
  }
  static std::vector<int> makeCyclic(const VehicleModel& m, bool isTurn) {
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

ConstraintJacobian calcConstraintJacobian(const LinearizeContext& c) {
  const int nq = c.nq, nu = c.nu;
  auto errors = [&](const SimTK::State& st, Eigen::VectorXd& out) { c.fn.calcConstraintErrors(st, out); };
  Eigen::VectorXd err0, col;
  c.fn.calcConstraintErrors(c.s, err0);
  ConstraintJacobian out;
  out.m = static_cast<int>(err0.size());
  out.mp = c.s.getNQErr();
  Eigen::MatrixXd& G = out.G;
  G.resize(out.m, nq + nu);
  for (int j = 0; j < nq + nu && out.m > 0; ++j) {  // no constraints: G has no rows
    const StateEntry e{j < nq ? Slot::Q : Slot::U, j < nq ? j : j - nq};
    if (c.isCyclicQ(e) && !c.opt.computeCyclicColumns) {
      G.col(j).setZero();
      continue;
    }
    if (e.slot == Slot::U) continue;  // below, exactly
    c.fn.calcDirectionalDerivative(c.s, {{e, 1.0}}, c.stepFor(e), c.opt.order, errors, col);
    G.col(j) = col;
  }
  // The constraint errors are affine in u: one-sided unit differences are exact.
  for (int j = 0; j < nu && out.m > 0; ++j) {
    const StateEntry e{Slot::U, j};
    const double base = c.fn.get(c.s, e);
    c.fn.set(c.s, e, base + 1.0);
    c.fn.calcConstraintErrors(c.s, col);
    c.fn.set(c.s, e, base);
    G.col(nq + j) = col - err0;
  }
  return out;
}

// The tangent space of the constraints: dependent q and u, and the solve for their increments.
struct TangentSpace {
  std::vector<int> depQ, depU, depCols;  ///< depCols: q index, or nq + u index
  Eigen::PartialPivLU<Eigen::MatrixXd> GdepLU;
};

TangentSpace chooseTangentSpace(const LinearizeContext& c, const ConstraintJacobian& cj) {
  // Dependent coordinates: heights and pitch first, then the rates that the contact fixes.
  const CoordinateIndices& ix = c.model.getIndices();
  const int nq = c.nq, nu = c.nu, m = cj.m, mp = cj.mp;
  TangentSpace t;
  if (m > 0) {
    t.depQ = chooseDependentColumns(cj.G.topLeftCorner(mp, nq), withPriority({ix.height, ix.pitch}, nq));
    t.depU = chooseDependentColumns(cj.G.bottomRightCorner(m - mp, nu),
                                    withPriority({ix.height, ix.pitch, ix.rearSpin, ix.frontSpin, ix.y, ix.yaw}, nu));
    if (static_cast<int>(t.depQ.size()) != mp || static_cast<int>(t.depU.size()) != m - mp)
      throw std::runtime_error("linearize: constraints are redundant or singular at the trim");
  }
  for (int q : t.depQ) t.depCols.push_back(q);
  for (int u : t.depU) t.depCols.push_back(nq + u);
  Eigen::MatrixXd Gdep(m, t.depCols.size());
  for (size_t k = 0; k < t.depCols.size(); ++k) Gdep.col(k) = cj.G.col(t.depCols[k]);
  if (m > 0) t.GdepLU = Gdep.partialPivLu();
  return t;
}

// Independent states in model order: q, u, z.
std::vector<LinearState> listIndependentStates(const LinearizeContext& c, const TangentSpace& t) {
  std::vector<LinearState> states;
  for (int i = 0; i < c.nq; ++i)
    if (std::find(t.depQ.begin(), t.depQ.end(), i) == t.depQ.end()) states.push_back({c.model.getQNames()[i], {Slot::Q, i}});
  for (int i = 0; i < c.nu; ++i)
    if (std::find(t.depU.begin(), t.depU.end(), i) == t.depU.end()) states.push_back({c.model.getUNames()[i], {Slot::U, i}});
  for (int i = 0; i < c.nz; ++i) states.push_back({c.model.getZNames()[i], {Slot::Z, i}});
  return states;
}

// The perturbation along independent state `e` scaled by `scale`, with the dependent coordinates
// moved to stay on the constraints.
// In a turn, yaw in the heading frame turns the ground-frame velocity with it: d(xdot, ydot) =
// (-ydot, xdot) dpsi (docs/cornering.md).
void addDirection(const LinearizeContext& c, const ConstraintJacobian& cj, const TangentSpace& t, const StateEntry& e,
                  double scale, Direction& dir) {
  const size_t first = dir.size();
  dir.push_back({e, scale});
  const CoordinateIndices& ix = c.model.getIndices();
  if (c.turn && e.slot == Slot::Q && e.index == ix.yaw)
    dir.push_back({{Slot::U, ix.x}, -c.vy * scale}), dir.push_back({{Slot::U, ix.y}, c.vx * scale});
  if (e.slot == Slot::Z || cj.m == 0) return;
  Eigen::VectorXd g = Eigen::VectorXd::Zero(cj.m);
  for (size_t k = first; k < dir.size(); ++k) g += dir[k].second * cj.G.col(c.rowOf(dir[k].first));
  const Eigen::VectorXd dDep = t.GdepLU.solve(-g);
  for (size_t k = 0; k < t.depCols.size(); ++k) {
    const int col = t.depCols[k];
    dir.push_back({{col < c.nq ? Slot::Q : Slot::U, col < c.nq ? col : col - c.nq}, dDep[k]});
  }
}

// The heading-frame velocity v_h = R(-psi) (xdot, ydot) obeys v_h' = R(-psi) a_G - r J v_h (J: +90 deg
// about z); at psi = 0 its derivative along `dir` is the ground-frame one plus (docs/cornering.md)
//   d(v_h')/d psi = -J a_G,  d(v_h')/d r = -J v_h,  d(v_h')/d v_h = -r J.
void addHeadingFrameTerms(const LinearizeContext& c, const Direction& dir, Eigen::VectorXd& col) {
  if (!c.turn) return;
  const CoordinateIndices& ix = c.model.getIndices();
  const int rowX = c.nq + ix.x, rowY = c.nq + ix.y;
  double dPsi = 0, dR = 0, dVx = 0, dVy = 0;  // dVx, dVy: of the ground-frame velocity
  for (const auto& [e, k] : dir) {
    if (e.slot == Slot::Q && e.index == ix.yaw) dPsi += k;
    if (e.slot != Slot::U) continue;
    if (e.index == ix.yaw) dR += k;
    if (e.index == ix.x) dVx += k;
    if (e.index == ix.y) dVy += k;
  }
  // The heading-frame velocity's own change: the ground-frame one less the turn by dPsi.
  const double dHx = dVx + c.vy * dPsi, dHy = dVy - c.vx * dPsi;
  col[rowX] += c.ay * dPsi + c.vy * dR + c.yawRate * dHy;
  col[rowY] += -c.ax * dPsi - c.vx * dR - c.yawRate * dHx;
}

// The derivative of ydot along `dir` (step h), in the heading frame in a turn.
void differentiate(const LinearizeContext& c, SimTK::State& s, const Direction& dir, double h, Eigen::VectorXd& col) {
  auto yDot = [&](const SimTK::State& st, Eigen::VectorXd& out) { c.fn.calcYDot(st, out); };
  c.fn.calcDirectionalDerivative(s, dir, h, c.opt.order, yDot, col);
  addHeadingFrameTerms(c, dir, col);
}

// Grouping pattern row (states, then removed states) -> lin.states index (-1 where lin lacks the
// state); the first g.states.size() entries are the columns'.
std::vector<int> mapGroupingStates(const ColumnGrouping& g, const LinearModel& lin) {
  std::vector<int> out;
  for (const auto* names : {&g.states, &g.removedStates})
    for (const auto& name : *names) out.push_back(lin.findState(name));
  return out;
}

// Mirror sign of pattern row r: the state's, or for a removed state's row that of the columns it
// touches (-1 if any is lateral).
int getRowSign(const ColumnGrouping& g, size_t r) {
  if (r < g.mirror.size()) return g.mirror[r];
  for (size_t j = 0; j < g.mirror.size(); ++j)
    if (g.pattern(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(j)) && g.mirror[j] == -1) return -1;
  return 1;
}

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

// The group's direction with each column's step (rad, m, rad/s, m/s).
Direction makeGroupDirection(const LinearizeContext& c, const ConstraintJacobian& cj, const TangentSpace& t,
                             const LinearModel& lin, const std::vector<int>& linearIndexOf, const std::vector<int>& group) {
  Direction dir;
  for (int g : group) {
    const StateEntry& e = lin.states[linearIndexOf[g]].entry;
    addDirection(c, cj, t, e, c.stepFor(e), dir);
  }
  return dir;
}

// Columns of A evaluated together (opt.grouping); marks them in `done`. Lateral groups at a symmetric
// trim take one evaluation (checkMirrorSymmetry): (f(y0 + d) - f(y0 - d)) / 2 with f(y0 - d) = S f(y0 + d).
void differenceGroupedColumns(const LinearizeContext& c, const ConstraintJacobian& cj, const TangentSpace& t,
                              const LinearModel& lin, Eigen::MatrixXd& A, std::vector<bool>& done) {
  const ColumnGrouping& grouping = c.opt.grouping;
  auto yDot = [&](const SimTK::State& st, Eigen::VectorXd& out) { c.fn.calcYDot(st, out); };
  const std::vector<int> linearIndexOf = mapGroupingStates(grouping, lin);
  const bool grouped = !grouping.groups.empty() &&
                       std::find(linearIndexOf.begin(), linearIndexOf.end(), -1) == linearIndexOf.end();
  if (!grouped) return;
  const bool mirrored = grouping.useMirror && cj.m == 0 && !c.turn && isTrimSymmetric(c, grouping, lin, linearIndexOf);
  const Eigen::VectorXd rowMirror = mirrored ? calcRowMirror(c, grouping, lin, linearIndexOf) : Eigen::VectorXd();
  Eigen::VectorXd col;
  for (const auto& group : grouping.groups) {
    const Direction dir = makeGroupDirection(c, cj, t, lin, linearIndexOf, group);
    if (mirrored && isLateralGroup(grouping, group)) {
      c.fn.calcDisplaced(c.s, dir, 1.0, yDot, col);
      col = (col - rowMirror.cwiseProduct(col)) / 2;
    } else {
      differentiate(c, c.s, dir, 1.0, col);  // sum of h_j times column j
    }
    for (int g : group) {
      const int j = linearIndexOf[g];
      const double h = c.stepFor(lin.states[j].entry);
      A.col(j).setZero();
      for (size_t r = 0; r < linearIndexOf.size(); ++r)
        if (grouping.pattern(r, g)) A(linearIndexOf[r], j) = col[c.rowOf(lin.states[linearIndexOf[r]].entry)] / h;
      done[j] = true;
    }
  }
}

// A: directional derivatives along the tangent-space basis vectors, grouped ones together.
Eigen::MatrixXd differenceColumns(const LinearizeContext& c, const ConstraintJacobian& cj, const TangentSpace& t,
                                  const LinearModel& lin) {
  const int n = static_cast<int>(lin.states.size());
  const int yaw = c.model.getIndices().yaw;
  Eigen::MatrixXd A(n, n);
  std::vector<bool> done(n, false);
  differenceGroupedColumns(c, cj, t, lin, A, done);
  Eigen::VectorXd col;
  for (int j = 0; j < n; ++j) {
    if (done[j]) continue;
    const StateEntry& e = lin.states[j].entry;
    const bool knownDeadYaw = e.slot == Slot::Q && e.index == yaw && c.opt.removeYaw == 1;
    if ((c.isCyclicQ(e) && !c.opt.computeCyclicColumns) || knownDeadYaw) {
      A.col(j).setZero();
      continue;
    }
    Direction dir;
    addDirection(c, cj, t, e, 1.0, dir);
    differentiate(c, c.s, dir, c.stepFor(e), col);
    for (int i = 0; i < n; ++i) A(i, j) = col[c.rowOf(lin.states[i].entry)];
  }
  return A;
}

// B: accelerations are affine in the generalized input forces, so a one-sided unit difference is exact.
Eigen::MatrixXd differenceInputColumns(const LinearizeContext& c, const LinearModel& lin) {
  const int n = static_cast<int>(lin.states.size());
  Eigen::MatrixXd B(n, c.opt.computeB ? kNumInputs : 0);
  Eigen::VectorXd y0, y1;
  if (c.opt.computeB) c.fn.calcYDot(c.s, y0);
  for (int k = 0; k < B.cols(); ++k) {
    const StateEntry in{Slot::Input, k};
    const double base = c.fn.get(c.s, in);
    c.fn.set(c.s, in, base + 1.0);
    c.fn.calcYDot(c.s, y1);
    c.fn.set(c.s, in, base);
    for (int i = 0; i < n; ++i) B(i, k) = y1[c.rowOf(lin.states[i].entry)] - y0[c.rowOf(lin.states[i].entry)];
  }
  return B;
}

// Columns (states) to remove: the cyclic coordinates, and yaw when no kept row depends on it.
std::vector<int> chooseRemovedStates(const LinearizeContext& c, const LinearModel& lin, const Eigen::MatrixXd& A) {
  const int n = static_cast<int>(lin.states.size());
  std::vector<int> remove;
  int yawCol = -1;
  for (int j = 0; j < n; ++j) {
    const StateEntry& e = lin.states[j].entry;
    if (e.slot != Slot::Q) continue;
    if (c.isCyclicQ(e)) remove.push_back(j);
    else if (e.index == c.model.getIndices().yaw) yawCol = j;
  }
  if (yawCol >= 0) {
    double yawInfluence = 0;
    for (int i = 0; i < n; ++i)
      if (std::find(remove.begin(), remove.end(), i) == remove.end())
        yawInfluence = std::max(yawInfluence, std::abs(A(i, yawCol)));
    const bool dead = yawInfluence < c.opt.zeroColumnTolerance * std::max(1.0, A.lpNorm<Eigen::Infinity>());
    if (c.opt.removeYaw == 1 || (c.opt.removeYaw < 0 && dead)) remove.push_back(yawCol);
  }
  return remove;
}

// Keeps the other states in lin (A, B, states); records the removed columns' kept rows.
void removeStates(const LinearizeContext& c, const std::vector<int>& remove, const Eigen::MatrixXd& A,
                  const Eigen::MatrixXd& B, LinearModel& lin) {
  const int n = static_cast<int>(lin.states.size());
  std::vector<int> keep;
  for (int j = 0; j < n; ++j)
    if (std::find(remove.begin(), remove.end(), j) == remove.end()) keep.push_back(j);
  for (int j : remove) {
    if (c.isCyclicQ(lin.states[j].entry) && !c.opt.computeCyclicColumns) continue;
    Eigen::VectorXd kept(keep.size());
    for (size_t a = 0; a < keep.size(); ++a) kept[a] = A(keep[a], j);
    lin.removedColumns.push_back({lin.states[j].name, kept});
  }
  for (int j : remove) {
    Eigen::RowVectorXd row(keep.size());
    for (size_t a = 0; a < keep.size(); ++a) row[a] = A(j, keep[a]);
    lin.removedRows.push_back({lin.states[j].name, row});
  }
  lin.A.resize(keep.size(), keep.size());
  lin.B.resize(keep.size(), B.cols());
  std::vector<LinearState> kept;
  for (size_t a = 0; a < keep.size(); ++a) {
    kept.push_back(lin.states[keep[a]]);
    lin.B.row(a) = B.row(keep[a]);
    for (size_t b = 0; b < keep.size(); ++b) lin.A(a, b) = A(keep[a], keep[b]);
  }
  lin.states = kept;
}

// The blocks of A that exact zeros decouple (connected components of A(i, j) != 0 or A(j, i) != 0),
// each in ascending state order; one block when A is irreducible.
std::vector<std::vector<int>> findDecoupledBlocks(const Eigen::MatrixXd& A) {
  const int n = static_cast<int>(A.rows());
  std::vector<int> block(n, -1);
  std::vector<std::vector<int>> blocks;
  for (int s = 0; s < n; ++s) {
    if (block[s] >= 0) continue;
    blocks.emplace_back();
    std::vector<int> stack{s};
    block[s] = static_cast<int>(blocks.size()) - 1;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      blocks.back().push_back(i);
      for (int j = 0; j < n; ++j)
        if (block[j] < 0 && (A(i, j) != 0 || A(j, i) != 0)) block[j] = block[s], stack.push_back(j);
    }
    std::sort(blocks.back().begin(), blocks.back().end());
  }
  return blocks;
}

// Eigenvalues and unit eigenvectors; a block-diagonal A (after a permutation: sweeps of laterally
// symmetric vehicles, whose grouped columns hold exact zeros off the pattern) block by block, the
// eigenvectors zero outside their block (the same eigensystem at a fraction of the O(n^3) cost).
void solveEigen(LinearModel& lin) {
  const Eigen::Index n = lin.A.rows();
  const auto blocks = findDecoupledBlocks(lin.A);
  lin.eigenvalues.resize(n);
  lin.eigenvectors = Eigen::MatrixXcd::Zero(n, n);
  Eigen::Index k = 0;
  for (const auto& b : blocks) {
    const Eigen::Index m = static_cast<Eigen::Index>(b.size());
    Eigen::MatrixXd sub(m, m);
    for (Eigen::Index i = 0; i < m; ++i)
      for (Eigen::Index j = 0; j < m; ++j) sub(i, j) = lin.A(b[i], b[j]);
    const Eigen::EigenSolver<Eigen::MatrixXd> es(sub);
    const Eigen::MatrixXcd vectors = es.eigenvectors();  // assembled on each call
    for (Eigen::Index c = 0; c < m; ++c, ++k) {
      lin.eigenvalues[k] = es.eigenvalues()[c];
      for (Eigen::Index i = 0; i < m; ++i) lin.eigenvectors(b[i], k) = vectors(i, c);
      lin.eigenvectors.col(k).normalize();
    }
  }
}

}  // namespace

namespace {

// Relative cost of one evaluation, by the lowest stage the group's perturbation invalidates (q:
// Position, u: Velocity, z: Dynamics; measured 12.5, 7.2 and 4.3 us on the enduro at 20 m/s, 17.2,
// 8.3 and 5.5 us with the four issue-10 extensions).
double calcEvaluationCost(const ColumnGrouping& g, const std::vector<int>& group) {
  double c = 0;
  for (int j : group) c = std::max(c, g.slots[j] == Slot::Q ? 2.0 : g.slots[j] == Slot::U ? 1.0 : 0.6);
  return c;
}

// Groups for one-evaluation lateral columns: lateral and in-plane columns grouped apart, then a lateral
// group a (one evaluation alone) merged with an in-plane group b (two) where that saves
// c(a) + 2 c(b) - 2 max(c(a), c(b)), largest savings first.
std::vector<std::vector<int>> planMirrorGroups(const ColumnGrouping& g) {
  const auto lateral = colourColumns(g.pattern, orderBySlot(g.slots, g.mirror, -1));
  const auto inPlane = colourColumns(g.pattern, orderBySlot(g.slots, g.mirror, 1));
  struct Merge {
    double saving;
    size_t a, b;
  };
  std::vector<Merge> merges;
  for (size_t a = 0; a < lateral.size(); ++a)
    for (size_t b = 0; b < inPlane.size(); ++b) {
      const double ca = calcEvaluationCost(g, lateral[a]), cb = calcEvaluationCost(g, inPlane[b]);
      if (const double s = ca + 2 * cb - 2 * std::max(ca, cb); s > 0) merges.push_back({s, a, b});
    }
  std::stable_sort(merges.begin(), merges.end(), [](const Merge& x, const Merge& y) { return x.saving > y.saving; });
  std::vector<bool> usedA(lateral.size(), false), usedB(inPlane.size(), false);
  std::vector<std::vector<int>> out;
  for (const Merge& m : merges) {
    if (usedA[m.a] || usedB[m.b]) continue;
    usedA[m.a] = usedB[m.b] = true;
    out.push_back(lateral[m.a]);
    out.back().insert(out.back().end(), inPlane[m.b].begin(), inPlane[m.b].end());
  }
  for (size_t a = 0; a < lateral.size(); ++a)
    if (!usedA[a]) out.push_back(lateral[a]);
  for (size_t b = 0; b < inPlane.size(); ++b)
    if (!usedB[b]) out.push_back(inPlane[b]);
  return out;
}

}  // namespace

bool checkMirrorSymmetry(const VehicleModel& model, TrimResult& trim, const LinearizeOptions& opt,
                         ColumnGrouping& g, double tolerance, double* defect) {
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

LinearModel linearizeInPlace(const VehicleModel& model, TrimResult& trim, const LinearizeOptions& opt) {
  const LinearizeContext c(model, trim.state, opt, trim.turn);
  const ConstraintJacobian cj = calcConstraintJacobian(c);
  const TangentSpace tangent = chooseTangentSpace(c, cj);
  LinearModel lin;
  lin.speed = trim.speed;
  lin.roll = trim.turn ? trim.roll : 0.0;
  lin.headingFrame = trim.turn;
  lin.states = listIndependentStates(c, tangent);
  const Eigen::MatrixXd A = differenceColumns(c, cj, tangent, lin);
  lin.inputNames = VehicleModel::getInputNames();
  const Eigen::MatrixXd B = differenceInputColumns(c, lin);
  removeStates(c, chooseRemovedStates(c, lin, A), A, B, lin);
  solveEigen(lin);
  return lin;
}

}  // namespace motostab::analysis
