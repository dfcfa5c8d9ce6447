#pragma once
// Impact-test signal processing: hit checks, force and exponential windows, FFTW spectra, H1 and coherence.
#include <complex>
#include <string>
#include <vector>

namespace motostab::modal {

/// One hammer hit: uniformly sampled force and responses (one vector per channel, same length).
struct ImpactRecord {
  double dt = 0;                               ///< sampling interval, s
  std::vector<double> force;                   ///< N
  std::vector<std::vector<double>> responses;  ///< [channel][sample], e.g. m/s^2
};

/// Thresholds for hit checks (fractions are of the force peak).
struct HitCheckOptions {
  double pulseEdgeFraction = 0.02;  ///< the pulse starts/ends where |force| falls below this
  double doubleHitFraction = 0.10;  ///< |force| above this after the pulse is a double hit
  double forceRange = 0;            ///< N; readings at or above it are an overload (0: not given)
  double responseRange = 0;         ///< response units; same (0: not given)
  int clipRun = 3;                  ///< this many consecutive samples at the channel's extreme = clipped
};

/// Where the pulse is and what is wrong with the hit (empty `problems` = usable).
struct HitCheck {
  size_t peakIndex = 0, pulseStart = 0, pulseEnd = 0;  ///< sample indices; pulseEnd is exclusive
  double peakForce = 0;                                ///< N, signed
  std::vector<std::string> problems;                   ///< "double hit at 0.123 s", "overload on A2", ...
};

/// Finds the force pulse and detects double hits (a second pulse after the first) and overloads
/// (readings at the stated range, or a flat top of `clipRun` samples at a channel's extreme).
HitCheck checkHit(const ImpactRecord& hit, const HitCheckOptions& options = {});

/// Windowing of impact records (applied to force and responses alike, except the force window).
struct WindowOptions {
  bool forceWindow = true;          ///< zero the force outside the pulse (cosine taper of one pulse width)
  double exponentialEndValue = 1;   ///< exponential window value at the record end (1 = no window)
};

/// Force window for a pulse [start, end): 1 from one pulse width before to one after, then a cosine
/// taper of one pulse width (at least 2 samples), 0 elsewhere.
std::vector<double> calcForceWindow(size_t n, size_t pulseStart, size_t pulseEnd);

/// Decay rate (1/s) that an exponential window exp(-t/tau) ending at `endValue` after `duration` s adds
/// to every pole: sigma_w = ln(1/endValue)/duration. The true pole is lambda_measured + sigma_w.
double calcExponentialDecayRate(double duration, double endValue);

/// Averaged single-input FRF estimate.
struct FrfEstimate {
  double df = 0;                                           ///< Hz
  std::vector<double> frequency;                           ///< Hz, bins 0..N/2
  std::vector<std::vector<std::complex<double>>> h1;       ///< [channel][bin], response/force
  std::vector<std::vector<double>> coherence;              ///< [channel][bin], 0..1
  int averages = 0;                                        ///< hits averaged
  double windowDecayRate = 0;                              ///< 1/s added by the exponential window
  /// Per-hit spectra kept for resampling (jackknife): F[hit][bin], X[hit][channel][bin].
  std::vector<std::vector<std::complex<double>>> forceSpectra;
  std::vector<std::vector<std::vector<std::complex<double>>>> responseSpectra;
};

/// Real-to-complex DFT (FFTW) of a real sequence: bins 0..N/2, unscaled.
std::vector<std::complex<double>> calcRealDft(const std::vector<double>& x);

/// H1 = S_fx / S_ff and coherence |S_fx|^2/(S_ff S_xx) averaged over hits, after windowing.
/// All hits must have the same length, dt and channel count (std::logic_error otherwise: the readers check them).
FrfEstimate estimateH1(const std::vector<ImpactRecord>& hits, const WindowOptions& window = {});

/// H1 and coherence from the kept per-hit spectra of `estimate`, using only hits with use[i] true
/// (for leave-one-out resampling).
void calcH1FromSpectra(const FrfEstimate& estimate, const std::vector<bool>& use,
                       std::vector<std::vector<std::complex<double>>>& h1,
                       std::vector<std::vector<double>>* coherence = nullptr);

}  // namespace motostab::modal
