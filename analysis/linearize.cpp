#include "analysis/linearize.h"

#include <Eigen/Eigenvalues>
#include <algorithm>

namespace motostab {

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

}  // namespace

Eigen::MatrixXd calcTrimJacobian(const VehicleModel& model, const LinearModel& lin, const Eigen::MatrixXd& previous) {
  const SimTK::State& s = model.getDefaultState();
  const bool hasB = lin.B.cols() == kNumInputs;
  if (s.getNQErr() + s.getNUErr() > 0) return {};
  std::vector<int> rows;  // residual rows: every udot, then every zdot
  for (const auto* names : {&model.getUNames(), &model.getZNames()})
    for (const auto& name : *names) {
      rows.push_back(lin.findState(name));
      if (rows.back() < 0) return {};
    }
  const auto unknowns = getTrimUnknowns(model);
  const Eigen::Index nr = static_cast<Eigen::Index>(rows.size()), nx = static_cast<Eigen::Index>(unknowns.size());
  if (!hasB && (previous.rows() != nr || previous.cols() != nx)) return {};
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(nr, nx);
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
  const int n = static_cast<int>(first.states.size());
  for (const LinearModel* m : samples) {
    if (static_cast<int>(m->states.size()) != n || m->A.rows() != n) return {};
    for (int i = 0; i < n; ++i)
      if (m->states[i].name != first.states[i].name) return {};
  }
  for (const auto& st : first.states) g.states.push_back(st.name);
  g.pattern.setConstant(n, n, false);
  for (const LinearModel* m : samples)
    for (int i = 0; i < n; ++i) {
      const double rowMax = m->A.row(i).cwiseAbs().maxCoeff();
      for (int j = 0; j < n; ++j) g.pattern(i, j) = g.pattern(i, j) || std::abs(m->A(i, j)) > tolerance * rowMax;
    }
  std::vector<int> order;  // coordinates first, then rates, then auxiliary states
  for (Slot slot : {Slot::Q, Slot::U, Slot::Z})
    for (int j = 0; j < n; ++j)
      if (first.states[j].entry.slot == slot) order.push_back(j);
  std::vector<std::vector<int>> groups;
  std::vector<Eigen::Matrix<bool, Eigen::Dynamic, 1>> rows;  // union of the rows each group touches
  for (int j : order) {
    size_t k = 0;
    while (k < groups.size() && (rows[k].array() && g.pattern.col(j).array()).any()) ++k;
    if (k == groups.size()) groups.emplace_back(), rows.emplace_back(Eigen::Matrix<bool, Eigen::Dynamic, 1>::Constant(n, false));
    groups[k].push_back(j);
    rows[k] = rows[k].array() || g.pattern.col(j).array();
  }
  for (auto& grp : groups)
    if (grp.size() > 1) g.groups.push_back(grp);
  return g;
}

LinearModel linearize(const VehicleModel& model, const TrimResult& trim, const LinearizeOptions& opt) {
  TrimResult work;
  work.speed = trim.speed;
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
  const std::vector<int> cyclic;
  LinearizeContext(const VehicleModel& m, SimTK::State& state, const LinearizeOptions& o)
      : model(m), fn(m), s(state), opt(o), nq(m.getNumQ()), nu(m.getNumU()), nz(m.getNumZ()), cyclic(m.getCyclicQ()) {}
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
void addDirection(const LinearizeContext& c, const ConstraintJacobian& cj, const TangentSpace& t, const StateEntry& e,
                  double scale, Direction& dir) {
  dir.push_back({e, scale});
  if (e.slot == Slot::Z || cj.m == 0) return;
  const Eigen::VectorXd dDep = t.GdepLU.solve(-cj.G.col(c.rowOf(e)));
  for (size_t k = 0; k < t.depCols.size(); ++k) {
    const int col = t.depCols[k];
    dir.push_back({{col < c.nq ? Slot::Q : Slot::U, col < c.nq ? col : col - c.nq}, scale * dDep[k]});
  }
}

// Columns of A evaluated together (opt.grouping); marks them in `done`.
void differenceGroupedColumns(const LinearizeContext& c, const ConstraintJacobian& cj, const TangentSpace& t,
                              const LinearModel& lin, Eigen::MatrixXd& A, std::vector<bool>& done) {
  const ColumnGrouping& grouping = c.opt.grouping;
  auto yDot = [&](const SimTK::State& st, Eigen::VectorXd& out) { c.fn.calcYDot(st, out); };
  std::vector<int> linearIndexOf;  // grouping's state index -> lin.states index
  for (const auto& name : grouping.states) linearIndexOf.push_back(lin.findState(name));
  const bool grouped = !grouping.groups.empty() &&
                       std::find(linearIndexOf.begin(), linearIndexOf.end(), -1) == linearIndexOf.end();
  if (!grouped) return;
  Eigen::VectorXd col;
  for (const auto& group : grouping.groups) {
    Direction dir;
    for (int g : group) addDirection(c, cj, t, lin.states[linearIndexOf[g]].entry, c.stepFor(lin.states[linearIndexOf[g]].entry), dir);
    c.fn.calcDirectionalDerivative(c.s, dir, 1.0, c.opt.order, yDot, col);  // sum of h_j times column j
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
  auto yDot = [&](const SimTK::State& st, Eigen::VectorXd& out) { c.fn.calcYDot(st, out); };
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
    c.fn.calcDirectionalDerivative(c.s, dir, c.stepFor(e), c.opt.order, yDot, col);
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
    if (e.index == c.model.getIndices().yaw) yawCol = j;
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

void solveEigen(LinearModel& lin) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(lin.A);
  lin.eigenvalues = es.eigenvalues();
  lin.eigenvectors = es.eigenvectors();
  for (int k = 0; k < lin.eigenvectors.cols(); ++k) lin.eigenvectors.col(k).normalize();
}

}  // namespace

LinearModel linearizeInPlace(const VehicleModel& model, TrimResult& trim, const LinearizeOptions& opt) {
  const LinearizeContext c(model, trim.state, opt);
  const ConstraintJacobian cj = calcConstraintJacobian(c);
  const TangentSpace tangent = chooseTangentSpace(c, cj);
  LinearModel lin;
  lin.speed = trim.speed;
  lin.states = listIndependentStates(c, tangent);
  const Eigen::MatrixXd A = differenceColumns(c, cj, tangent, lin);
  lin.inputNames = VehicleModel::getInputNames();
  const Eigen::MatrixXd B = differenceInputColumns(c, lin);
  removeStates(c, chooseRemovedStates(c, lin, A), A, B, lin);
  solveEigen(lin);
  return lin;
}

}  // namespace motostab
