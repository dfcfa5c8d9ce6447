#pragma once
// Half-power (-3 dB) peak picking: a quick first estimate of natural frequencies and damping.
#include <complex>
#include <vector>

namespace motostab::modal {

/// A peak of a mode indicator with its half-power damping estimate.
struct PeakEstimate {
  double frequencyHz = 0;  ///< peak frequency (parabolic interpolation), Hz
  double dampingRatio = 0; ///< (f2 - f1)/(2 f0), window decay removed; NaN if a half-power point is not found
  double lossFactor = 0;   ///< hysteretic loss factor = 2 * dampingRatio
  double peakValue = 0;    ///< indicator value at the peak
};

/// Mode indicator: sum over channels of |H|^2 at every bin (a single FRF gives |H|^2).
std::vector<double> calcPowerIndicator(const std::vector<std::vector<std::complex<double>>>& h);

/// Peaks of `indicator` (a power quantity such as |H|^2) in [fMin, fMax]: local maxima over +/- halfWidth
/// bins at least minRelative times the band maximum. Half-power points (indicator = peak/2) are
/// interpolated linearly; windowDecayRate (1/s) from an exponential window is removed:
/// zeta = (f2 - f1)/(2 f0) - sigma_w/(2 pi f0).
std::vector<PeakEstimate> findHalfPowerPeaks(const std::vector<double>& frequency, const std::vector<double>& indicator,
                                             double fMin, double fMax, double windowDecayRate = 0,
                                             double minRelative = 1e-3, int halfWidth = 3);

}  // namespace motostab::modal
