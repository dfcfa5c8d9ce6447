// Linearisation about a trim: constraint tangent space, differenced A and B, state removal, eigensystem.
#include "analysis/linearize.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "analysis/linearize_detail.h"
#include "analysis/modes.h"
#include "io/result_error.h"

namespace motostab::analysis {

using vehicle::CoordinateIndices;
using vehicle::VehicleModel;
using vehicle::kNumInputs;

using vehicle::Input;

int LinearModel::findState(const std::string& name) const {
  for (size_t i = 0; i < states.size(); ++i)
    if (states[i].name == name) return static_cast<int>(i);
  return -1;
}

int LinearModel::findState(vehicle::StateRole role, vehicle::StateKind kind) const {
  for (size_t i = 0; i < states.size(); ++i)
    if (states[i].role == role && states[i].getKind() == kind) return static_cast<int>(i);
  return -1;
}

int LinearModel::findState(const StateEntry& e) const {
  for (size_t i = 0; i < states.size(); ++i)
    if (states[i].entry.slot == e.slot && states[i].entry.index == e.index) return static_cast<int>(i);
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

}  // namespace

LinearModel linearize(const VehicleModel& model, const TrimResult& trim, const LinearizeOptions& opt) {
  TrimResult work;
  work.speed = trim.speed;
  work.turn = trim.turn;
  work.roll = trim.roll;
  work.state = trim.state;
  return linearizeInPlace(model, work, opt);
}

namespace detail {
namespace {

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
      throw io::ResultError("linearize: constraints are redundant or singular at the trim");
  }
  for (int q : t.depQ) t.depCols.push_back(q);
  for (int u : t.depU) t.depCols.push_back(nq + u);
  Eigen::MatrixXd Gdep(m, t.depCols.size());
  for (size_t k = 0; k < t.depCols.size(); ++k) Gdep.col(k) = cj.G.col(t.depCols[k]);
  if (m > 0) t.GdepLU = Gdep.partialPivLu();
  return t;
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

}  // namespace

// Independent states in model order: q, u, z, with their names and roles.
std::vector<LinearState> listIndependentStates(const LinearizeContext& c, const TangentSpace& t) {
  std::vector<LinearState> states;
  auto add = [&](const vehicle::StateInfo& info, Slot slot, int i) { states.push_back({info.name, {slot, i}, info.role, info.wheel}); };
  for (int i = 0; i < c.nq; ++i)
    if (std::find(t.depQ.begin(), t.depQ.end(), i) == t.depQ.end()) add(c.model.getQStates()[i], Slot::Q, i);
  for (int i = 0; i < c.nu; ++i)
    if (std::find(t.depU.begin(), t.depU.end(), i) == t.depU.end()) add(c.model.getUStates()[i], Slot::U, i);
  for (int i = 0; i < c.nz; ++i) add(c.model.getZStates()[i], Slot::Z, i);
  return states;
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

namespace {

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

// The mass matrix over the rate states of lin: T^T M T, the columns of T the tangent-space directions
// of those rates (their dependent rates moved to keep the velocity constraints) in u.
Eigen::MatrixXd calcRateMassMatrix(const LinearizeContext& c, const ConstraintJacobian& cj, const TangentSpace& t,
                                   const LinearModel& lin) {
  c.model.getSystem().realize(c.s, SimTK::Stage::Position);
  SimTK::Matrix M;
  c.model.getMatter().calcM(c.s, M);
  std::vector<int> rates;
  for (size_t i = 0; i < lin.states.size(); ++i)
    if (lin.states[i].entry.slot == Slot::U) rates.push_back(static_cast<int>(i));
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(c.nu, rates.size());
  for (size_t j = 0; j < rates.size(); ++j) {
    Direction dir;
    addDirection(c, cj, t, lin.states[rates[j]].entry, 1.0, dir);
    for (const auto& [e, v] : dir)
      if (e.slot == Slot::U) T(e.index, j) += v;
  }
  Eigen::MatrixXd Me(c.nu, c.nu);
  for (int i = 0; i < c.nu; ++i)
    for (int j = 0; j < c.nu; ++j) Me(i, j) = M(i, j);
  return T.transpose() * Me * T;
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
}  // namespace detail

LinearModel linearizeInPlace(const VehicleModel& model, TrimResult& trim, const LinearizeOptions& opt) {
  using namespace detail;
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
  if (opt.labelModes) {
    lin.massMatrix = calcRateMassMatrix(c, cj, tangent, lin);
    lin.labels = labelModes(lin);
  }
  return lin;
}

}  // namespace motostab::analysis
