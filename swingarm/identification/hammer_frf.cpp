// Identification of a hammer test: hit screening, H1, LSCF stabilisation, modes, modal axes and labels.
#include "swingarm/identification/hammer_frf.h"

#include <cmath>
#include <limits>

#include "io/csv.h"
#include "io/input_error.h"
#include "io/result_error.h"
#include "swingarm/identification/frf_diagnosis.h"
#include "swingarm/identification/yaml_input.h"

namespace motostab::swingarm::identification {

using io::InputError;
using io::formatNumber;
namespace {

using cd = std::complex<double>;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// Real shape of a complex ODS: its quadrature part Im(u) (the resonant response lags the force by 90 deg,
// while the off-resonance response of the other modes is nearly in phase), and the modal phase
// collinearity MPC = ((l1 - l2)/(l1 + l2))^2 of [Re u, Im u] as a quality figure.
Eigen::VectorXd calcRealShape(const std::vector<cd>& u, double* mpc) {
  const int n = static_cast<int>(u.size());
  Eigen::MatrixXd ab(n, 2);
  for (int i = 0; i < n; ++i) ab(i, 0) = u[i].real(), ab(i, 1) = u[i].imag();
  if (mpc) {
    const Eigen::Vector2d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(ab.transpose() * ab).eigenvalues();
    *mpc = (l[0] + l[1]) > 0 ? std::pow((l[1] - l[0]) / (l[1] + l[0]), 2) : 0.0;
  }
  return ab.col(1);
}

size_t getNearestBin(const modal::FrfEstimate& frf, double f) {
  return std::min(frf.frequency.size() - 1, static_cast<size_t>(std::lround(f / frf.df)));
}

std::vector<cd> getOds(const std::vector<std::vector<cd>>& h, size_t bin) {
  std::vector<cd> u;
  for (const auto& c : h) u.push_back(c[bin]);
  return u;
}

// Stage 1: hit checks (double hit, overload: rejected, with the reason).
std::vector<modal::ImpactRecord> screenHits(const FrfTest& test, const std::vector<modal::ImpactRecord>& hits,
                                            FrfResult& res) {
  modal::HitCheckOptions hc;
  hc.doubleHitFraction = test.doubleHitFraction;
  hc.forceRange = test.forceRange;
  hc.responseRange = test.responseRange;
  std::vector<modal::ImpactRecord> good;
  for (size_t i = 0; i < hits.size(); ++i) {
    const auto c = modal::checkHit(hits[i], hc);
    if (c.problems.empty()) {
      good.push_back(hits[i]);
      res.usedHits.push_back(test.hits[i].string());
    } else {
      std::string why;
      for (const auto& p : c.problems) why += (why.empty() ? "" : "; ") + p;
      res.rejectedHits.push_back(test.hits[i].string() + ": " + why);
    }
  }
  if (good.empty()) throw InputError({test.file.string(), 0, 0, "hits"}, "every hit was rejected: " + res.rejectedHits[0]);
  return good;
}

size_t countBins(const modal::FrfEstimate& frf, double fMin, double fMax) {
  size_t n = 0;
  for (double f : frf.frequency) n += f >= fMin && f <= fMax && f > 0;
  return n;
}

// Stage 3: band (processing.band_hz or from the data), indicator peaks, orders (processing.model_order or
// from the peak count).
void chooseLscfOptions(const FrfTest& test, FrfResult& res) {
  const auto& frf = res.frf;
  auto& o = res.options;
  res.automaticBand = test.bandMinHz == 0 && test.bandMaxHz == 0;
  if (res.automaticBand) {
    try {
      res.band = modal::chooseBand(frf);
    } catch (const io::ResultError& e) {  // no usable band: analyse the whole record, say why
      res.band.fMin = 5 * frf.df;
      res.band.fMax = 0.8 * frf.frequency.back();
      res.band.description = formatNumber(res.band.fMin, 6) + "-" + formatNumber(res.band.fMax, 6) +
                             " Hz (5 bins to 0.8 Nyquist: " + e.what() + ")";
    }
  } else {
    res.band.fMin = test.bandMinHz;
    res.band.fMax = std::min(test.bandMaxHz, frf.frequency.back());
    res.band.description = formatNumber(res.band.fMin, 6) + "-" + formatNumber(res.band.fMax, 6) + " Hz (processing.band_hz)";
  }
  o.fMin = res.band.fMin;
  o.fMax = res.band.fMax;
  o.windowDecayRate = frf.windowDecayRate;
  res.indicatorPeaks = modal::findIndicatorPeaks(frf, o.fMin, o.fMax);
  res.automaticOrders = test.minOrder == 0 && test.maxOrder == 0;
  if (res.automaticOrders) {
    const auto c = modal::chooseOrders(res.indicatorPeaks.size(), countBins(frf, o.fMin, o.fMax));
    o.minOrder = c.minOrder, o.maxOrder = c.maxOrder;
    res.orderReason = "automatic: " + std::to_string(res.indicatorPeaks.size()) +
                      " indicator peaks n -> orders max(4, 2n) .. 4n + 24";
  } else {
    o.minOrder = test.minOrder, o.maxOrder = test.maxOrder;
    res.orderReason = "processing.model_order";
  }
}

// Indicator peaks with no selected mode within max(3 bins, 0.5 %).
std::vector<modal::IndicatorPeak> findUnmatchedPeaks(const FrfResult& res, const std::vector<modal::ModalEstimate>& modes) {
  std::vector<double> f;
  for (const auto& m : modes) f.push_back(m.frequencyHz);
  return modal::findUnexplainedPeaks(res.indicatorPeaks, f, res.frf.df);
}

// Stage 4: stabilisation diagram and stable-mode selection. With automatic orders, when indicator peaks
// are left without a stable mode the sweep is extended once to twice the highest order; the diagram with
// fewer unexplained peaks is kept.
std::vector<modal::ModalEstimate> runStabilisation(FrfResult& res) {
  auto run = [&](const modal::LscfOptions& o, std::vector<modal::StabilisationPole>& diagram,
                 std::vector<modal::ModalEstimate>& rejected) {
    diagram = modal::calcStabilisationDiagram(modal::LscfEstimator(res.frf.frequency, res.frf.h1, o));
    rejected.clear();
    return modal::selectStableModes(diagram, o, &rejected);
  };
  auto modes = run(res.options, res.diagram, res.rejectedClusters);
  const size_t unmatched = findUnmatchedPeaks(res, modes).size();
  const int cap = std::min(modal::AutomaticSettingsOptions().maxOrderCap,
                           static_cast<int>(countBins(res.frf, res.options.fMin, res.options.fMax)) - 2);
  if (!res.automaticOrders || unmatched == 0 || res.options.maxOrder >= cap) return modes;
  modal::LscfOptions wider = res.options;
  wider.maxOrder = std::min(cap, 2 * res.options.maxOrder);
  std::vector<modal::StabilisationPole> diagram;
  std::vector<modal::ModalEstimate> rejected;
  auto more = run(wider, diagram, rejected);
  if (findUnmatchedPeaks(res, more).size() >= unmatched) return modes;
  res.options = wider;
  res.diagram = std::move(diagram);
  res.rejectedClusters = std::move(rejected);
  res.orderReason += "; extended to " + std::to_string(wider.maxOrder) + " for peaks without a stable mode";
  return more;
}

// Stage 5: values and uncertainties of one mode (jackknife over hits combined with the scatter over orders),
// its half-power estimate and the lowest channel coherence at the resonance bin.
ModeResult makeModeResult(const FrfResult& res, const modal::ModalEstimate& e, std::pair<double, double> jack) {
  const auto& frf = res.frf;
  ModeResult m;
  m.frequencyHz = e.frequencyHz;
  m.dampingRatio = e.dampingRatio;
  m.frequencyStderrHz = std::hypot(std::isnan(jack.first) ? 0.0 : jack.first, e.frequencyScatterHz);
  m.dampingStderr = std::hypot(std::isnan(jack.second) ? 0.0 : jack.second, e.dampingScatter);
  m.lossFactor = 2 * m.dampingRatio;
  m.lossFactorStderr = 2 * m.dampingStderr;
  m.order = e.order;
  m.stableCount = e.count;
  m.halfPowerFrequencyHz = m.halfPowerDampingRatio = kNaN;
  const size_t peakBin = getNearestBin(frf, e.rawLambda.imag() / (2 * M_PI));
  m.coherence = 1;
  for (const auto& c : frf.coherence) m.coherence = std::min(m.coherence, c[peakBin]);
  for (const auto& p : res.peaks)
    if (std::abs(p.frequencyHz - m.frequencyHz) < 3 * frf.df &&
        (std::isnan(m.halfPowerFrequencyHz) ||
         std::abs(p.frequencyHz - m.frequencyHz) < std::abs(m.halfPowerFrequencyHz - m.frequencyHz)))
      m.halfPowerFrequencyHz = p.frequencyHz, m.halfPowerDampingRatio = p.dampingRatio;
  return m;
}

// Complex shape of mode i at the channels from FRFs h: the ODS at the resonance bin, or the residues of the
// modal model (LSFD with all identified poles, so neighbouring modes are removed).
std::vector<cd> calcModeShape(const FrfTest& test, const FrfResult& res, const std::vector<std::vector<cd>>& h,
                              const std::vector<cd>& rawPoles, size_t i) {
  if (!test.axesFromModalModel) return getOds(h, getNearestBin(res.frf, rawPoles[i].imag() / (2 * M_PI)));
  std::vector<cd> u;
  for (const auto& hc : h)
    u.push_back(modal::fitModalModel(res.frf.frequency, hc, res.options.fMin, res.options.fMax, rawPoles).residues[i]);
  return u;
}

// Stage 6: modal twist axis of mode i (plate plane fit of the real shape) and its jackknife over hits.
void attachModalAxis(const FrfTest& test, const FrfResult& res, const std::vector<cd>& rawPoles, size_t i,
                     const Eigen::MatrixXd& P, ModeResult& m) {
  try {
    m.axis = calcTwistAxis(P * calcRealShape(calcModeShape(test, res, res.frf.h1, rawPoles, i), &m.mpc), test.forcePoint);
    m.hasAxis = true;
  } catch (const io::ResultError&) {  // the plate only translates in this mode
    m.hasAxis = false;
  }
  const size_t nHits = res.frf.forceSpectra.size();
  if (!m.hasAxis || nHits < 3) return;
  std::vector<double> arms, betas;
  for (size_t k = 0; k < nHits; ++k) {
    std::vector<bool> use(nHits, true);
    use[k] = false;
    std::vector<std::vector<cd>> h;
    modal::calcH1FromSpectra(res.frf, use, h);
    const TwistAxis a = calcTwistAxis(P * calcRealShape(calcModeShape(test, res, h, rawPoles, i), nullptr), test.forcePoint);
    arms.push_back(a.arm);
    betas.push_back(wrapDegrees(a.betaDeg - m.axis.betaDeg));
  }
  m.armStderr = modal::calcJackknifeSpread(arms);
  m.betaStderrDeg = modal::calcJackknifeSpread(betas);
}

// Sum over channels of |H1|^2 at the resonance bin: how strongly the hit excites a mode.
double calcModeStrength(const FrfResult& res, const ModeResult& m) {
  const size_t bin = getNearestBin(res.frf, m.frequencyHz);
  double s = 0;
  for (const auto& h : res.frf.h1) s += std::norm(h[bin]);
  return s;
}

// Stage 7: bending / torsion labels: the hints (processing.*_mode_hz) or, among the modes whose axis is
// within 45 deg of normal to x (bending) or of x (torsion), the most strongly excited one.
void labelModes(const FrfTest& test, FrfResult& res) {
  auto nearest = [&](double f) {
    int best = -1;
    for (size_t i = 0; i < res.modes.size(); ++i)
      if (best < 0 || std::abs(res.modes[i].frequencyHz - f) < std::abs(res.modes[best].frequencyHz - f)) best = i;
    return best;
  };
  auto strongestWith = [&](bool normalToX, int exclude) {
    int best = -1;
    for (size_t i = 0; i < res.modes.size(); ++i) {
      const auto& m = res.modes[i];
      if (static_cast<int>(i) == exclude || !m.hasAxis) continue;
      const double s = std::abs(std::sin(m.axis.betaDeg * M_PI / 180));
      if ((normalToX ? s >= std::sqrt(0.5) : s < std::sqrt(0.5)) &&
          (best < 0 || calcModeStrength(res, m) > calcModeStrength(res, res.modes[best])))
        best = static_cast<int>(i);
    }
    return best;
  };
  res.bendingIndex = test.bendingModeHz > 0 ? nearest(test.bendingModeHz) : strongestWith(true, -1);
  res.torsionIndex = test.torsionModeHz > 0 ? nearest(test.torsionModeHz) : strongestWith(false, res.bendingIndex);
  if (res.bendingIndex >= 0) res.modes[res.bendingIndex].label = "bending";
  if (res.torsionIndex >= 0 && res.torsionIndex != res.bendingIndex) res.modes[res.torsionIndex].label = "torsion";
  else res.torsionIndex = -1;
}

}  // namespace

FrfResult identifyFrf(const FrfTest& test, const std::vector<modal::ImpactRecord>& hits) {
  FrfResult res;
  const auto good = screenHits(test, hits, res);
  modal::WindowOptions w;
  w.forceWindow = test.forceWindow;
  if (test.exponentialEndValue > 0) {
    res.window.endValue = test.exponentialEndValue;
    res.window.description = "exponential, end value " + formatNumber(test.exponentialEndValue, 6) +
                             " (processing.exponential_end_value)";
  } else {
    res.window = modal::chooseExponentialWindow(good);
  }
  w.exponentialEndValue = res.window.endValue;
  res.frf = modal::estimateH1(good, w);
  chooseLscfOptions(test, res);
  const auto& o = res.options;
  const auto modes = runStabilisation(res);
  const auto jack = modal::calcJackknifeStdErr(res.frf, o, modes);
  res.peaks = modal::findHalfPowerPeaks(res.frf.frequency, modal::calcPowerIndicator(res.frf.h1), o.fMin, o.fMax,
                                        res.frf.windowDecayRate);
  std::vector<cd> rawPoles;
  for (const auto& m : modes) rawPoles.push_back(m.rawLambda);
  for (const auto& h : res.frf.h1)
    res.models.push_back(modal::fitModalModel(res.frf.frequency, h, o.fMin, o.fMax, rawPoles, true));
  std::vector<PlatePoint> pts;
  for (const auto& c : test.channels) pts.push_back(c.position);
  const Eigen::MatrixXd P = pts.size() >= 3 ? calcPlaneFitOperator(pts) : Eigen::MatrixXd();
  for (size_t i = 0; i < modes.size(); ++i) {
    res.modes.push_back(makeModeResult(res, modes[i], jack[i]));
    if (pts.size() >= 3) attachModalAxis(test, res, rawPoles, i, P, res.modes.back());
  }
  labelModes(test, res);
  diagnoseFrf(test, res);
  return res;
}

}  // namespace motostab::swingarm::identification
