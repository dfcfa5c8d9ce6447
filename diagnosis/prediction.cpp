#include "diagnosis/prediction.h"

#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

#include "scenario/scenario.h"
#include "vehicle/vehicle_model.h"

namespace motostab {
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

// Rows c_j of the outputs: signal j reads state getStateName(quantity).
Eigen::MatrixXd calcOutputRows(const LinearModel& lin, const ResponseRun& run) {
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(static_cast<int>(run.signals.size()), lin.A.rows());
  for (size_t j = 0; j < run.signals.size(); ++j) {
    const int k = lin.findState(getStateName(run.signals[j].quantity));
    if (k < 0)
      throw InputError(run.where, "quantity " + getQuantityName(run.signals[j].quantity) +
                                      " is not a state of this model's linearisation");
    C(static_cast<int>(j), k) = 1;
  }
  return C;
}

// basis[j](i, :) = c_j exp(A (t_i - t_0)).
std::vector<Eigen::MatrixXd> calcFreeResponseBasis(const LinearModel& lin, const ResponseRun& run) {
  const Eigen::MatrixXd C = calcOutputRows(lin, run);
  const int n = static_cast<int>(lin.A.rows()), m = static_cast<int>(run.time.size());
  std::vector<Eigen::MatrixXd> basis(run.signals.size(), Eigen::MatrixXd(m, n));
  Eigen::MatrixXd E = Eigen::MatrixXd::Identity(n, n), step;
  double lastDt = -1;
  for (int i = 0; i < m; ++i) {
    if (i > 0) {
      const double dt = run.time[i] - run.time[i - 1];
      if (std::abs(dt - lastDt) > 1e-12 * std::max(1.0, dt)) step = (lin.A * dt).exp();
      lastDt = dt;
      E = step * E;
    }
    const Eigen::MatrixXd row = C * E;
    for (size_t j = 0; j < basis.size(); ++j) basis[j].row(i) = row.row(static_cast<int>(j));
  }
  return basis;
}

struct BilinearFit {
  Eigen::VectorXd x0;
  std::vector<double> gains, offsets;
  double cost = 0;
};

double calcCost(const std::vector<Eigen::MatrixXd>& basis, const ResponseRun& run, const std::vector<double>& sigma,
                BilinearFit& f) {
  f.cost = 0;
  for (size_t j = 0; j < basis.size(); ++j) {
    const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(run.signals[j].values.data(), basis[j].rows());
    f.cost += ((f.gains[j] * (basis[j] * f.x0)).array() + f.offsets[j] - y.array()).matrix().squaredNorm() /
              (sigma[j] * sigma[j]);
  }
  return f.cost;
}

// x0 and offsets for fixed gains: one weighted least-squares problem (minimum norm: unobservable
// directions of x0 stay zero).
void solveStateAndOffsets(const std::vector<Eigen::MatrixXd>& basis, const ResponseRun& run,
                          const std::vector<double>& sigma, BilinearFit& f) {
  const int n = static_cast<int>(basis[0].cols()), ns = static_cast<int>(basis.size());
  const int m = static_cast<int>(basis[0].rows());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(m * ns, n + ns);
  Eigen::VectorXd y(m * ns);
  for (int j = 0; j < ns; ++j) {
    M.block(j * m, 0, m, n) = f.gains[j] * basis[j] / sigma[j];
    M.block(j * m, n + j, m, 1).setConstant(1.0 / sigma[j]);
    y.segment(j * m, m) = Eigen::Map<const Eigen::VectorXd>(run.signals[j].values.data(), m) / sigma[j];
  }
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(M);
  cod.setThreshold(1e-10);
  const Eigen::VectorXd s = cod.solve(y);
  f.x0 = s.head(n);
  for (int j = 0; j < ns; ++j) f.offsets[j] = s(n + j);
}

// Gain and offset of signal j for fixed x0.
void solveGain(const Eigen::MatrixXd& basis, const ResponseSignal& sig, BilinearFit& f, size_t j) {
  const Eigen::VectorXd z = basis * f.x0;
  const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(sig.values.data(), z.size());
  Eigen::MatrixXd M(z.size(), 2);
  M.col(0) = z;
  M.col(1).setOnes();
  const Eigen::VectorXd s = M.colPivHouseholderQr().solve(y);
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

}  // namespace

ResponseFit fitFreeResponse(const LinearModel& lin, const ResponseRun& run, const std::vector<double>& sigma) {
  const std::vector<Eigen::MatrixXd> basis = calcFreeResponseBasis(lin, run);
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
    solveStateAndOffsets(basis, run, sigma, f);
    for (size_t j = 0; j < ns; ++j)
      if (run.signals[j].freeScale && static_cast<int>(j) != reference) solveGain(basis[j], run.signals[j], f, j);
    const double cost = calcCost(basis, run, sigma, f);
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
  for (const auto& row : data.eigenvalues)
    for (double v : getEvaluationSpeeds(row)) speeds_.push_back(v);
  for (const auto& run : data.responses) speeds_.push_back(run.speed);
  std::sort(speeds_.begin(), speeds_.end());
  speeds_.erase(std::unique(speeds_.begin(), speeds_.end()), speeds_.end());
  const Scenario scenario = loadScenario(scenarioFile_, baseOverrides_);
  const VehicleModel model(scenario);
  SweepOptions opt;
  opt.step = std::min(scenario.speeds.step, 0.1);
  opt.start = std::min(scenario.speeds.start, std::floor(speeds_.front() / opt.step) * opt.step);
  opt.stop = std::max(scenario.speeds.stop, std::ceil(speeds_.back() / opt.step) * opt.step);
  opt.threads = 2;
  reference_ = std::make_shared<SweepResult>(runSweep(model, opt));
}

std::vector<LinearModel> Predictor::calcLinearModels(const std::vector<std::string>& overrides) const {
  std::vector<std::string> all = baseOverrides_;
  all.insert(all.end(), overrides.begin(), overrides.end());
  const Scenario scenario = loadScenario(scenarioFile_, all);
  const VehicleModel model(scenario);
  const SweepOptions sweep;
  TrimResult trim = calcTrim(model, speeds_.front(), sweep.trim);
  std::vector<LinearModel> out;
  for (size_t i = 0; i < speeds_.size(); ++i) {
    if (i > 0) updTrim(model, speeds_[i], sweep.trim, trim);
    out.push_back(linearizeInPlace(model, trim, sweep.linearize));
  }
  return out;
}

int Predictor::findSpeed(double v) const {
  return static_cast<int>(std::lower_bound(speeds_.begin(), speeds_.end(), v) - speeds_.begin());
}

std::complex<double> Predictor::pickEigenvalue(const LinearModel& lin, const MeasuredEigenvalue& row) const {
  std::complex<double> best;
  if (row.mode.empty()) {
    double dmin = HUGE_VAL;
    for (int k = 0; k < lin.eigenvalues.size(); ++k) {
      const std::complex<double> l = lin.eigenvalues(k);
      const double d = std::abs(std::complex<double>(l.real(), std::abs(l.imag())) - std::complex<double>(row.real, row.imag));
      if (d < dmin) dmin = d, best = l;
    }
  } else {
    const SweepResult& ref = *reference_;
    const size_t k = std::min_element(ref.speeds.begin(), ref.speeds.end(), [&](double a, double b) {
                       return std::abs(a - lin.speed) < std::abs(b - lin.speed);
                     }) - ref.speeds.begin();
    const auto branch = std::find_if(ref.branches.begin(), ref.branches.end(),
                                     [&](const ModeBranch& b) { return b.label == row.mode && b.index[k] >= 0; });
    if (branch == ref.branches.end())
      throw InputError(row.where, "the scenario has no " + row.mode + " mode near " + std::to_string(lin.speed) + " m/s");
    best = lin.eigenvalues(findBestMatch(ref.models[k], branch->index[k], lin));
  }
  return {best.real(), std::abs(best.imag())};
}

Prediction Predictor::predict(const std::vector<std::string>& overrides,
                              const std::vector<std::vector<double>>& sigma) const {
  const std::vector<LinearModel> models = calcLinearModels(overrides);
  Prediction p;
  for (const auto& row : data_.eigenvalues) {
    const std::vector<double> nodes = getEvaluationSpeeds(row);
    std::complex<double> sum = 0;
    for (double v : nodes) sum += pickEigenvalue(models[findSpeed(v)], row);
    p.eigenvalues.push_back(sum / static_cast<double>(nodes.size()));
  }
  for (size_t r = 0; r < data_.responses.size(); ++r) {
    p.responses.push_back(fitFreeResponse(models[findSpeed(data_.responses[r].speed)], data_.responses[r], sigma[r]));
    p.numLinear += p.responses.back().numLinear;
  }
  return p;
}

}  // namespace motostab
