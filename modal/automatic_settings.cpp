#include "modal/automatic_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "io/result_error.h"

namespace motostab::modal {
namespace {

// Force autospectrum averaged over hits, per bin.
std::vector<double> calcForceAutospectrum(const FrfEstimate& frf) {
  std::vector<double> s(frf.frequency.size(), 0.0);
  for (const auto& F : frf.forceSpectra)
    for (size_t k = 0; k < s.size(); ++k) s[k] += std::norm(F[k]) / frf.forceSpectra.size();
  return s;
}

// Coherence averaged over channels, then a sliding median of `width` bins.
std::vector<double> calcSmoothedCoherence(const FrfEstimate& frf, int width) {
  const size_t n = frf.frequency.size();
  std::vector<double> mean(n, 0.0), out(n, 0.0);
  for (const auto& c : frf.coherence)
    for (size_t k = 0; k < n; ++k) mean[k] += c[k] / frf.coherence.size();
  const long half = width / 2;
  std::vector<double> w;
  for (long k = 0; k < static_cast<long>(n); ++k) {
    w.assign(mean.begin() + std::max(0L, k - half), mean.begin() + std::min<long>(n, k + half + 1));
    std::nth_element(w.begin(), w.begin() + w.size() / 2, w.end());
    out[k] = w[w.size() / 2];
  }
  return out;
}

// Index of the first bin above `from` whose force autospectrum is below fraction x its maximum.
size_t findForceLimitBin(const std::vector<double>& sff, double fraction) {
  const size_t kMax = std::max_element(sff.begin() + 1, sff.end()) - sff.begin();
  for (size_t k = kMax; k < sff.size(); ++k)
    if (sff[k] < fraction * sff[kMax]) return k - 1;
  return sff.size() - 1;
}

// True if |H| falls to peak/sqrt(2) on both sides of bin k before exceeding the peak (band bins lo..hi).
bool standsOut(const std::vector<double>& a, size_t k, size_t lo, size_t hi) {
  const double level = a[k] / std::sqrt(2.0);
  auto side = [&](long step) {
    for (long j = static_cast<long>(k) + step; j >= static_cast<long>(lo) && j <= static_cast<long>(hi); j += step) {
      if (a[j] > a[k]) return false;
      if (a[j] <= level) return true;
    }
    return false;
  };
  return side(-1) && side(1);
}

}  // namespace

BandChoice chooseBand(const FrfEstimate& frf, const AutomaticSettingsOptions& o) {
  const auto sff = calcForceAutospectrum(frf);
  const auto coh = calcSmoothedCoherence(frf, o.coherenceWindowBins);
  const size_t nyquistCap = static_cast<size_t>(0.8 * (frf.frequency.size() - 1));
  const size_t forceBin = std::min(findForceLimitBin(sff, o.forceDropFraction), nyquistCap);
  size_t lo = 1;
  while (lo < forceBin && coh[lo] < o.bandCoherence) ++lo;
  size_t hi = forceBin;
  while (hi > lo && coh[hi] < o.bandCoherence) --hi;
  if (hi <= lo + 4 || coh[lo] < o.bandCoherence) {
    char why[160];
    std::snprintf(why, sizeof why, "no usable band: the coherence (median over %d bins) stays below %.3g up to the "
                  "force limit %.6g Hz", o.coherenceWindowBins, o.bandCoherence, frf.frequency[forceBin]);
    throw io::ResultError(why);
  }
  BandChoice b;
  b.fMin = frf.frequency[lo];
  b.fMax = frf.frequency[hi];
  b.forceLimitHz = frf.frequency[forceBin];
  char text[200];
  std::snprintf(text, sizeof text, "%.6g-%.6g Hz (force autospectrum within %.0f dB up to %.6g Hz%s; coherence > %.3g from %.6g to %.6g Hz)",
                b.fMin, b.fMax, -10 * std::log10(o.forceDropFraction), b.forceLimitHz,
                forceBin == nyquistCap ? ", capped at 0.8 Nyquist" : "", o.bandCoherence, b.fMin, b.fMax);
  b.description = text;
  return b;
}

WindowChoice chooseExponentialWindow(const std::vector<ImpactRecord>& hits, const AutomaticSettingsOptions& o) {
  WindowChoice w;
  for (const auto& h : hits)
    for (const auto& x : h.responses) {
      double peak = 0, tail = 0;
      const size_t n = x.size(), start = n - std::max<size_t>(1, n / 10);
      for (double v : x) peak = std::max(peak, std::abs(v));
      for (size_t k = start; k < n; ++k) tail += x[k] * x[k] / (n - start);
      if (peak > 0) w.tail = std::max(w.tail, std::sqrt(tail) / peak);
    }
  w.endValue = w.tail <= o.tailFraction ? 1.0 : std::max(o.minEndValue, o.tailFraction / w.tail);
  char text[200];
  if (w.endValue == 1)
    std::snprintf(text, sizeof text, "none (the responses decay to %.3g %% of their peak by the record end)", 100 * w.tail);
  else
    std::snprintf(text, sizeof text, "exponential, end value %.3g (the responses end at %.3g %% of their peak; aim %.3g %%)",
                  w.endValue, 100 * w.tail, 100 * o.tailFraction);
  w.description = text;
  return w;
}

std::vector<IndicatorPeak> findIndicatorPeaks(const FrfEstimate& frf, double fMin, double fMax,
                                              const AutomaticSettingsOptions& o) {
  const size_t n = frf.frequency.size();
  size_t lo = 1, hi = n - 1;
  while (lo < n && frf.frequency[lo] < fMin) ++lo;
  while (hi > lo && frf.frequency[hi] > fMax) --hi;
  std::vector<IndicatorPeak> all;
  for (size_t c = 0; c < frf.h1.size(); ++c) {
    std::vector<double> a(n);
    double aMax = 0;
    for (size_t k = 0; k < n; ++k) a[k] = std::abs(frf.h1[c][k]);
    for (size_t k = lo; k <= hi; ++k) aMax = std::max(aMax, a[k]);
    for (size_t k = lo + 1; k + 1 <= hi; ++k) {
      if (a[k] < o.peakMinRelative * aMax || a[k] < a[k - 1] || a[k] < a[k + 1]) continue;
      const double coh = std::max({frf.coherence[c][k - 1], frf.coherence[c][k], frf.coherence[c][k + 1]});
      if (coh <= o.peakMinCoherence || !standsOut(a, k, lo, hi)) continue;
      all.push_back({frf.frequency[k], a[k] / aMax, coh, static_cast<int>(c)});
    }
  }
  std::sort(all.begin(), all.end(), [](const auto& x, const auto& y) { return x.frequencyHz < y.frequencyHz; });
  std::vector<IndicatorPeak> merged;
  for (const auto& p : all) {
    if (!merged.empty() && p.frequencyHz - merged.back().frequencyHz <= 3 * frf.df) {
      if (p.relativeAmplitude > merged.back().relativeAmplitude) merged.back() = p;
    } else {
      merged.push_back(p);
    }
  }
  return merged;
}

std::vector<IndicatorPeak> findUnexplainedPeaks(const std::vector<IndicatorPeak>& peaks,
                                                const std::vector<double>& modeFrequenciesHz, double df) {
  std::vector<IndicatorPeak> out;
  for (const auto& p : peaks) {
    bool found = false;
    for (double f : modeFrequenciesHz) found = found || std::abs(f - p.frequencyHz) <= std::max(3 * df, 0.005 * p.frequencyHz);
    if (!found) out.push_back(p);
  }
  return out;
}

OrderChoice chooseOrders(size_t peakCount, size_t bandBins, const AutomaticSettingsOptions& o) {
  const int n = static_cast<int>(peakCount);
  const int cap = std::min<int>(o.maxOrderCap, static_cast<int>(bandBins) - 2);
  OrderChoice c;
  c.maxOrder = std::max(std::min(cap, 4 * n + 24), 2);
  c.minOrder = std::max(2, std::min(std::max(o.minOrder, 2 * n), c.maxOrder));
  return c;
}

}  // namespace motostab::modal
