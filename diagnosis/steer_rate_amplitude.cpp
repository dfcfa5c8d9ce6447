#include "diagnosis/steer_rate_amplitude.h"

#include <cmath>
#include <complex>
#include <functional>

namespace motostab::diagnosis {

namespace {

// The nominal weave at the reference sweep's speed nearest v: its eigenvalue and the ratio
// |steer rate| / |roll rate| of its eigenvector. False when there is no oscillatory weave there or the
// model has no such states.
bool findWeave(const Predictor& nominal, double v, std::complex<double>& lambda, double& steerPerRoll) {
  const analysis::SweepResult& sweep = nominal.getReferenceSweep();
  if (sweep.speeds.empty()) return false;
  size_t s = 0;
  for (size_t i = 1; i < sweep.speeds.size(); ++i)
    if (std::abs(sweep.speeds[i] - v) < std::abs(sweep.speeds[s] - v)) s = i;
  const analysis::LinearModel& lin = sweep.models[s];
  for (const auto& b : sweep.branches) {
    if (b.label != analysis::ModeLabel::Weave || s >= b.index.size() || b.index[s] < 0) continue;
    lambda = lin.eigenvalues(b.index[s]);
    const int steer = lin.findState(vehicle::StateRole::Steer, vehicle::StateKind::Rate);
    const int roll = lin.findState(vehicle::StateRole::Roll, vehicle::StateKind::Rate);
    if (!(std::abs(lambda.imag()) > 0) || steer < 0 || roll < 0) return false;
    const double r = std::abs(lin.eigenvectors(roll, b.index[s]));
    if (!(r > 0)) return false;
    steerPerRoll = std::abs(lin.eigenvectors(steer, b.index[s])) / r;
    return true;
  }
  return false;
}

// Mean over the runs of the amplitude `perRun` gives (NaN: the run has none); "" when no run has one.
std::string averageRuns(const MeasuredData& data, const std::string& what,
                        const std::function<double(const ResponseRun&, const ResponseSignal&)>& perRun,
                        Quantity q, double& mean) {
  double sum = 0;
  std::string runs;
  int n = 0;
  for (size_t r = 0; r < data.responses.size(); ++r)
    for (const auto& sig : data.responses[r].signals) {
      if (sig.quantity != q || sig.freeScale) continue;
      const double a = perRun(data.responses[r], sig);
      if (!std::isfinite(a) || !(a > 0)) continue;
      sum += a, ++n;
      runs += (runs.empty() ? "run " : ", run ") + std::to_string(r + 1) + " " + sig.column;
      break;  // one signal per run
    }
  if (n == 0) return "";
  mean = sum / n;
  return what + " (" + runs + (n > 1 ? "; mean of " + std::to_string(n) + " runs" : "") + ")";
}

}  // namespace

double calcSinusoidAmplitude(const std::vector<double>& values) {
  if (values.empty()) return 0;
  double mean = 0, ss = 0;
  for (double y : values) mean += y;
  mean /= static_cast<double>(values.size());
  for (double y : values) ss += (y - mean) * (y - mean);
  return std::sqrt(2 * ss / static_cast<double>(values.size()));
}

SteerRateAmplitude findSteerRateAmplitude(const MeasuredData& data, const Predictor& nominal) {
  if (data.steerRateAmplitude > 0) return {data.steerRateAmplitude, "steer_rate_amplitude_rad_s of " + data.file};
  const auto amplitude = [](const ResponseSignal& s) { return calcSinusoidAmplitude(s.values) * std::abs(s.scale); };
  double mean = 0;
  std::string src = averageRuns(data, "sqrt(2) RMS of the measured steer rate",
                                [&](const ResponseRun&, const ResponseSignal& s) { return amplitude(s); }, Quantity::SteerRate, mean);
  if (!src.empty()) return {mean, src};
  src = averageRuns(data, "sqrt(2) RMS of the measured steer angle times the nominal weave's |lambda|",
                    [&](const ResponseRun& run, const ResponseSignal& s) {
                      std::complex<double> lambda;
                      double ratio = 0;
                      return findWeave(nominal, run.speed, lambda, ratio) ? amplitude(s) * std::abs(lambda) : std::nan("");
                    },
                    Quantity::SteerAngle, mean);
  if (!src.empty()) return {mean, src};
  src = averageRuns(data, "sqrt(2) RMS of the measured roll rate times the nominal weave's |steer rate| / |roll rate|",
                    [&](const ResponseRun& run, const ResponseSignal& s) {
                      std::complex<double> lambda;
                      double ratio = 0;
                      return findWeave(nominal, run.speed, lambda, ratio) ? amplitude(s) * ratio : std::nan("");
                    },
                    Quantity::RollRate, mean);
  if (!src.empty()) return {mean, src};
  return {0, "no steer-rate amplitude in the data (give steer_rate_amplitude_rad_s, or a response run with a "
             "calibrated steer_rate, steer_angle or roll_rate signal)"};
}

}  // namespace motostab::diagnosis
