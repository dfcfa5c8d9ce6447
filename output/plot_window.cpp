#include "output/plot_window.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "io/number.h"

namespace motostab::output {

using analysis::ModeBranch;
using analysis::ModeLabel;
using io::formatNumber;

namespace {

double toHz(std::complex<double> l) { return l.imag() / (2 * M_PI); }

bool isNamed(ModeLabel label, const std::vector<ModeLabel>& modes) {
  return std::find(modes.begin(), modes.end(), label) != modes.end();
}

// A number for a legend: 3 significant digits.
std::string formatShort(double x) { return formatNumber(x, 3); }

}  // namespace

AxisRange calcAxisRange(const std::vector<double>& values) {
  AxisRange r;  // 0 is in every range: the stability boundary, or the real axis
  for (double v : values)
    if (std::isfinite(v)) r.lo = std::min(r.lo, v), r.hi = std::max(r.hi, v);
  const double pad = r.hi > r.lo ? kPlotMargin * (r.hi - r.lo) : 0.5;
  return {r.lo - pad, r.hi + pad};
}

bool LocusWindow::contains(std::complex<double> lambda) const {
  return real.contains(lambda.real()) && frequency.contains(toHz(lambda));
}

LocusWindow calcLocusWindow(const std::vector<std::complex<double>>& named) {
  std::vector<double> re, hz;
  for (const auto& l : named) re.push_back(l.real()), hz.push_back(toHz(l));
  LocusWindow w;
  w.real = calcAxisRange(re);
  double top = 0;
  for (double f : hz)
    if (std::isfinite(f)) top = std::max(top, f);
  if (top <= 0) top = 1 / (1 + kPlotMargin);  // real roots only: 1 Hz of room above the real axis
  w.frequency = {-kPlotMargin * top, (1 + kPlotMargin) * top};
  return w;
}

HiddenRoots findHiddenRoots(const LocusWindow& window, const std::vector<std::vector<std::complex<double>>>& roots) {
  HiddenRoots h;
  h.realMin = std::numeric_limits<double>::infinity(), h.realMax = h.frequencyMax = -h.realMin;
  for (const auto& root : roots) {
    bool out = false;
    for (const auto& l : root) {
      if (l.imag() < 0 || !std::isfinite(l.real()) || window.contains(l)) continue;
      out = true;
      h.realMin = std::min(h.realMin, l.real()), h.realMax = std::max(h.realMax, l.real());
      h.frequencyMax = std::max(h.frequencyMax, toHz(l));
    }
    h.count += out;
  }
  return h;
}

HiddenRoots findHiddenRealParts(const AxisRange& range, const std::vector<std::vector<std::complex<double>>>& roots) {
  HiddenRoots h;
  h.realMin = std::numeric_limits<double>::infinity(), h.realMax = -h.realMin;
  for (const auto& root : roots) {
    bool out = false;
    for (const auto& l : root) {
      if (!std::isfinite(l.real()) || range.contains(l.real())) continue;
      out = true;
      h.realMin = std::min(h.realMin, l.real()), h.realMax = std::max(h.realMax, l.real());
    }
    h.count += out;
  }
  return h;
}

namespace {

std::string countRoots(int n, const std::string& what) {
  return std::to_string(n) + (what.empty() ? "" : " " + what) + (n == 1 ? " root" : " roots") + " off the axes";
}

}  // namespace

std::string formatLocusNote(const HiddenRoots& h) {
  if (h.count == 0) return "";
  std::string reach = h.realMin <= h.realMax ? "real part " + formatShort(h.realMin) + " to " + formatShort(h.realMax) + " 1/s" : "";
  if (h.frequencyMax > 0) reach += (reach.empty() ? "" : ", ") + std::string("frequency up to ") + formatShort(h.frequencyMax) + " Hz";
  return countRoots(h.count, "") + (reach.empty() ? "" : " (" + reach + ")");
}

std::string formatRealPartNote(const HiddenRoots& h) {
  if (h.count == 0) return "";
  return countRoots(h.count, "other") + " (real part " + formatShort(h.realMin) + " to " + formatShort(h.realMax) + " 1/s)";
}

std::vector<std::complex<double>> collectNamedPoints(const std::vector<ModeBranch>& branches, const std::vector<ModeLabel>& modes) {
  std::vector<std::complex<double>> out;
  for (const ModeBranch& b : branches)
    for (size_t k = 0; k < b.eigenvalue.size() && k < b.labels.size(); ++k)
      if (b.eigenvalue[k].imag() >= 0 && isNamed(b.labels[k], modes)) out.push_back(b.eigenvalue[k]);
  return out;
}

std::vector<std::vector<std::complex<double>>> collectOtherRoots(const std::vector<ModeBranch>& branches,
                                                                 const std::vector<ModeLabel>& modes) {
  std::vector<std::vector<std::complex<double>>> out;
  for (const ModeBranch& b : branches) {
    std::vector<std::complex<double>> root;
    for (size_t k = 0; k < b.eigenvalue.size() && k < b.labels.size(); ++k)
      if (!isNamed(b.labels[k], modes)) root.push_back(b.eigenvalue[k]);
    if (!root.empty()) out.push_back(root);
  }
  return out;
}

std::string formatRange(const std::string& axis, const AxisRange& range) {
  std::ostringstream os;
  os << std::setprecision(17) << "  set " << axis << "range [" << range.lo << ":" << range.hi << "]\n";
  return os.str();
}

std::string formatLocusRanges(const LocusWindow& w) { return formatRange("x", w.real) + formatRange("y", w.frequency); }

}  // namespace motostab::output
