#include "swingarm/identification/frf_diagnosis.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "io/csv.h"
#include "io/result_error.h"

namespace motostab::swingarm::identification {

using io::ResultError;
using io::formatNumber;

namespace {

std::string fmt(double v, int digits = 6) { return formatNumber(v, digits); }

std::string describePeak(const modal::IndicatorPeak& p) {
  char s[120];
  std::snprintf(s, sizeof s, "%.6g Hz (%.3g %% of the largest peak, coherence %.4f)", p.frequencyHz,
                100 * p.relativeAmplitude, p.coherence);
  return s;
}

std::string listModes(const FrfResult& r) {
  std::string s;
  for (const auto& m : r.modes) {
    char b[120];
    if (m.hasAxis)
      std::snprintf(b, sizeof b, "%.6g Hz (axis beta %.1f deg)", m.frequencyHz, m.axis.betaDeg);
    else
      std::snprintf(b, sizeof b, "%.6g Hz (no axis)", m.frequencyHz);
    s += (s.empty() ? "" : ", ") + std::string(b);
  }
  return s.empty() ? "none" : s;
}

// Indicator peaks not explained by any identified mode (within max(3 bins, 0.5 %)).
std::vector<modal::IndicatorPeak> findUnexplainedPeaks(const FrfResult& r) {
  std::vector<double> f;
  for (const auto& m : r.modes) f.push_back(m.frequencyHz);
  return modal::findUnexplainedPeaks(r.indicatorPeaks, f, r.frf.df);
}

// Channel position farthest from the force point along x (bending: axis roughly along z) or z (torsion).
const FrfChannel* findFarthestChannel(const FrfTest& t, bool alongX) {
  const FrfChannel* best = nullptr;
  auto d = [&](const FrfChannel& c) {
    return alongX ? std::abs(c.position.x - t.forcePoint.x) : std::abs(c.position.z - t.forcePoint.z);
  };
  for (const auto& c : t.channels)
    if (!best || d(c) > d(*best)) best = &c;
  return best;
}

// Which mode is missing, why, and where to hit (the lever of the hit about the missing axis is too short).
std::string describeMissingMode(const FrfTest& t, const FrfResult& r, bool bending) {
  const char* name = bending ? "bending" : "torsion";
  std::ostringstream s;
  s << name << " mode not found: no identified mode has a modal axis within 45 deg of "
    << (bending ? "the normal to x" : "x") << " (modes found: " << listModes(r) << "). ";
  const auto unexplained = findUnexplainedPeaks(r);
  if (!unexplained.empty()) {
    s << "Indicator peaks without a stable mode: ";
    for (size_t i = 0; i < unexplained.size(); ++i) s << (i ? ", " : "") << describePeak(unexplained[i]);
    s << "; try processing.model_order or a processing.band_hz around them. ";
  } else {
    s << "The mode indicator shows no other peak of at least 1 % of the largest with coherence > 0.99 in "
      << fmt(r.options.fMin) << "-" << fmt(r.options.fMax) << " Hz: the hit at (x, z) = (" << fmt(t.forcePoint.x)
      << ", " << fmt(t.forcePoint.z) << ") m lies too close to the " << name << " axis to excite it. ";
  }
  const FrfChannel* c = findFarthestChannel(t, bending);
  s << "Hit farther from the " << name << " axis (" << (bending ? "it runs roughly along z, so move along x"
                                                               : "it runs roughly along x, so move along z");
  if (c) s << ", e.g. near channel " << c->name << " at (" << fmt(c->position.x) << ", " << fmt(c->position.z) << ") m";
  s << "), or give processing." << name << "_mode_hz if you know its frequency.";
  return s.str();
}

}  // namespace

void diagnoseFrf(const FrfTest& t, FrfResult& r) {
  for (const auto& c : r.rejectedClusters)
    if (static_cast<size_t>(c.count) >= modal::calcRequiredStableOrders(r.options))
      r.diagnostics.push_back("poles at " + fmt(c.frequencyHz) + " Hz are stable at " + std::to_string(c.count) +
                              " orders but their damping ratio after removing the exponential window (" +
                              fmt(c.dampingRatio, 3) + ") is not positive: the damping is below what the record "
                              "resolves; dropped (a longer record or processing.exponential_end_value nearer 1 helps)");
  for (const auto& p : findUnexplainedPeaks(r))
    r.diagnostics.push_back("indicator peak at " + describePeak(p) + " has no stable mode (orders " +
                            std::to_string(r.options.minOrder) + "-" + std::to_string(r.options.maxOrder) +
                            "); try a narrower processing.band_hz around it or a higher processing.model_order");
  if (t.channels.size() < 3 || r.modes.empty()) return;
  if (r.bendingIndex < 0) r.diagnostics.push_back(describeMissingMode(t, r, true));
  if (r.torsionIndex < 0) r.diagnostics.push_back(describeMissingMode(t, r, false));
}

std::string describeFrfAttempt(const FrfResult& r) {
  std::ostringstream s;
  s << r.frf.averages << " hits averaged (" << r.rejectedHits.size() << " rejected); window " << r.window.description
    << "; band " << r.band.description
    << (r.automaticBand ? " [automatic]" : "") << "; model orders " << r.options.minOrder << "-" << r.options.maxOrder
    << " (" << r.orderReason << "); " << r.indicatorPeaks.size()
    << " mode indicator peaks (>= 1 % of the largest, coherence > 0.99)";
  for (size_t i = 0; i < r.indicatorPeaks.size(); ++i) s << (i ? ", " : ": ") << fmt(r.indicatorPeaks[i].frequencyHz) << " Hz";
  s << "; " << r.rejectedClusters.size() << " clusters of stable poles at fewer than "
    << modal::calcRequiredStableOrders(r.options) << " orders";
  for (size_t i = 0; i < r.rejectedClusters.size() && i < 8; ++i)
    s << (i ? ", " : ": ") << fmt(r.rejectedClusters[i].frequencyHz) << " Hz (" << r.rejectedClusters[i].count << ")";
  return s.str();
}

std::string suggestFrfSettings(const FrfResult& r) {
  std::ostringstream s;
  s << "What to set (under processing: in the test YAML): band_hz: [low, high] around the resonances you see in "
       "frf.csv (the force spectrum must still be within -20 dB and the coherence > 0.9 there); "
       "model_order: [min, max] with max well above twice the number of modes in the band (e.g. [10, 80]); "
       "if the coherence is low, check the hits (frf/coherence.png) or hit harder/closer to a sensor.";
  if (!r.rejectedClusters.empty()) s << " Clusters stable at too few orders may become modes with a wider order range.";
  return s.str();
}

std::string formatStabilisationSummary(const FrfResult& r) {
  std::map<int, std::pair<int, int>> perOrder;  // order -> (poles, stable in frequency and damping)
  for (const auto& p : r.diagram) {
    perOrder[p.order].first++;
    perOrder[p.order].second += p.stableDamping;
  }
  std::ostringstream s;
  s << "stabilisation (band " << fmt(r.options.fMin) << "-" << fmt(r.options.fMax) << " Hz, orders "
    << r.options.minOrder << "-" << r.options.maxOrder << ", a mode needs " << modal::calcRequiredStableOrders(r.options)
    << " stable orders):\n  order: poles/stable";
  int i = 0;
  for (const auto& [order, c] : perOrder) s << (i++ % 10 ? "  " : "\n   ") << order << ": " << c.first << "/" << c.second;
  s << "\n";
  for (const auto& m : r.modes)
    s << "  mode    " << fmt(m.frequencyHz) << " Hz stable at " << m.stableCount << " orders\n";
  size_t few = 0;
  for (const auto& c : r.rejectedClusters) {
    if (c.count < 3) {
      ++few;
      continue;
    }
    s << "  dropped " << fmt(c.frequencyHz) << " Hz stable at " << c.count << " orders"
      << (c.dampingRatio <= 0 ? " (damping ratio <= 0)" : "") << "\n";
  }
  if (few) s << "  dropped " << few << " more clusters stable at 1 or 2 orders\n";
  for (const auto& p : r.indicatorPeaks) s << "  indicator peak " << describePeak(p) << "\n";
  return s.str();
}

void requireModes(const FrfResult& r) {
  if (!r.modes.empty()) return;
  throw ResultError("no mode identified. Tried: " + describeFrfAttempt(r) + ". " + suggestFrfSettings(r));
}

void requireBendingAndTorsion(const FrfResult& r) {
  if (r.bendingIndex >= 0 && r.torsionIndex >= 0) return;
  std::string s = "the hammer test did not give both a bending and a torsion mode.";
  for (const auto& d : r.diagnostics) s += "\n  " + d;
  throw ResultError(s + "\n  Tried: " + describeFrfAttempt(r));
}

}  // namespace motostab::swingarm::identification
