#pragma once
// Modes from a transient response: fits y_k(t) = c_k + sum_m A_km exp(sigma_m tau) cos(omega_m tau + phi_km),
// tau = t - t0, to one or several sampled signals sharing the same modes (matrix pencil, order selection by
// BIC, variable-projection Levenberg-Marquardt polish on the original samples). See
// docs/response-identification.md.
#include <limits>
#include <vector>

namespace motostab::response {

/// Options of identifyModes(). Times in s.
struct IdentificationOptions {
  double windowStart = -std::numeric_limits<double>::infinity();  ///< s; samples with t < windowStart are ignored
  double windowEnd = std::numeric_limits<double>::infinity();     ///< s; samples with t > windowEnd are ignored
  int maxOrder = 10;        ///< largest model order tried (complex pair counts 2, real exponential 1; offset excluded)
  int fixedOrder = 0;       ///< if > 0, the best candidate of exactly this order instead of order selection
  /// Order selection considers only pencil sizes P (order + offset) at a singular-value gap,
  /// s_{P+1} / s_P < gapRatio (all sizes if there is none), and picks the lowest BIC among them.
  double gapRatio = 0.5;
  bool fitOffset = true;    ///< include a constant offset c_k per signal
  bool polish = true;       ///< refine the poles by nonlinear least squares on the original samples
  int maxPencilSamples = 1500;  ///< cap on the uniform grid for the pencil (a coarser step is used beyond it)
  double uniformTolerance = 1e-6;  ///< relative spread of the time steps below which samples count as uniform
};

/// One identified mode, lambda = real + i imag. A complex pair is reported once, with imag > 0.
struct IdentifiedMode {
  double real = 0;           ///< 1/s (sigma; negative = decaying)
  double imag = 0;           ///< rad/s (omega >= 0; 0 for a real exponential)
  double frequencyHz = 0;    ///< imag / 2 pi, Hz
  double dampingRatio = 0;   ///< -real / |lambda| (+-1 for a real exponential)
  std::vector<double> amplitude;  ///< per signal: A_km >= 0 at tau = 0, signal units
  std::vector<double> phase;      ///< per signal: phi_km, rad (0 or pi for a real exponential)
};

/// One candidate model considered during order selection.
struct OrderCandidate {
  int order = 0;              ///< model order of the fitted poles (complex pair 2, real 1)
  bool offset = false;        ///< fitted with a constant offset (P - 1 poles) or without (P poles)
  int pencilSize = 0;         ///< pencil truncation P (components: poles + offset)
  double singularValueRatio = 0;  ///< s_{P+1} / s_P of the Hankel matrix
  bool atGap = false;         ///< singularValueRatio < gapRatio: eligible for selection
  double rSquared = 0;        ///< coefficient of determination on the window samples
  double criterion = 0;       ///< BIC = n ln(RSS/n) + k ln(n), n = samples x signals, k = free parameters
};

/// Result of identifyModes().
struct IdentificationResult {
  std::vector<IdentifiedMode> modes;   ///< sorted by decreasing contribution (largest peak amplitude first)
  std::vector<double> offset;          ///< per signal: c_k, signal units (0 without fitOffset)
  int order = 0;                       ///< selected order (complex pair 2, real 1; offset excluded)
  double referenceTime = 0;            ///< t0 of tau = t - t0 (first sample in the window), s
  double windowStart = 0, windowEnd = 0;  ///< first and last sample time used, s
  int sampleCount = 0;                 ///< samples in the window (per signal)
  bool resampled = false;              ///< true if the pencil ran on an interpolated uniform grid
  double pencilStep = 0;               ///< uniform step used by the pencil, s
  double rSquared = 0;                 ///< 1 - RSS/TSS over all signals (TSS about each signal's mean)
  std::vector<double> rmsResidual;     ///< per signal, signal units
  std::vector<double> normalisedRmsResidual;  ///< per signal: rms residual / standard deviation of the signal
  std::vector<double> singularValues;  ///< leading singular values of the pencil's Hankel matrix (normalised)
  std::vector<OrderCandidate> candidates;  ///< every order tried, for diagnosis
};

/// Identifies the modes of `signals` (each sampled at `time`, s, strictly increasing, same length) inside
/// the options' window. Throws io::InputError without a location on bad data (lengths, non-increasing
/// time, empty window, too few samples for the order, a constant signal: the caller names the source),
/// io::ResultError when no model fits the window.
IdentificationResult identifyModes(const std::vector<double>& time, const std::vector<std::vector<double>>& signals,
                                   const IdentificationOptions& options = {});

/// The fitted model of signal `signalIndex` at times `time` (s), signal units.
std::vector<double> calcModelResponse(const IdentificationResult& result, int signalIndex,
                                      const std::vector<double>& time);

}  // namespace motostab::response
