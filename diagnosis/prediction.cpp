#include "diagnosis/prediction.h"

#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

#include "scenario/scenario.h"
#include "vehicle/vehicle_model.h"

namespace motostab::diagnosis {

using analysis::LinearModel;
using analysis::ModeBranch;
using analysis::SweepOptions;
using analysis::SweepResult;
using analysis::TrimResult;
using analysis::calcColumnGrouping;
using analysis::calcMatchCost;
using analysis::calcTrim;
using analysis::linearizeInPlace;
using analysis::runSweep;
using analysis::trackModes;
using analysis::updTrim;
using io::InputError;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

std::string getStateName(Quantity q) {
  switch (q) {
    case Quantity::RollAngle: return "roll";
    case Quantity::RollRate: return "roll_rate";
    case Quantity::SteerAngle: return "steer";
    case Quantity::SteerRate: return "steer_rate";
    case Quantity::YawRate: return "yaw_rate";
  }
  return "";
}

// Rows c_j of the outputs: signal j reads state getStateName(quantity); a yaw rate that is no state
// (a model on rolling constraints, where it is a dependent speed) is the linearised rate of the yaw
// coordinate, d(yaw)/dt = c x (LinearModel::getRateRow; for the Whipple bicycle
// (v delta + c delta') cos(lambda) / w, Meijaard et al. 2007).
Eigen::MatrixXd calcOutputRows(const LinearModel& lin, const ResponseRun& run) {
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(static_cast<int>(run.signals.size()), lin.A.rows());
  for (size_t j = 0; j < run.signals.size(); ++j) {
    const Quantity q = run.signals[j].quantity;
    const int k = lin.findState(getStateName(q));
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

std::vector<double> makeSortedUnique(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// Accuracy asked of the fast predictions' interpolation (chooseNodes), 1/s per (1 + |lambda| s).
constexpr double kNodeTolerance = 3e-4;

size_t findSpeed(const std::vector<double>& speeds, double v) {
  return std::lower_bound(speeds.begin(), speeds.end(), v) - speeds.begin();
}

// Barycentric interpolation on Chebyshev points of the second kind x_j (weights (-1)^j, halved at the ends).
std::complex<double> interpolate(const std::vector<double>& x, const std::vector<std::complex<double>>& f, double v) {
  std::complex<double> num = 0;
  double den = 0;
  const size_t n = x.size();
  for (size_t j = 0; j < n; ++j) {
    if (v == x[j]) return f[j];
    const double w = ((j % 2) ? -1.0 : 1.0) * ((j == 0 || j + 1 == n) ? 0.5 : 1.0) / (v - x[j]);
    num += w * f[j];
    den += w;
  }
  return num / den;
}

}  // namespace

ResponseFit fitFreeResponse(const LinearModel& lin, const ResponseRun& run, const std::vector<double>& sigma,
                            const std::vector<ArNoise>& noise) {
  const std::vector<Eigen::MatrixXd> basis = calcFreeResponseBasis(lin, run);
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

std::vector<double> getEvaluationSpeeds(const MeasuredEigenvalue& row) {
  if (!row.hasRange || row.speedMax - row.speedMin < 1e-9) return {row.speed};
  const double m = 0.5 * (row.speedMin + row.speedMax), h = 0.5 * (row.speedMax - row.speedMin);
  return {m - h / std::sqrt(3.0), m + h / std::sqrt(3.0)};
}

Predictor::Predictor(std::string scenarioFile, std::vector<std::string> baseOverrides, const MeasuredData& data)
    : scenarioFile_(std::move(scenarioFile)), baseOverrides_(std::move(baseOverrides)), data_(data) {
  for (ControllerGroup& g : splitByController(data)) {
    auto part = std::make_shared<ControllerPart>();
    part->group = std::move(g);
    std::vector<std::string> base = baseOverrides_;
    base.insert(base.end(), part->group.overrides.begin(), part->group.overrides.end());
    part->predictor = std::make_unique<Predictor>(scenarioFile_, base, part->group.data);
    for (double v : part->predictor->speeds_) speeds_.push_back(v);
    parts_.push_back(part);
  }
  if (!parts_.empty()) {
    speeds_ = makeSortedUnique(speeds_);
    reference_ = parts_.front()->predictor->reference_;
    return;
  }
  for (const auto& row : data.eigenvalues)
    for (double v : getEvaluationSpeeds(row)) speeds_.push_back(v);
  for (const auto& run : data.responses) speeds_.push_back(run.speed);
  speeds_ = makeSortedUnique(speeds_);
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto& row : data.eigenvalues)
    for (double v : getEvaluationSpeeds(row))
      if (!row.mode.empty()) lo = std::min(lo, v), hi = std::max(hi, v);
  const Scenario scenario = loadScenario(scenarioFile_, baseOverrides_);
  const VehicleModel model(scenario);
  SweepOptions opt;
  opt.step = std::min(scenario.speeds.step, 0.1);
  opt.start = std::min(scenario.speeds.start, std::floor(speeds_.front() / opt.step) * opt.step);
  opt.stop = std::max(scenario.speeds.stop, std::ceil(speeds_.back() / opt.step) * opt.step);
  opt.threads = 2;
  reference_ = std::make_shared<SweepResult>(runSweep(model, opt));
  if (hi > lo) exactModes_ = findBranchPointModes(lo, hi);
  std::vector<double> others;  // speeds predicted exactly inside the fast predictions
  int labelled = 0;            // evaluations of interpolated rows
  lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto& row : data.eigenvalues)
    for (double v : getEvaluationSpeeds(row)) {
      if (row.mode.empty() || isExactMode(row.mode)) others.push_back(v);
      else lo = std::min(lo, v), hi = std::max(hi, v), ++labelled;
    }
  if (hi > lo) nodes_ = chooseNodes(lo, hi, labelled);
  for (const auto& run : data.responses) others.push_back(run.speed);
  fastSpeeds_ = nodes_;
  fastSpeeds_.insert(fastSpeeds_.end(), others.begin(), others.end());
  fastSpeeds_ = makeSortedUnique(fastSpeeds_);
}

bool Predictor::isExactMode(const std::string& mode) const {
  return std::find(exactModes_.begin(), exactModes_.end(), mode) != exactModes_.end();
}

// Labelled modes of the rows whose base branch is real at some reference speed in [lo, hi] and
// complex at another (e.g. capsize and castor joining into a pair at low speed).
std::vector<std::string> Predictor::findBranchPointModes(double lo, double hi) const {
  const SweepResult& ref = *reference_;
  std::vector<std::string> out;
  for (const auto& row : data_.eigenvalues) {
    if (row.mode.empty() || std::find(out.begin(), out.end(), row.mode) != out.end()) continue;
    const auto b = std::find_if(ref.branches.begin(), ref.branches.end(), [&](const ModeBranch& x) { return x.label == row.mode; });
    if (b == ref.branches.end()) continue;
    bool real = false, complex = false;
    for (size_t k = 0; k < ref.speeds.size(); ++k)
      if (ref.speeds[k] >= lo && ref.speeds[k] <= hi && b->index[k] >= 0)
        (std::abs(b->eigenvalue[k].imag()) > 0 ? complex : real) = true;
    if (real && complex) out.push_back(row.mode);
  }
  return out;
}

// The fewest Chebyshev points (5 to 16) on [lo, hi] whose interpolant reproduces every interpolated
// labelled mode of the base scenario at the reference sweep's speeds in [lo, hi] to kNodeTolerance
// (absolute, 1/s, plus that times |lambda|); none when the rows' own speeds are fewer, 16 when no
// count does (docs/diagnosis.md, Known limits).
std::vector<double> Predictor::chooseNodes(double lo, double hi, int labelled) const {
  const SweepResult& ref = *reference_;
  std::vector<double> nodes;
  for (int n = 5; n <= 16 && n < labelled; ++n) {
    nodes.clear();
    for (int j = n - 1; j >= 0; --j) nodes.push_back(0.5 * (lo + hi) + 0.5 * (hi - lo) * std::cos(M_PI * j / (n - 1)));
    const std::vector<LinearModel> models = calcLinearModels({}, nodes);
    double worst = 0;
    for (const ModeTrack& t : trackModes(models)) {
      if (isExactMode(t.mode)) continue;
      std::vector<std::complex<double>> f;
      for (size_t k = 0; k < models.size() && t.index[k] >= 0; ++k) {
        const auto l = models[k].eigenvalues(t.index[k]);
        f.push_back({l.real(), std::abs(l.imag())});
      }
      const auto b = std::find_if(ref.branches.begin(), ref.branches.end(), [&](const ModeBranch& x) { return x.label == t.mode; });
      if (f.size() != nodes.size() || b == ref.branches.end()) return {};  // the mode is not smooth over the rows
      for (size_t k = 0; k < ref.speeds.size(); ++k) {
        if (ref.speeds[k] < lo || ref.speeds[k] > hi || b->index[k] < 0) continue;
        const std::complex<double> e(b->eigenvalue[k].real(), std::abs(b->eigenvalue[k].imag()));
        worst = std::max(worst, std::abs(interpolate(nodes, f, ref.speeds[k]) - e) / (1 + std::abs(e)));
      }
    }
    if (worst <= kNodeTolerance) return nodes;
  }
  return nodes.size() >= 5 ? nodes : std::vector<double>();
}

// The sweep's trims and linearisations (warm-started in increasing speed, columns grouped after the
// first two speeds as runSweep groups them).
std::vector<LinearModel> Predictor::calcLinearModels(const std::vector<std::string>& overrides,
                                                     const std::vector<double>& speeds) const {
  std::vector<std::string> all = baseOverrides_;
  all.insert(all.end(), overrides.begin(), overrides.end());
  const Scenario scenario = loadScenario(scenarioFile_, all);
  const VehicleModel model(scenario);
  SweepOptions sweep;
  TrimResult trim = calcTrim(model, speeds.front(), sweep.trim);
  std::vector<LinearModel> out;
  for (size_t i = 0; i < speeds.size(); ++i) {
    if (i > 0) updTrim(model, speeds[i], sweep.trim, trim);
    out.push_back(linearizeInPlace(model, trim, sweep.linearize));
    if (i == 1 && sweep.groupColumns) {
      sweep.linearize.removeYaw = out[0].findState("yaw") < 0 ? 1 : 0;
      sweep.linearize.grouping = calcColumnGrouping({&out[0], &out[1]});
    }
  }
  return out;
}

// Cost of each eigenvalue of `lin` as mode `mode`: how well it continues the base sweep's branch at
// the nearest sweep speed plus, when given, the mode's eigenvalue `prevIndex` of `prev` (the same
// model at the previous speed). Empty where the base sweep has no such branch.
Eigen::VectorXd Predictor::calcModeCosts(const std::string& mode, const LinearModel& lin, const LinearModel* prev,
                                         int prevIndex) const {
  const SweepResult& ref = *reference_;
  const size_t k = std::min_element(ref.speeds.begin(), ref.speeds.end(), [&](double a, double b) {
                     return std::abs(a - lin.speed) < std::abs(b - lin.speed);
                   }) - ref.speeds.begin();
  const auto branch = std::find_if(ref.branches.begin(), ref.branches.end(),
                                   [&](const ModeBranch& b) { return b.label == mode && b.index[k] >= 0; });
  if (branch == ref.branches.end()) return {};
  Eigen::VectorXd c(lin.eigenvalues.size());
  for (int kb = 0; kb < lin.eigenvalues.size(); ++kb) {
    c[kb] = calcMatchCost(ref.models[k], branch->index[k], lin, kb);
    if (prev && prevIndex >= 0) c[kb] += calcMatchCost(*prev, prevIndex, lin, kb);
  }
  return c;
}

// The labelled modes of the rows, matched speed by speed (calcModeCosts), cheapest match first; a
// real eigenvalue goes to one label only (two labels on one real root is a mismatch: held-out
// Crescendo had capsize and castor predicted equal at 2-3.2 m/s), a complex pair may carry two
// (capsize and castor joined into one pair at low speed).
std::vector<Predictor::ModeTrack> Predictor::trackModes(const std::vector<LinearModel>& models) const {
  std::vector<ModeTrack> out;
  for (const auto& row : data_.eigenvalues)
    if (!row.mode.empty() && std::none_of(out.begin(), out.end(), [&](const ModeTrack& t) { return t.mode == row.mode; }))
      out.push_back({row.mode, std::vector<int>(models.size(), -1)});
  for (size_t k = 0; k < models.size(); ++k) {
    std::vector<Eigen::VectorXd> costs;
    std::vector<size_t> order;
    for (size_t m = 0; m < out.size(); ++m) {
      costs.push_back(calcModeCosts(out[m].mode, models[k], k ? &models[k - 1] : nullptr, k ? out[m].index[k - 1] : -1));
      if (costs.back().size() > 0) order.push_back(m);
    }
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return costs[a].minCoeff() < costs[b].minCoeff(); });
    std::vector<bool> taken(static_cast<size_t>(models[k].eigenvalues.size()), false);
    for (size_t m : order) {
      int best = -1;
      for (int kb = 0; kb < costs[m].size(); ++kb)
        if (!taken[kb] && (best < 0 || costs[m][kb] < costs[m][best])) best = kb;
      out[m].index[k] = best;
      if (best >= 0 && models[k].eigenvalues[best].imag() == 0) taken[best] = true;
    }
  }
  return out;
}

std::vector<std::complex<double>> Predictor::predictInterpolated(const std::vector<LinearModel>& models,
                                                                 const std::vector<double>& speeds) const {
  std::vector<std::complex<double>> out;
  const std::vector<ModeTrack> tracks = trackModes(models);
  std::vector<std::vector<std::complex<double>>> atNodes(tracks.size());  // per mode, per node
  for (const auto& row : data_.eigenvalues) {
    std::complex<double> sum = 0;
    const std::vector<double> vs = getEvaluationSpeeds(row);
    for (double v : vs) {
      if (row.mode.empty() || isExactMode(row.mode)) {
        sum += pickEigenvalue(models, findSpeed(speeds, v), row, tracks);
        continue;
      }
      const size_t m = std::find_if(tracks.begin(), tracks.end(), [&](const ModeTrack& t) { return t.mode == row.mode; }) -
                       tracks.begin();
      if (atNodes[m].empty())
        for (double x : nodes_) atNodes[m].push_back(pickEigenvalue(models, findSpeed(speeds, x), row, tracks));
      sum += interpolate(nodes_, atNodes[m], v);
    }
    out.push_back(sum / static_cast<double>(vs.size()));
  }
  return out;
}

std::complex<double> Predictor::pickEigenvalue(const std::vector<LinearModel>& models, size_t k,
                                               const MeasuredEigenvalue& row, const std::vector<ModeTrack>& tracks) const {
  const LinearModel& lin = models[k];
  std::complex<double> best;
  if (row.mode.empty()) {
    double dmin = HUGE_VAL;
    for (int i = 0; i < lin.eigenvalues.size(); ++i) {
      const std::complex<double> l = lin.eigenvalues(i);
      const double d = std::abs(std::complex<double>(l.real(), std::abs(l.imag())) - std::complex<double>(row.real, row.imag));
      if (d < dmin) dmin = d, best = l;
    }
  } else {
    const auto t = std::find_if(tracks.begin(), tracks.end(), [&](const ModeTrack& m) { return m.mode == row.mode; });
    if (t->index[k] < 0)
      throw InputError(row.where, "the scenario has no " + row.mode + " mode near " + std::to_string(lin.speed) + " m/s");
    best = lin.eigenvalues(t->index[k]);
  }
  return {best.real(), std::abs(best.imag())};
}

Prediction Predictor::predictParts(const std::vector<std::string>& overrides,
                                   const std::vector<std::vector<double>>& sigma, bool exact,
                                   const std::vector<std::vector<ArNoise>>& noise) const {
  Prediction p;
  p.eigenvalues.resize(data_.eigenvalues.size());
  p.responses.resize(data_.responses.size());
  for (const auto& part : parts_) {
    const ControllerGroup& g = part->group;
    std::vector<std::vector<double>> partSigma;
    std::vector<std::vector<ArNoise>> partNoise;
    for (size_t r : g.runs) {
      partSigma.push_back(sigma[r]);
      if (!noise.empty()) partNoise.push_back(noise[r]);
    }
    const Prediction q = part->predictor->predict(overrides, partSigma, exact, partNoise);
    for (size_t i = 0; i < g.rows.size(); ++i) p.eigenvalues[g.rows[i]] = q.eigenvalues[i];
    for (size_t i = 0; i < g.runs.size(); ++i) p.responses[g.runs[i]] = q.responses[i];
    p.numLinear += q.numLinear;
  }
  return p;
}

Prediction Predictor::predict(const std::vector<std::string>& overrides,
                              const std::vector<std::vector<double>>& sigma, bool exact,
                              const std::vector<std::vector<ArNoise>>& noise) const {
  if (!parts_.empty()) return predictParts(overrides, sigma, exact, noise);
  const bool fast = !exact && !nodes_.empty();
  const std::vector<double>& speeds = fast ? fastSpeeds_ : speeds_;
  const std::vector<LinearModel> models = calcLinearModels(overrides, speeds);
  Prediction p;
  if (fast) p.eigenvalues = predictInterpolated(models, speeds);
  const std::vector<ModeTrack> tracks = fast ? std::vector<ModeTrack>() : trackModes(models);
  for (const auto& row : data_.eigenvalues) {
    if (fast) break;
    const std::vector<double> nodes = getEvaluationSpeeds(row);
    std::complex<double> sum = 0;
    for (double v : nodes) sum += pickEigenvalue(models, findSpeed(speeds, v), row, tracks);
    p.eigenvalues.push_back(sum / static_cast<double>(nodes.size()));
  }
  for (size_t r = 0; r < data_.responses.size(); ++r) {
    p.responses.push_back(fitFreeResponse(models[findSpeed(speeds, data_.responses[r].speed)], data_.responses[r], sigma[r],
                                          r < noise.size() ? noise[r] : std::vector<ArNoise>()));
    p.numLinear += p.responses.back().numLinear;
  }
  return p;
}

}  // namespace motostab::diagnosis
