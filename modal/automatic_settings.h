#pragma once
// Analysis settings read off the data, so that LSCF runs on a hammer test nobody tuned for:
//  - the band: where the hammer put energy in (force autospectrum within `forceDropFraction` of its
//    maximum, -20 dB by default) and the FRF is trustworthy (coherence, median over a sliding window,
//    above `bandCoherence`);
//  - the mode indicator peaks in that band: a local maximum of |H| of any channel, at least
//    `peakMinRelative` of that channel's largest peak, with coherence above `peakMinCoherence` and
//    standing out of its flanks by the half-power ratio (|H| falls below peak/sqrt(2) on both sides
//    before rising above the peak), peaks of different channels within 3 bins merged;
//  - the model orders swept in the stabilisation diagram, from the number of peaks: an LSCF model of
//    order p has p poles, i.e. p/2 modes, so 2 n_peaks is the least order that can hold every peak;
//    the sweep runs to 4 n_peaks + 24 (computational poles absorb noise, leakage and out-of-band modes).
//  - the exponential window: none if every response has died out by the end of the record (RMS of the
//    last 10 % below `tailFraction` of the channel's peak), else just strong enough to bring that tail
//    down to `tailFraction` (end value tailFraction / tail, at least minEndValue): every window adds
//    damping that must be subtracted again, which lightly damped modes cannot afford.
// Which poles become modes is left to the stabilisation diagram (modal/lscf.h).
// References: Peeters et al. (2004) "The PolyMAX frequency-domain method", Shock Vib. 11, 395-409
// (stabilisation diagram); Ewins (2000) "Modal testing", sec. 3.9 (hammer spectrum, coherence).
#include <string>
#include <vector>

#include "modal/spectra.h"

namespace motostab::modal {

/// Thresholds of the automatic choices.
struct AutomaticSettingsOptions {
  double forceDropFraction = 0.01;  ///< force autospectrum / its maximum below which the band ends (power ratio)
  double bandCoherence = 0.9;       ///< sliding-median coherence needed inside the band
  int coherenceWindowBins = 21;     ///< width of that median window, bins
  double peakMinRelative = 0.01;    ///< |H| at a peak / the channel's largest peak in the band
  double peakMinCoherence = 0.99;   ///< coherence at a peak (best of the peak bin and its neighbours)
  double tailFraction = 0.01;       ///< response RMS over the last 10 % of a record / its peak, aimed at
  double minEndValue = 0.05;        ///< strongest exponential window used (value at the record end)
  int minOrder = 4;                 ///< least order swept
  int maxOrderCap = 160;            ///< largest order ever swept
};

/// The band and why it ends where it does.
struct BandChoice {
  double fMin = 0, fMax = 0;     ///< Hz
  double forceLimitHz = 0;       ///< where the force autospectrum leaves the -20 dB range
  std::string description;       ///< e.g. "12-380 Hz (force -20 dB at 380 Hz; coherence > 0.9 from 12 Hz)"
};

/// A peak of the mode indicator.
struct IndicatorPeak {
  double frequencyHz = 0;    ///< bin frequency of the local maximum, Hz
  double relativeAmplitude = 0;  ///< |H| / the channel's largest peak |H| in the band
  double coherence = 0;      ///< best coherence of the peak bin and its two neighbours
  int channel = 0;           ///< the channel where the peak is largest relative to that channel
};

/// The exponential window and why.
struct WindowChoice {
  double endValue = 1;      ///< window value at the record end (1 = no window)
  double tail = 0;          ///< largest (RMS of the last 10 % of a record) / (peak |x|) over hits and channels
  std::string description;  ///< e.g. "none (responses decay to 0.2 % of their peak by the record end)"
};

/// Model orders of the stabilisation diagram.
struct OrderChoice {
  int minOrder = 4, maxOrder = 40;
};

/// Band from the data (see the file comment). Throws io::ResultError if no bin qualifies.
BandChoice chooseBand(const FrfEstimate& frf, const AutomaticSettingsOptions& options = {});

/// Exponential window from the responses (see the file comment).
WindowChoice chooseExponentialWindow(const std::vector<ImpactRecord>& hits, const AutomaticSettingsOptions& options = {});

/// Mode indicator peaks in [fMin, fMax] (see the file comment), ascending in frequency.
std::vector<IndicatorPeak> findIndicatorPeaks(const FrfEstimate& frf, double fMin, double fMax,
                                              const AutomaticSettingsOptions& options = {});

/// The peaks with no entry of `modeFrequenciesHz` within max(3 df, 0.5 %) of their frequency.
std::vector<IndicatorPeak> findUnexplainedPeaks(const std::vector<IndicatorPeak>& peaks,
                                                const std::vector<double>& modeFrequenciesHz, double df);

/// Orders 2 n_peaks .. 4 n_peaks + 24 (at least options.minOrder, at most maxOrderCap and the number of
/// band bins minus 2, which LSCF needs).
OrderChoice chooseOrders(size_t peakCount, size_t bandBins, const AutomaticSettingsOptions& options = {});

}  // namespace motostab::modal
