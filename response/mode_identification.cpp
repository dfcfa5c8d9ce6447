#include "response/mode_identification.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include "io/csv.h"
#include "io/input_error.h"
#include "io/result_error.h"
#include "response/exponential_fit.h"
#include "response/matrix_pencil.h"

namespace motostab::response {

using io::formatNumber;

namespace {

// Bad samples or window: an InputError the caller locates (response_csv.cpp names the file and columns).
io::InputError badData(const std::string& why) { return io::InputError({}, why); }


constexpr double kPi = 3.14159265358979323846;
// Residual ratio by which a fit without the allowed offset must beat the fit with it.
constexpr double kOffsetPreference = 10;
// Levenberg-Marquardt iterations for each candidate; the chosen one is then polished to convergence.
constexpr int kCandidateIterations = 40;

std::string formatTime(double t) { return formatNumber(t, 6); }

// Samples of the window on a uniform grid for the pencil: the samples themselves when already uniform
// (decimated by an integer factor if too many), else linear interpolation at the median step.
Eigen::MatrixXd makeUniformSamples(const Eigen::VectorXd& tau, const Eigen::MatrixXd& samples,
                                   const IdentificationOptions& options, bool& resampled, double& step) {
  const int n = static_cast<int>(tau.size());
  std::vector<double> steps(n - 1);
  for (int i = 0; i + 1 < n; ++i) steps[i] = tau(i + 1) - tau(i);
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  const auto [lo, hi] = std::minmax_element(steps.begin(), steps.end());
  const int cap = std::max(options.maxPencilSamples, 16);
  if ((*hi - *lo) <= options.uniformTolerance * median) {
    const int factor = (n + cap - 1) / cap;
    resampled = false;
    step = (tau(n - 1) - tau(0)) / (n - 1) * factor;
    const int m = (n - 1) / factor + 1;
    Eigen::MatrixXd out(m, samples.cols());
    for (int i = 0; i < m; ++i) out.row(i) = samples.row(i * factor);
    return out;
  }
  resampled = true;
  const double span = tau(n - 1) - tau(0);
  step = std::max(median, span / (cap - 1));
  const int m = static_cast<int>(std::floor(span / step + 1e-9)) + 1;
  Eigen::MatrixXd out(m, samples.cols());
  int j = 0;
  for (int i = 0; i < m; ++i) {
    const double t = tau(0) + i * step;
    while (j + 2 < n && tau(j + 1) < t) ++j;
    const double w = std::clamp((t - tau(j)) / (tau(j + 1) - tau(j)), 0.0, 1.0);
    out.row(i) = (1 - w) * samples.row(j) + w * samples.row(j + 1);
  }
  return out;
}

// Continuous poles from the pencil's discrete poles: a pair once (omega > 0), real exponentials with z > 0;
// poles at z <= 0 (Nyquist, numerically zero) and ones that would overflow in the window are dropped.
std::vector<ContinuousPole> toContinuousPoles(const std::vector<std::complex<double>>& discrete, double step,
                                              double span) {
  std::vector<ContinuousPole> poles;
  for (const auto& z : discrete) {
    if (!(std::abs(z) > 1e-12) || !std::isfinite(std::abs(z))) continue;
    if (z.imag() < 0 || (z.imag() == 0 && z.real() <= 0)) continue;
    const std::complex<double> lambda = std::log(z) / step;
    if (lambda.real() * span > 50) continue;
    poles.push_back({lambda.real(), z.imag() > 0 ? lambda.imag() : 0.0});
  }
  return poles;
}

// Removes the real pole nearest z = 1 (the offset's pole); false if there is no real pole.
bool removeOffsetPole(std::vector<ContinuousPole>& poles) {
  auto nearest = poles.end();
  for (auto it = poles.begin(); it != poles.end(); ++it)
    if (it->omega == 0 && (nearest == poles.end() || std::abs(it->sigma) < std::abs(nearest->sigma))) nearest = it;
  if (nearest == poles.end()) return false;
  poles.erase(nearest);
  return true;
}

int getOrder(const std::vector<ContinuousPole>& poles) { return getBasisSize(poles, false); }

// Throws InputError (no location: the caller knows the data's source) unless the samples and the window can be fitted.
void checkInput(const std::vector<double>& time, const std::vector<std::vector<double>>& signals,
                const IdentificationOptions& options) {
  if (signals.empty()) throw badData("no signal to identify");
  for (size_t k = 0; k < signals.size(); ++k) {
    if (signals[k].size() != time.size())
      throw badData("signal " + std::to_string(k) + " has " + std::to_string(signals[k].size()) +
                                  " samples but time has " + std::to_string(time.size()));
    for (size_t i = 0; i < time.size(); ++i)
      if (!std::isfinite(signals[k][i]))
        throw badData("signal " + std::to_string(k) + " sample " + std::to_string(i) + " is not finite");
  }
  if (time.empty()) throw badData("no samples");
  for (size_t i = 0; i < time.size(); ++i) {
    if (!std::isfinite(time[i])) throw badData("time sample " + std::to_string(i) + " is not finite");
    if (i > 0 && !(time[i] > time[i - 1]))
      throw badData("time is not strictly increasing at sample " + std::to_string(i) + " (t = " +
                                  formatTime(time[i]) + " s)");
  }
  if (!(options.windowStart < options.windowEnd))
    throw badData("window start " + formatTime(options.windowStart) + " s is not before its end " +
                                formatTime(options.windowEnd) + " s");
  if (options.maxOrder < 1) throw badData("maximum order must be at least 1");
  // A window reaching beyond the data is an error (infinite ends mean "from the start" / "to the end").
  const double slack = 1e-9 * std::max(1.0, std::abs(time.back() - time.front()));
  if ((std::isfinite(options.windowStart) && options.windowStart < time.front() - slack) ||
      (std::isfinite(options.windowEnd) && options.windowEnd > time.back() + slack))
    throw badData("window " + formatTime(options.windowStart) + ":" + formatTime(options.windowEnd) +
                                " s is outside the data (" + formatTime(time.front()) + " to " +
                                formatTime(time.back()) + " s)");
}

// The result's order, offsets and modes in signal units (a cos + b sin = A cos(omega tau + phi)), sorted by
// their largest contribution in the window relative to the signal's standard deviation `scale`.
void setModes(const ExponentialFit& best, const Eigen::VectorXd& scale, double span, IdentificationResult& result) {
  result.order = getOrder(best.poles);
  const int k = static_cast<int>(scale.size());
  result.offset.assign(k, 0.0);
  if (best.offset)
    for (int s = 0; s < k; ++s) result.offset[s] = best.coefficients(0, s) * scale(s);
  std::vector<std::pair<double, IdentifiedMode>> ranked;
  int col = best.offset ? 1 : 0;
  for (const auto& pole : best.poles) {
    IdentifiedMode mode;
    mode.real = pole.sigma;
    mode.imag = pole.omega;
    mode.frequencyHz = pole.omega / (2 * kPi);
    mode.dampingRatio = -pole.sigma / std::hypot(pole.sigma, pole.omega);
    double peak = 0;
    for (int s = 0; s < k; ++s) {
      const double a = best.coefficients(col, s), b = pole.omega > 0 ? best.coefficients(col + 1, s) : 0.0;
      const double amplitude = std::hypot(a, b);
      mode.amplitude.push_back(amplitude * scale(s));
      mode.phase.push_back(pole.omega > 0 ? std::atan2(-b, a) : (a >= 0 ? 0.0 : kPi));
      peak = std::max(peak, amplitude * std::max(1.0, std::exp(pole.sigma * span)));
    }
    col += pole.omega > 0 ? 2 : 1;
    ranked.emplace_back(peak, mode);
  }
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (auto& r : ranked) result.modes.push_back(std::move(r.second));
}

// The samples of the window: times tau from its first sample (s) and the signals scaled by their
// standard deviations, so that all signals weigh alike.
struct WindowSamples {
  Eigen::VectorXd tau;
  Eigen::MatrixXd y;      ///< one column per signal, scaled
  Eigen::VectorXd scale;  ///< each signal's standard deviation in the window (signal units)
};

// The window's samples; its first and last times and sample count go into `result`. Throws
// InputError when the window has too few samples for `maxOrder` or a constant signal.
WindowSamples selectWindow(const std::vector<double>& time, const std::vector<std::vector<double>>& signals,
                           const IdentificationOptions& options, int maxOrder, IdentificationResult& result) {
  std::vector<int> index;
  for (size_t i = 0; i < time.size(); ++i)
    if (time[i] >= options.windowStart && time[i] <= options.windowEnd) index.push_back(static_cast<int>(i));
  const int n = static_cast<int>(index.size());
  const int k = static_cast<int>(signals.size());
  const int needed = std::max(12, 3 * (maxOrder + 2));
  if (n < needed)
    throw badData("window has " + std::to_string(n) + " samples; order " + std::to_string(maxOrder) +
                                " needs at least " + std::to_string(needed) + " (lower the maximum order)");

  result.referenceTime = time[index.front()];
  result.windowStart = time[index.front()];
  result.windowEnd = time[index.back()];
  result.sampleCount = n;
  WindowSamples w;
  Eigen::VectorXd& tau = w.tau;
  Eigen::MatrixXd& y = w.y;
  tau.resize(n);
  y.resize(n, k);
  for (int i = 0; i < n; ++i) {
    tau(i) = time[index[i]] - result.referenceTime;
    for (int s = 0; s < k; ++s) y(i, s) = signals[s][index[i]];
  }
  Eigen::VectorXd& scale = w.scale;
  scale.resize(k);
  for (int s = 0; s < k; ++s) {
    const double mean = y.col(s).mean();
    scale(s) = std::sqrt((y.col(s).array() - mean).square().sum() / n);
    if (!(scale(s) > 0)) throw badData("signal " + std::to_string(s) + " is constant in the window");
    y.col(s) /= scale(s);
  }
  return w;
}

// The candidates of one pencil size: its poles without offset or, if an offset is allowed, the offset
// with one pole fewer (the real pole nearest z = 1 taken as the offset); each polished. Of the two, the
// offset is kept unless the fit without it is kOffsetPreference times better (it then has a real mode).
std::vector<ExponentialFit> fitPencilSize(const PencilDecomposition& pencil, int size, const WindowSamples& w,
                                          const IdentificationOptions& options, int maxOrder, double pencilStep) {
  const Eigen::VectorXd& tau = w.tau;
  const Eigen::MatrixXd& y = w.y;
  const double span = tau(tau.size() - 1), maxOmega = kPi / pencilStep;
  const auto all = toContinuousPoles(calcPencilPoles(pencil, size), pencilStep, span);
  std::vector<std::pair<std::vector<ContinuousPole>, bool>> variants{{all, false}};
  if (options.fitOffset) {
    auto poles = all;
    if (removeOffsetPole(poles)) variants.emplace_back(poles, true);
  }
  std::vector<ExponentialFit> sizeFits;
  for (const auto& [poles, offset] : variants) {
    if (poles.empty() || getOrder(poles) > maxOrder) continue;
    ExponentialFit fit = calcLinearFit(poles, offset, tau, y);
    if (options.polish) fit = polishPoles(fit, tau, y, maxOmega, kCandidateIterations);
    if (std::isfinite(fit.residualSumSquares)) sizeFits.push_back(std::move(fit));
  }
  // An allowed offset is preferred: the fit without it must be 10x better (it then has a real mode).
  if (sizeFits.size() == 2) {
    const bool keepOffset = sizeFits[0].residualSumSquares * kOffsetPreference > sizeFits[1].residualSumSquares;
    sizeFits.erase(sizeFits.begin() + (keepOffset ? 0 : 1));
  }
  return sizeFits;
}

// The candidate's figures: order, singular-value ratio at its pencil size, R^2 and BIC over `samplesTotal`
// scaled samples of `signalCount` signals.
OrderCandidate makeCandidate(const ExponentialFit& fit, int size, const Eigen::VectorXd& sv, int signalCount,
                             double samplesTotal, const IdentificationOptions& options) {
  int params = getBasisSize(fit.poles, fit.offset) * signalCount;
  for (const auto& p : fit.poles) params += p.omega > 0 ? 2 : 1;
  const double rss = std::max(fit.residualSumSquares, 1e-28 * samplesTotal);
  OrderCandidate c;
  c.order = getOrder(fit.poles);
  c.offset = fit.offset;
  c.pencilSize = size;
  // Two zero singular values (a noiseless signal past its order) show no gap: ratio 1, not 0/0.
  c.singularValueRatio = size >= sv.size() ? 0.0 : sv(size - 1) > 0 ? sv(size) / sv(size - 1) : 1.0;
  c.atGap = c.singularValueRatio < options.gapRatio;
  c.rSquared = 1 - fit.residualSumSquares / samplesTotal;
  c.criterion = samplesTotal * std::log(rss / samplesTotal) + params * std::log(samplesTotal);
  return c;
}

// Candidates: for every pencil size P, the P poles without offset or, if an offset is allowed, the offset
// with P-1 poles (fitPencilSize). Both have P components, as many as the leading singular values. Each is
// scored by BIC; the candidates go into result.candidates, their fits (same order) are returned.
std::vector<ExponentialFit> fitCandidates(const PencilDecomposition& pencil, const WindowSamples& w,
                                          const IdentificationOptions& options, int maxOrder,
                                          IdentificationResult& result) {
  const int extra = options.fitOffset ? 1 : 0;
  const double samplesTotal = static_cast<double>(w.y.rows()) * w.y.cols();
  std::vector<ExponentialFit> fits;
  for (int size = 1; size <= maxOrder + extra; ++size)
    for (auto& fit : fitPencilSize(pencil, size, w, options, maxOrder, result.pencilStep)) {
      result.candidates.push_back(
          makeCandidate(fit, size, pencil.singularValues, static_cast<int>(w.y.cols()), samplesTotal, options));
      fits.push_back(std::move(fit));
    }
  return fits;
}

// Selection: the lowest BIC among sizes at a singular-value gap (all sizes if there is none), or among
// candidates of the fixed order; -1 if none qualifies.
int chooseCandidate(const std::vector<OrderCandidate>& candidates, const IdentificationOptions& options) {
  const bool anyGap =
      std::any_of(candidates.begin(), candidates.end(), [](const OrderCandidate& c) { return c.atGap; });
  int chosen = -1;
  double bestCriterion = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < candidates.size(); ++i) {
    const auto& c = candidates[i];
    if (options.fixedOrder > 0 ? c.order != options.fixedOrder : anyGap && !c.atGap) continue;
    if (c.criterion < bestCriterion) {
      bestCriterion = c.criterion;
      chosen = static_cast<int>(i);
    }
  }
  return chosen;
}

// R^2 of the chosen fit over all signals and each signal's RMS residual (signal units and scaled).
void setResiduals(const ExponentialFit& best, const WindowSamples& w, IdentificationResult& result) {
  const int n = static_cast<int>(w.y.rows()), k = static_cast<int>(w.y.cols());
  const double samplesTotal = static_cast<double>(n) * k;
  const Eigen::MatrixXd residual = w.y - calcBasis(best.poles, best.offset, w.tau) * best.coefficients;
  result.rSquared = 1 - residual.squaredNorm() / samplesTotal;
  for (int s = 0; s < k; ++s) {
    const double rms = std::sqrt(residual.col(s).squaredNorm() / n);
    result.rmsResidual.push_back(rms * w.scale(s));
    result.normalisedRmsResidual.push_back(rms);
  }
}

}  // namespace

IdentificationResult identifyModes(const std::vector<double>& time, const std::vector<std::vector<double>>& signals,
                                   const IdentificationOptions& options) {
  checkInput(time, signals, options);
  const int maxOrder = options.fixedOrder > 0 ? options.fixedOrder : options.maxOrder;
  IdentificationResult result;
  const WindowSamples w = selectWindow(time, signals, options, maxOrder, result);
  const Eigen::MatrixXd uniform = makeUniformSamples(w.tau, w.y, options, result.resampled, result.pencilStep);
  const int extra = options.fitOffset ? 1 : 0;
  const int pencilParameter = static_cast<int>(uniform.rows()) / 3;
  if (pencilParameter < maxOrder + extra + 1)
    throw badData("too few samples in the window for order " + std::to_string(maxOrder));
  const PencilDecomposition pencil = calcPencilDecomposition(uniform, pencilParameter);
  for (int i = 0; i < std::min<int>(static_cast<int>(pencil.singularValues.size()), 2 * (maxOrder + extra) + 2); ++i)
    result.singularValues.push_back(pencil.singularValues(i));

  // Candidates of every pencil size scored by BIC; the chosen one is polished to convergence.
  const std::vector<ExponentialFit> fits = fitCandidates(pencil, w, options, maxOrder, result);
  const int chosen = chooseCandidate(result.candidates, options);
  if (chosen < 0) throw io::ResultError("no model could be fitted to the window");
  const double maxOmega = kPi / result.pencilStep;
  const ExponentialFit best = options.polish ? polishPoles(fits[chosen], w.tau, w.y, maxOmega) : fits[chosen];

  setModes(best, w.scale, w.tau(w.tau.size() - 1), result);
  setResiduals(best, w, result);
  return result;
}

std::vector<double> calcModelResponse(const IdentificationResult& result, int signalIndex,
                                      const std::vector<double>& time) {
  if (signalIndex < 0 || signalIndex >= static_cast<int>(result.offset.size()))
    throw std::logic_error("calcModelResponse: signal index " + std::to_string(signalIndex) + " out of range");
  std::vector<double> out;
  out.reserve(time.size());
  for (double t : time) {
    const double tau = t - result.referenceTime;
    double v = result.offset[signalIndex];
    for (const auto& m : result.modes)
      v += m.amplitude[signalIndex] * std::exp(m.real * tau) * std::cos(m.imag * tau + m.phase[signalIndex]);
    out.push_back(v);
  }
  return out;
}

}  // namespace motostab::response
