#include "analysis/linearize.h"

#include <Eigen/Eigenvalues>
#include <algorithm>

namespace motostab {

int LinearModel::findState(const std::string& name) const {
  for (size_t i = 0; i < states.size(); ++i)
    if (states[i].name == name) return static_cast<int>(i);
  return -1;
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

LinearModel linearizeInPlace(const VehicleModel& model, TrimResult& trim, const LinearizeOptions& opt) {
  const StateFunction fn(model);
  const CoordinateIndices& ix = model.getIndices();
  SimTK::State& s = trim.state;
  const int nq = model.getNumQ(), nu = model.getNumU(), nz = model.getNumZ();
  auto yDot = [&](const SimTK::State& st, Eigen::VectorXd& out) { fn.calcYDot(st, out); };
  auto errors = [&](const SimTK::State& st, Eigen::VectorXd& out) { fn.calcConstraintErrors(st, out); };
  auto stepFor = [&](const StateEntry& e) { return opt.step * std::max(1.0, std::abs(fn.get(s, e))); };

  // Constraint Jacobian G = d[qerr; uerr]/d[q; u].
  Eigen::VectorXd err0, col;
  fn.calcConstraintErrors(s, err0);
  const int m = static_cast<int>(err0.size());
  const int mp = s.getNQErr();
  Eigen::MatrixXd G(m, nq + nu);
  const auto cyclic = model.getCyclicQ();
  auto isCyclicQ = [&](const StateEntry& e) {
    return e.slot == Slot::Q && std::find(cyclic.begin(), cyclic.end(), e.index) != cyclic.end();
  };
  for (int j = 0; j < nq + nu && m > 0; ++j) {  // no constraints: G has no rows
    const StateEntry e{j < nq ? Slot::Q : Slot::U, j < nq ? j : j - nq};
    if (isCyclicQ(e) && !opt.computeCyclicColumns) {
      G.col(j).setZero();
      continue;
    }
    if (e.slot == Slot::U) continue;  // below, exactly
    fn.calcDirectionalDerivative(s, {{e, 1.0}}, stepFor(e), opt.order, errors, col);
    G.col(j) = col;
  }
  // The constraint errors are affine in u: one-sided unit differences are exact.
  for (int j = 0; j < nu && m > 0; ++j) {
    const StateEntry e{Slot::U, j};
    const double base = fn.get(s, e);
    fn.set(s, e, base + 1.0);
    fn.calcConstraintErrors(s, col);
    fn.set(s, e, base);
    G.col(nq + j) = col - err0;
  }

  // Dependent coordinates: heights and pitch first, then the rates that the contact fixes.
  std::vector<int> depQ, depU;
  if (m > 0) {
    depQ = chooseDependentColumns(G.topLeftCorner(mp, nq), withPriority({ix.height, ix.pitch}, nq));
    depU = chooseDependentColumns(G.bottomRightCorner(m - mp, nu),
                           withPriority({ix.height, ix.pitch, ix.rearSpin, ix.frontSpin, ix.y, ix.yaw}, nu));
    if (static_cast<int>(depQ.size()) != mp || static_cast<int>(depU.size()) != m - mp)
      throw std::runtime_error("linearize: constraints are redundant or singular at the trim");
  }
  std::vector<int> depCols;
  for (int q : depQ) depCols.push_back(q);
  for (int u : depU) depCols.push_back(nq + u);
  Eigen::MatrixXd Gdep(m, depCols.size());
  for (size_t k = 0; k < depCols.size(); ++k) Gdep.col(k) = G.col(depCols[k]);
  const Eigen::PartialPivLU<Eigen::MatrixXd> GdepLU = m > 0 ? Gdep.partialPivLu() : Eigen::PartialPivLU<Eigen::MatrixXd>();

  // Independent states in model order: q, u, z.
  LinearModel lin;
  lin.speed = trim.speed;
  for (int i = 0; i < nq; ++i)
    if (std::find(depQ.begin(), depQ.end(), i) == depQ.end()) lin.states.push_back({model.getQNames()[i], {Slot::Q, i}});
  for (int i = 0; i < nu; ++i)
    if (std::find(depU.begin(), depU.end(), i) == depU.end()) lin.states.push_back({model.getUNames()[i], {Slot::U, i}});
  for (int i = 0; i < nz; ++i) lin.states.push_back({model.getZNames()[i], {Slot::Z, i}});
  const int n = static_cast<int>(lin.states.size());
  auto rowOf = [&](const StateEntry& e) { return e.slot == Slot::Q ? e.index : e.slot == Slot::U ? nq + e.index : nq + nu + e.index; };

  // Columns: directional derivatives along the tangent-space basis vectors, grouped ones together.
  auto addDirection = [&](int j, double scale, std::vector<std::pair<StateEntry, double>>& dir) {
    const StateEntry& e = lin.states[j].entry;
    dir.push_back({e, scale});
    if (e.slot == Slot::Z || m == 0) return;
    const Eigen::VectorXd dDep = GdepLU.solve(-G.col(rowOf(e)));
    for (size_t k = 0; k < depCols.size(); ++k) {
      const int c = depCols[k];
      dir.push_back({{c < nq ? Slot::Q : Slot::U, c < nq ? c : c - nq}, scale * dDep[k]});
    }
  };
  Eigen::MatrixXd A(n, n);
  std::vector<bool> done(n, false);
  std::vector<int> linearIndexOf;  // grouping's state index -> lin.states index
  for (const auto& name : opt.grouping.states) linearIndexOf.push_back(lin.findState(name));
  const bool grouped = !opt.grouping.groups.empty() &&
                       std::find(linearIndexOf.begin(), linearIndexOf.end(), -1) == linearIndexOf.end();
  for (const auto& group : grouped ? opt.grouping.groups : std::vector<std::vector<int>>{}) {
    std::vector<std::pair<StateEntry, double>> dir;
    for (int g : group) addDirection(linearIndexOf[g], stepFor(lin.states[linearIndexOf[g]].entry), dir);
    fn.calcDirectionalDerivative(s, dir, 1.0, opt.order, yDot, col);  // sum of h_j times column j
    for (int g : group) {
      const int j = linearIndexOf[g];
      const double h = stepFor(lin.states[j].entry);
      A.col(j).setZero();
      for (size_t r = 0; r < linearIndexOf.size(); ++r)
        if (opt.grouping.pattern(r, g)) A(linearIndexOf[r], j) = col[rowOf(lin.states[linearIndexOf[r]].entry)] / h;
      done[j] = true;
    }
  }
  for (int j = 0; j < n; ++j) {
    if (done[j]) continue;
    const StateEntry& e = lin.states[j].entry;
    const bool knownDeadYaw = e.slot == Slot::Q && e.index == ix.yaw && opt.removeYaw == 1;
    if ((isCyclicQ(e) && !opt.computeCyclicColumns) || knownDeadYaw) {
      A.col(j).setZero();
      continue;
    }
    std::vector<std::pair<StateEntry, double>> dir;
    addDirection(j, 1.0, dir);
    fn.calcDirectionalDerivative(s, dir, stepFor(e), opt.order, yDot, col);
    for (int i = 0; i < n; ++i) A(i, j) = col[rowOf(lin.states[i].entry)];
  }
  lin.inputNames = VehicleModel::getInputNames();
  // Accelerations are affine in the generalized input forces: a one-sided unit difference is exact.
  Eigen::MatrixXd B(n, opt.computeB ? kNumInputs : 0);
  Eigen::VectorXd y0, y1;
  if (opt.computeB) fn.calcYDot(s, y0);
  for (int k = 0; k < B.cols(); ++k) {
    const StateEntry in{Slot::Input, k};
    const double base = fn.get(s, in);
    fn.set(s, in, base + 1.0);
    fn.calcYDot(s, y1);
    fn.set(s, in, base);
    for (int i = 0; i < n; ++i) B(i, k) = y1[rowOf(lin.states[i].entry)] - y0[rowOf(lin.states[i].entry)];
  }

  // Remove cyclic coordinates; yaw too when no kept row depends on it (rolling constraints).
  std::vector<int> remove;
  int yawCol = -1;
  for (int j = 0; j < n; ++j) {
    const StateEntry& e = lin.states[j].entry;
    if (e.slot != Slot::Q) continue;
    if (isCyclicQ(e)) remove.push_back(j);
    if (e.index == ix.yaw) yawCol = j;
  }
  if (yawCol >= 0) {
    double yawInfluence = 0;
    for (int i = 0; i < n; ++i)
      if (std::find(remove.begin(), remove.end(), i) == remove.end())
        yawInfluence = std::max(yawInfluence, std::abs(A(i, yawCol)));
    const bool dead = yawInfluence < opt.zeroColumnTolerance * std::max(1.0, A.lpNorm<Eigen::Infinity>());
    if (opt.removeYaw == 1 || (opt.removeYaw < 0 && dead)) remove.push_back(yawCol);
  }
  std::vector<int> keep;
  for (int j = 0; j < n; ++j)
    if (std::find(remove.begin(), remove.end(), j) == remove.end()) keep.push_back(j);
  for (int j : remove) {
    if (isCyclicQ(lin.states[j].entry) && !opt.computeCyclicColumns) continue;
    Eigen::VectorXd kept(keep.size());
    for (size_t a = 0; a < keep.size(); ++a) kept[a] = A(keep[a], j);
    lin.removedColumns.push_back({lin.states[j].name, kept});
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

  Eigen::EigenSolver<Eigen::MatrixXd> es(lin.A);
  lin.eigenvalues = es.eigenvalues();
  lin.eigenvectors = es.eigenvectors();
  for (int k = 0; k < lin.eigenvectors.cols(); ++k) lin.eigenvectors.col(k).normalize();
  return lin;
}

}  // namespace motostab
