#include "modal/spectra.h"

#include <fftw3.h>

#include <cmath>
#include <cstdio>
#include <mutex>
#include <stdexcept>

namespace motostab::modal {
namespace {

std::string formatTime(double t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g s", t);
  return buf;
}

// True if `x` sits at its extreme for `run` consecutive samples (a clipped converter).
bool hasFlatTop(const std::vector<double>& x, int run) {
  double m = 0;
  for (double v : x) m = std::max(m, std::abs(v));
  if (m == 0) return false;
  int count = 0;
  for (double v : x) {
    count = (std::abs(v) >= m * (1 - 1e-9)) ? count + 1 : 0;
    if (count >= run) return true;
  }
  return false;
}

double getMaxAbs(const std::vector<double>& x) {
  double m = 0;
  for (double v : x) m = std::max(m, std::abs(v));
  return m;
}

}  // namespace

HitCheck checkHit(const ImpactRecord& hit, const HitCheckOptions& options) {
  HitCheck c;
  const auto& f = hit.force;
  if (f.empty()) throw std::logic_error("checkHit: empty force record");
  for (size_t k = 0; k < f.size(); ++k)
    if (std::abs(f[k]) > std::abs(c.peakForce)) c.peakForce = f[k], c.peakIndex = k;
  const double peak = std::abs(c.peakForce), edge = options.pulseEdgeFraction * peak;
  size_t s = c.peakIndex, e = c.peakIndex;
  while (s > 0 && std::abs(f[s - 1]) >= edge) --s;
  while (e < f.size() && std::abs(f[e]) >= edge) ++e;
  c.pulseStart = s;
  c.pulseEnd = e;
  const size_t w = std::max<size_t>(e - s, 1);
  const double second = options.doubleHitFraction * peak;
  for (size_t k = 0; k < f.size(); ++k) {
    if (k + w >= s && k < e + w) continue;
    if (std::abs(f[k]) > second) {
      c.problems.push_back("double hit at " + formatTime(k * hit.dt) + " (" + std::to_string(std::abs(f[k])) +
                           " N after a " + std::to_string(peak) + " N pulse)");
      break;
    }
  }
  auto checkChannel = [&](const std::vector<double>& x, double range, const std::string& name) {
    if (range > 0 && getMaxAbs(x) >= range)
      c.problems.push_back("overload on " + name + " (reading at the stated range " + std::to_string(range) + ")");
    else if (hasFlatTop(x, options.clipRun))
      c.problems.push_back("overload on " + name + " (clipped: flat top of " + std::to_string(options.clipRun) +
                           "+ samples)");
  };
  checkChannel(f, options.forceRange, "force");
  for (size_t j = 0; j < hit.responses.size(); ++j)
    checkChannel(hit.responses[j], options.responseRange, "response channel " + std::to_string(j + 1));
  return c;
}

std::vector<double> calcForceWindow(size_t n, size_t pulseStart, size_t pulseEnd) {
  std::vector<double> w(n, 0.0);
  const size_t width = std::max<size_t>(pulseEnd - pulseStart, 1);
  const size_t taper = std::max<size_t>(width, 2);
  const size_t a = pulseStart > width ? pulseStart - width : 0;
  const size_t b = std::min(n, pulseEnd + width);
  for (size_t k = a; k < b; ++k) w[k] = 1.0;
  for (size_t k = 0; k < taper && b + k < n; ++k) w[b + k] = 0.5 * (1 + std::cos(M_PI * (k + 1) / (taper + 1)));
  return w;
}

double calcExponentialDecayRate(double duration, double endValue) {
  if (!(endValue > 0 && endValue <= 1) || !(duration > 0))
    throw std::logic_error("exponential window: end value must be in (0, 1] and duration > 0");
  return std::log(1.0 / endValue) / duration;
}

std::vector<std::complex<double>> calcRealDft(const std::vector<double>& x) {
  static std::mutex plannerMutex;  // FFTW planning is not thread-safe
  const int n = static_cast<int>(x.size());
  double* in = fftw_alloc_real(n);
  fftw_complex* out = fftw_alloc_complex(n / 2 + 1);
  fftw_plan plan;
  {
    std::lock_guard<std::mutex> lock(plannerMutex);
    plan = fftw_plan_dft_r2c_1d(n, in, out, FFTW_ESTIMATE);
  }
  std::copy(x.begin(), x.end(), in);
  fftw_execute(plan);
  std::vector<std::complex<double>> y(n / 2 + 1);
  for (int k = 0; k <= n / 2; ++k) y[k] = {out[k][0], out[k][1]};
  {
    std::lock_guard<std::mutex> lock(plannerMutex);
    fftw_destroy_plan(plan);
  }
  fftw_free(in);
  fftw_free(out);
  return y;
}

FrfEstimate estimateH1(const std::vector<ImpactRecord>& hits, const WindowOptions& window) {
  if (hits.empty()) throw std::logic_error("estimateH1: no hits");
  const size_t n = hits[0].force.size(), nc = hits[0].responses.size();
  const double dt = hits[0].dt;
  FrfEstimate e;
  e.df = 1.0 / (n * dt);
  e.averages = static_cast<int>(hits.size());
  e.windowDecayRate = calcExponentialDecayRate(n * dt, window.exponentialEndValue);
  std::vector<double> expo(n);
  for (size_t k = 0; k < n; ++k) expo[k] = std::exp(-e.windowDecayRate * k * dt);
  for (const auto& hit : hits) {
    if (hit.force.size() != n || hit.responses.size() != nc || std::abs(hit.dt - dt) > 1e-9 * dt)
      throw std::logic_error("estimateH1: hits differ in length, sampling interval or channel count");
    std::vector<double> f = hit.force;
    if (window.forceWindow) {
      const HitCheck c = checkHit(hit);
      const auto fw = calcForceWindow(n, c.pulseStart, c.pulseEnd);
      for (size_t k = 0; k < n; ++k) f[k] *= fw[k];
    }
    for (size_t k = 0; k < n; ++k) f[k] *= expo[k];
    e.forceSpectra.push_back(calcRealDft(f));
    std::vector<std::vector<std::complex<double>>> xs;
    for (const auto& r : hit.responses) {
      if (r.size() != n) throw std::logic_error("estimateH1: response length differs from force length");
      std::vector<double> x(n);
      for (size_t k = 0; k < n; ++k) x[k] = r[k] * expo[k];
      xs.push_back(calcRealDft(x));
    }
    e.responseSpectra.push_back(std::move(xs));
  }
  e.frequency.resize(n / 2 + 1);
  for (size_t k = 0; k < e.frequency.size(); ++k) e.frequency[k] = k * e.df;
  calcH1FromSpectra(e, std::vector<bool>(hits.size(), true), e.h1, &e.coherence);
  return e;
}

void calcH1FromSpectra(const FrfEstimate& e, const std::vector<bool>& use,
                       std::vector<std::vector<std::complex<double>>>& h1,
                       std::vector<std::vector<double>>* coherence) {
  const size_t nb = e.forceSpectra.at(0).size(), nc = e.responseSpectra.at(0).size();
  h1.assign(nc, std::vector<std::complex<double>>(nb));
  if (coherence) coherence->assign(nc, std::vector<double>(nb));
  for (size_t c = 0; c < nc; ++c) {
    for (size_t k = 0; k < nb; ++k) {
      double sff = 0, sxx = 0;
      std::complex<double> sfx = 0;
      for (size_t i = 0; i < e.forceSpectra.size(); ++i) {
        if (!use[i]) continue;
        const auto F = e.forceSpectra[i][k], X = e.responseSpectra[i][c][k];
        sff += std::norm(F);
        sxx += std::norm(X);
        sfx += std::conj(F) * X;
      }
      h1[c][k] = sff > 0 ? sfx / sff : 0.0;
      if (coherence) (*coherence)[c][k] = (sff > 0 && sxx > 0) ? std::norm(sfx) / (sff * sxx) : 0.0;
    }
  }
}

}  // namespace motostab::modal
