#pragma once
// Axes of the eigenvalue plots fitted to the modes an engineer reads (weave, wobble, capsize, castor):
// roots much faster than those leave the axes and the legend says how many and how fast
// (docs/commands.md, "Plots").
#include <complex>
#include <string>
#include <vector>

#include "analysis/modes.h"

namespace motostab::output {

/// Fraction of the named points' span added on each side of an axis.
constexpr double kPlotMargin = 0.08;

/// A closed interval [lo, hi] of one axis.
struct AxisRange {
  double lo = 0, hi = 0;
  bool contains(double x) const { return x >= lo && x <= hi; }
};

/// The values' range with 0 included, widened by kPlotMargin of its span on each side (by 0.5 each
/// side when the span is zero). `values` must not be empty; non-finite values are skipped.
AxisRange calcAxisRange(const std::vector<double>& values);

/// A root-locus window: real part (1/s) across, frequency imag/2pi (Hz, upper half-plane) up.
struct LocusWindow {
  AxisRange real;       ///< 1/s: the named points' real parts and 0, with margins
  AxisRange frequency;  ///< Hz: from a margin below 0 to the named points' largest frequency plus its margin
  bool contains(std::complex<double> lambda) const;
};

/// Roots left off a plot's axes: how many, and how far out they reach.
struct HiddenRoots {
  int count = 0;  ///< roots with at least one point outside the axes
  double realMin = 0, realMax = 0;  ///< extremes of the real parts of those outside points (1/s)
  double frequencyMax = 0;          ///< largest frequency of those outside points (Hz)
};

/// The legend note of a root locus, e.g. "3 roots off the axes (real part down to -6e+04 1/s)";
/// empty when no root is hidden.
std::string formatLocusNote(const HiddenRoots& hidden);

/// The legend note of a real-part plot: "2 other roots off the axes (real part down to -812 1/s)".
std::string formatRealPartNote(const HiddenRoots& hidden);

/// The window fitted to `named`: the eigenvalues (1/s) of the modes of interest, upper members of
/// pairs and real roots (imag >= 0). Empty `named`: a window of [-1, 1] 1/s x [0, 1] Hz.
LocusWindow calcLocusWindow(const std::vector<std::complex<double>>& named);

/// The roots among `roots` (each a root's eigenvalue at every speed, 1/s) with a point of
/// non-negative imaginary part outside `window`.
HiddenRoots findHiddenRoots(const LocusWindow& window, const std::vector<std::vector<std::complex<double>>>& roots);

/// The eigenvalues of `branches` whose label at their speed is one of `modes`, imag >= 0 (the points
/// a root locus of those modes draws).
std::vector<std::complex<double>> collectNamedPoints(const std::vector<analysis::ModeBranch>& branches,
                                                     const std::vector<analysis::ModeLabel>& modes);

/// Each branch's eigenvalues at the speeds where its label is none of `modes` (empty when it is one
/// at every speed): the roots a locus draws as "other roots".
std::vector<std::vector<std::complex<double>>> collectOtherRoots(const std::vector<analysis::ModeBranch>& branches,
                                                                 const std::vector<analysis::ModeLabel>& modes);

/// The roots among `roots` (each a root's eigenvalue at every speed, 1/s) whose real part leaves
/// `range` at some speed (a real-part plot's vertical axis).
HiddenRoots findHiddenRealParts(const AxisRange& range, const std::vector<std::vector<std::complex<double>>>& roots);

/// "  set AXISrange [lo:hi]\n" (17 significant digits); axis "x", "y", "cb", ...
std::string formatRange(const std::string& axis, const AxisRange& range);

/// "  set xrange [..]\n  set yrange [..]\n" of a locus window (17 significant digits).
std::string formatLocusRanges(const LocusWindow& window);

}  // namespace motostab::output
