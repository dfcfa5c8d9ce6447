#include "diagnosis/free_response.h"

#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

namespace motostab::diagnosis {

using analysis::LinearModel;
using io::InputError;

namespace {

// The state a quantity reads: role and kind.
std::pair<vehicle::StateRole, vehicle::StateKind> getState(Quantity q) {
  using vehicle::StateKind;
  using vehicle::StateRole;
  switch (q) {
    case Quantity::RollAngle: return {StateRole::Roll, StateKind::Coordinate};
    case Quantity::RollRate: return {StateRole::Roll, StateKind::Rate};
    case Quantity::SteerAngle: return {StateRole::Steer, StateKind::Coordinate};
    case Quantity::SteerRate: return {StateRole::Steer, StateKind::Rate};
    case Quantity::YawRate: break;
  }
  return {StateRole::Yaw, StateKind::Rate};
}

// Rows c_j of the outputs: signal j reads state getState(quantity); a yaw rate that is no state
// (a model on rolling constraints, where it is a dependent speed) is the linearised rate of the yaw
// coordinate, d(yaw)/dt = c x (LinearModel::getRateRow; for the Whipple bicycle
// (v delta + c delta') cos(lambda) / w, Meijaard et al. 2007).
Eigen::MatrixXd calcOutputRows(const LinearModel& lin, const ResponseRun& run) {
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(static_cast<int>(run.signals.size()), lin.A.rows());
  for (size_t j = 0; j < run.signals.size(); ++j) {
    const Quantity q = run.signals[j].quantity;
    const auto [role, kind] = getState(q);
    const int k = lin.findState(role, kind);
    const Eigen::RowVectorXd yaw = q == Quantity::YawRate && k < 0 ? lin.getRateRow("yaw") : Eigen::RowVectorXd();
    if (k < 0 && yaw.size() != lin.A.cols())
      throw InputError(run.where, "quantity " + getQuantityName(q) + " is not a state of this model's linearisation");
    if (k >= 0) C(static_cast<int>(j), k) = 1;
    else C.row(static_cast<int>(j)) = yaw;
  }
  return C;
}

// basis[j](i, :) = c_j exp(A (t_i - t0)) = c_j V diag(exp(lambda (t_i - t0))) V^-1 from the model's
// eigen-decomposition; by exponentials of A dt (Pade, Eigen's MatrixFunctions) when V is ill-conditioned.
std::vector<Eigen::MatrixXd> calcFreeResponseBasis(const LinearModel& lin, const ResponseRun& run) {
  const Eigen::MatrixXd C = calcOutputRows(lin, run);
  const int n = static_cast<int>(lin.A.rows()), m = static_cast<int>(run.time.size());
  std::vector<Eigen::MatrixXd> basis(run.signals.size(), Eigen::MatrixXd(m, n));
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(lin.eigenvectors);
  const Eigen::MatrixXcd Vinv = lu.inverse();
  const bool modal = lin.eigenvectors.rows() == n && Vinv.allFinite() &&
                     lin.eigenvectors.norm() * Vinv.norm() < 1e8;
  const Eigen::MatrixXcd CV = C * lin.eigenvectors;
  Eigen::MatrixXd E = Eigen::MatrixXd::Identity(n, n), step;
  double lastDt = -1;
  for (int i = 0; i < m; ++i) {
    Eigen::MatrixXd row;
    if (modal) {
      const Eigen::VectorXcd e = (lin.eigenvalues * (run.time[i] - run.time[0])).array().exp();
      row = ((CV * e.asDiagonal()) * Vinv).real();
    } else {
      if (i > 0) {
        const double dt = run.time[i] - run.time[i - 1];
        if (std::abs(dt - lastDt) > 1e-12 * std::max(1.0, dt)) step = (lin.A * dt).exp();
        lastDt = dt;
        E = step * E;
      }
      row = C * E;
    }
    for (size_t j = 0; j < basis.size(); ++j) basis[j].row(i) = row.row(static_cast<int>(j));
  }
  return basis;
}

// A(v) by Lagrange interpolation through the models' speeds (2 or 3 of them).
Eigen::MatrixXd interpolateA(const std::vector<LinearModel>& models, double v) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(models[0].A.rows(), models[0].A.cols());
  for (size_t i = 0; i < models.size(); ++i) {
    double w = 1;
    for (size_t j = 0; j < models.size(); ++j)
      if (j != i) w *= (v - models[j].speed) / (models[i].speed - models[j].speed);
    A += w * models[i].A;
  }
  return A;
}

// basis[j](i, :) = c_j Phi(t_i), Phi(t_i) = exp(A(v_i') dt_i) Phi(t_{i-1}), Phi(t0) = I: the
// piecewise-frozen transition along the speed trace (v_i': the trace at the interval's middle).
std::vector<Eigen::MatrixXd> calcVaryingSpeedBasis(const std::vector<LinearModel>& models, const ResponseRun& run) {
  const Eigen::MatrixXd C = calcOutputRows(models[0], run);
  const int n = static_cast<int>(models[0].A.rows()), m = static_cast<int>(run.time.size());
  for (const auto& lin : models)
    if (lin.A.rows() != n || lin.states.size() != models[0].states.size())
      throw std::logic_error("fitFreeResponse: the linear models along a speed trace differ in their states");
  std::vector<Eigen::MatrixXd> basis(run.signals.size(), Eigen::MatrixXd(m, n));
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i < m; ++i) {
    if (i > 0) {
      const double v = 0.5 * (run.speeds[i] + run.speeds[i - 1]), dt = run.time[i] - run.time[i - 1];
      const Eigen::MatrixXd step = (interpolateA(models, v) * dt).exp();
      Phi = step * Phi;
    }
    const Eigen::MatrixXd row = C * Phi;
    for (size_t j = 0; j < basis.size(); ++j) basis[j].row(i) = row.row(static_cast<int>(j));
  }
  return basis;
}

struct BilinearFit {
  Eigen::VectorXd x0;
  std::vector<double> gains, offsets;
  double cost = 0;
};

// One run's least-squares system per signal, each side prewhitened by the signal's AR noise
// (noise_model.h) and divided by its innovation sigma: basis W B_j / s_j, offset column W 1 / s_j,
// data W y_j / s_j. Whitening is linear, so W (g B x0 + o 1 - y) = g (W B) x0 + o (W 1) - W y: the
// fit of x0, offsets and gains is generalised least squares (white noise: W = identity).
struct WeightedRun {
  std::vector<Eigen::MatrixXd> basis;
  std::vector<Eigen::VectorXd> ones, y;
};

Eigen::VectorXd whitenColumn(const ArNoise* ar, const Eigen::VectorXd& v) {
  if (!ar || ar->getOrder() == 0) return v;
  Eigen::VectorXd w(v.size());
  whitenSeries(*ar, v.data(), w.data(), static_cast<int>(v.size()));
  return w;
}

WeightedRun makeWeightedRun(const std::vector<Eigen::MatrixXd>& basis, const ResponseRun& run, const std::vector<double>& sigma,
                            const std::vector<ArNoise>& noise) {
  WeightedRun w;
  for (size_t j = 0; j < basis.size(); ++j) {
    const ArNoise* ar = j < noise.size() ? &noise[j] : nullptr;
    const double s = ar ? sigma[j] / ar->calcMarginalFactor() : sigma[j];  // innovation sigma
    const int m = static_cast<int>(basis[j].rows());
    Eigen::MatrixXd b(m, basis[j].cols());
    for (int c = 0; c < b.cols(); ++c) b.col(c) = whitenColumn(ar, basis[j].col(c)) / s;
    w.basis.push_back(b);
    w.ones.push_back(whitenColumn(ar, Eigen::VectorXd::Ones(m)) / s);
    w.y.push_back(whitenColumn(ar, Eigen::Map<const Eigen::VectorXd>(run.signals[j].values.data(), m)) / s);
  }
  return w;
}

double calcCost(const WeightedRun& w, BilinearFit& f) {
  f.cost = 0;
  for (size_t j = 0; j < w.basis.size(); ++j)
    f.cost += (f.gains[j] * (w.basis[j] * f.x0) + f.offsets[j] * w.ones[j] - w.y[j]).squaredNorm();
  return f.cost;
}

// x0 and offsets for fixed gains: one weighted least-squares problem (minimum norm: unobservable
// directions of x0 stay zero).
void solveStateAndOffsets(const WeightedRun& w, BilinearFit& f) {
  const int n = static_cast<int>(w.basis[0].cols()), ns = static_cast<int>(w.basis.size());
  const int m = static_cast<int>(w.basis[0].rows());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(m * ns, n + ns);
  Eigen::VectorXd y(m * ns);
  for (int j = 0; j < ns; ++j) {
    M.block(j * m, 0, m, n) = f.gains[j] * w.basis[j];
    M.block(j * m, n + j, m, 1) = w.ones[j];
    y.segment(j * m, m) = w.y[j];
  }
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(M);
  cod.setThreshold(1e-10);
  const Eigen::VectorXd s = cod.solve(y);
  f.x0 = s.head(n);
  for (int j = 0; j < ns; ++j) f.offsets[j] = s(n + j);
}

// Gain and offset of signal j for fixed x0.
void solveGain(const WeightedRun& w, BilinearFit& f, size_t j) {
  Eigen::MatrixXd M(w.y[j].size(), 2);
  M.col(0) = w.basis[j] * f.x0;
  M.col(1) = w.ones[j];
  const Eigen::VectorXd s = M.colPivHouseholderQr().solve(w.y[j]);
  f.gains[j] = s(0);
  f.offsets[j] = s(1);
}

double calcVaf(const std::vector<double>& y, const std::vector<double>& yhat) {
  double my = 0, mr = 0;
  for (size_t i = 0; i < y.size(); ++i) {
    my += y[i] / y.size();
    mr += (y[i] - yhat[i]) / y.size();
  }
  double vy = 0, vr = 0;
  for (size_t i = 0; i < y.size(); ++i) {
    vy += (y[i] - my) * (y[i] - my);
    vr += (y[i] - yhat[i] - mr) * (y[i] - yhat[i] - mr);
  }
  return vy > 0 ? 100.0 * (1.0 - vr / vy) : 0.0;
}

// The bilinear fit of x0, offsets and free gains to the run for the given basis.
ResponseFit fitBasis(const std::vector<Eigen::MatrixXd>& basis, const ResponseRun& run, const std::vector<double>& sigma,
                     const std::vector<ArNoise>& noise) {
  const WeightedRun w = makeWeightedRun(basis, run, sigma, noise);
  const size_t ns = run.signals.size();
  BilinearFit f;
  f.gains.resize(ns);
  f.offsets.assign(ns, 0.0);
  int reference = -1, numFree = 0;  // the free gain held at 1 when no signal is calibrated
  bool anyCalibrated = false;
  for (size_t j = 0; j < ns; ++j) {
    f.gains[j] = run.signals[j].freeScale ? 1.0 : 1.0 / run.signals[j].scale;
    anyCalibrated |= !run.signals[j].freeScale;
    numFree += run.signals[j].freeScale;
    if (run.signals[j].freeScale && reference < 0) reference = static_cast<int>(j);
  }
  if (anyCalibrated) reference = -1;
  double last = HUGE_VAL;
  for (int it = 0; it < 200; ++it) {
    solveStateAndOffsets(w, f);
    for (size_t j = 0; j < ns; ++j)
      if (run.signals[j].freeScale && static_cast<int>(j) != reference) solveGain(w, f, j);
    const double cost = calcCost(w, f);
    if (numFree - (reference >= 0) == 0 || last - cost <= 1e-13 * cost) break;
    last = cost;
  }
  ResponseFit r;
  r.initialState = f.x0;
  r.gains = f.gains;
  r.offsets = f.offsets;
  r.numLinear = static_cast<int>(f.x0.size() + ns) + numFree - (reference >= 0);
  for (size_t j = 0; j < ns; ++j) {
    const Eigen::VectorXd yhat = (f.gains[j] * (basis[j] * f.x0)).array() + f.offsets[j];
    r.predicted.emplace_back(yhat.data(), yhat.data() + yhat.size());
    r.vaf.push_back(calcVaf(run.signals[j].values, r.predicted.back()));
  }
  return r;
}


}  // namespace

ResponseFit fitFreeResponse(const LinearModel& lin, const ResponseRun& run, const std::vector<double>& sigma,
                            const std::vector<ArNoise>& noise) {
  return fitBasis(calcFreeResponseBasis(lin, run), run, sigma, noise);
}

ResponseFit fitFreeResponse(const std::vector<LinearModel>& models, const ResponseRun& run,
                            const std::vector<double>& sigma, const std::vector<ArNoise>& noise) {
  if (models.size() == 1) return fitFreeResponse(models[0], run, sigma, noise);
  if (run.speeds.size() != run.time.size())
    throw std::logic_error("fitFreeResponse: several linear models need the run's speed trace");
  return fitBasis(calcVaryingSpeedBasis(models, run), run, sigma, noise);
}

std::vector<double> getTraceSpeeds(const ResponseRun& run) {
  if (run.speeds.empty()) return {run.speed};
  const auto [lo, hi] = std::minmax_element(run.speeds.begin(), run.speeds.end());
  if (*hi - *lo < 1e-9) return {run.speed};
  return {*lo, 0.5 * (*lo + *hi), *hi};
}

}  // namespace motostab::diagnosis
