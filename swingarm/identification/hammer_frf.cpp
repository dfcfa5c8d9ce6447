#include "swingarm/identification/hammer_frf.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "io/atomic_file.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "io/plot.h"
#include "swingarm/identification/axes_plot.h"
#include "swingarm/identification/frf_diagnosis.h"
#include "swingarm/identification/yaml_input.h"

namespace motostab::swingarm::identification {

using io::CsvTable;
using io::CsvWriter;
using io::InputError;
using io::YamlMap;
using io::formatNumber;
using io::gnuplotQuote;
using io::readCsv;
using io::renderGnuplot;
using io::writeFileAtomically;
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


}  // namespace

namespace {

// The optional `processing` mapping of a hammer test.
void readFrfProcessing(YamlMap p, FrfTest& t) {
  if (p.has("band_hz")) {
    const auto b = p.getDoubleList("band_hz", 2);
    if (!(b[0] >= 0 && b[1] > b[0])) p.fail("band_hz", "need 0 <= low < high");
    t.bandMinHz = b[0], t.bandMaxHz = b[1];
  }
  if (p.has("model_order")) {
    const auto o = p.getDoubleList("model_order", 2);
    if (!(o[0] >= 2 && o[1] >= o[0] && o[1] <= 200 && o[0] == std::floor(o[0]) && o[1] == std::floor(o[1])))
      p.fail("model_order", "need integers 2 <= min <= max <= 200");
    t.minOrder = static_cast<int>(o[0]), t.maxOrder = static_cast<int>(o[1]);
  }
  t.exponentialEndValue = p.getPositive("exponential_end_value", t.exponentialEndValue);
  if (t.exponentialEndValue > 1) p.fail("exponential_end_value", "must be in (0, 1]");
  t.forceWindow = p.getBool("force_window", t.forceWindow);
  t.doubleHitFraction = p.getPositive("double_hit_fraction", t.doubleHitFraction);
  t.forceRange = p.getPositive("force_range_N", 0.0);
  t.responseRange = p.getPositive("response_range_mps2", 0.0);
  t.bendingModeHz = p.getPositive("bending_mode_hz", 0.0);
  t.torsionModeHz = p.getPositive("torsion_mode_hz", 0.0);
  const std::string from = p.getString("modal_axes_from", "ods");
  if (from != "ods" && from != "modal_model") p.fail("modal_axes_from", "expected 'ods' or 'modal_model'");
  t.axesFromModalModel = from == "modal_model";
  p.finish();
}

}  // namespace

FrfTest readFrfTest(const std::filesystem::path& file) {
  YamlMap root = openTestFile(file, "frf");
  FrfTest t;
  t.file = file;
  t.frame = root.getString("frame", "");
  t.forcePoint = readForcePoint(root);
  std::vector<YamlMap> channels = root.getMapList("channels");
  if (channels.empty()) root.fail("channels", "expected a non-empty list of channels");
  std::set<std::string> names;
  std::vector<PlatePoint> pts;
  for (YamlMap& m : channels) {
    FrfChannel c;
    c.name = m.getString("name");
    c.column = m.getString("column", c.name + "_mps2");
    c.position = {m.getDouble("x"), m.getDouble("z")};
    if (!names.insert(c.name).second) m.fail("name", "duplicate channel name '" + c.name + "'");
    m.finish();
    pts.push_back(c.position);
    t.channels.push_back(c);
  }
  if (pts.size() >= 3) {
    const std::string why = checkPlaneGeometry(pts);
    if (!why.empty()) root.fail("channels", why);
  }
  for (const auto& hit : root.getFilePathList("hits")) t.hits.push_back(hit);
  if (t.hits.empty()) root.fail("hits", "expected a non-empty list of CSV files");
  t.timeColumn = root.getString("time_column", t.timeColumn);
  t.forceColumn = root.getString("force_column", t.forceColumn);
  if (root.has("processing")) readFrfProcessing(root.getMap("processing"), t);
  root.finish();
  return t;
}

std::vector<modal::ImpactRecord> readHits(const FrfTest& test) {
  std::vector<modal::ImpactRecord> out;
  for (const auto& file : test.hits) {
    const CsvTable csv = readCsv(file);
    const std::string src = file.string();
    const auto t = csv.getColumn(test.timeColumn);
    modal::ImpactRecord r;
    r.force = csv.getColumn(test.forceColumn);
    for (const auto& c : test.channels) r.responses.push_back(csv.getColumn(c.column));
    if (t.size() < 16) throw InputError({src, 0, 0, test.timeColumn}, "too few samples (" + std::to_string(t.size()) + ")");
    const int tc = csv.getColumnIndex(test.timeColumn) + 1;
    for (size_t i = 1; i < t.size(); ++i)
      if (!(t[i] > t[i - 1]))
        throw InputError({src, csv.lineNumbers[i], tc, test.timeColumn}, "time is not strictly increasing");
    r.dt = (t.back() - t.front()) / (t.size() - 1);
    for (size_t i = 1; i < t.size(); ++i)
      if (std::abs(t[i] - t[i - 1] - r.dt) > 0.05 * r.dt)
        throw InputError({src, csv.lineNumbers[i], tc, test.timeColumn},
                         "non-uniform sampling (step differs from the mean by more than 5 %)");
    if (!out.empty() && (r.force.size() != out[0].force.size() || std::abs(r.dt - out[0].dt) > 1e-3 * r.dt))
      throw InputError({src, 0, 0, test.timeColumn}, "hit differs from the first hit in length or sampling interval");
    out.push_back(std::move(r));
  }
  return out;
}

namespace {

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
    } catch (const std::runtime_error& e) {  // no usable band: analyse the whole record, say why
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
  } catch (const std::invalid_argument&) {
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

namespace {

// Upper frequency of the tables and plots: the band plus a fifth of its width (up to Nyquist).
double calcPlotTop(const FrfResult& r) {
  return std::min(r.frf.frequency.back(), r.options.fMax + 0.2 * (r.options.fMax - r.options.fMin));
}

// frf.csv: per channel H1 (re, im, magnitude, phase), coherence and the fitted modal model.
void writeFrfTable(const FrfTest& test, const FrfResult& r, const std::filesystem::path& dir) {
  const auto& frf = r.frf;
  std::vector<std::string> header{"frequency_hz"};
  for (const auto& c : test.channels)
    for (const char* s : {"_re", "_im", "_mag", "_phase_deg", "_coherence", "_model_re", "_model_im", "_model_mag",
                          "_model_phase_deg"})
      header.push_back(c.name + s);
  CsvWriter fw(header);
  const double fTop = calcPlotTop(r);
  for (size_t k = 1; k < frf.frequency.size() && frf.frequency[k] <= fTop; ++k) {
    const double f = frf.frequency[k];
    fw.beginRow().add(f);
    for (size_t c = 0; c < test.channels.size(); ++c) {
      const cd h = frf.h1[c][k], m = r.models[c].evaluate(f);
      fw.add(h.real()).add(h.imag()).add(std::abs(h)).add(std::arg(h) * 180 / M_PI).add(frf.coherence[c][k]);
      fw.add(m.real()).add(m.imag()).add(std::abs(m)).add(std::arg(m) * 180 / M_PI);
    }
  }
  writeFileAtomically(dir / "frf.csv", fw.getText());
}

// modes.csv: one row per identified mode.
void writeModesTable(const FrfResult& r, const std::filesystem::path& dir) {
  CsvWriter mw({"frequency_hz", "frequency_hz_stderr", "damping_ratio", "damping_ratio_stderr", "loss_factor",
                "loss_factor_stderr", "half_power_frequency_hz", "half_power_damping_ratio", "arm_m", "arm_m_stderr",
                "beta_deg", "beta_deg_stderr", "mpc", "model_order", "stable_poles", "coherence"});
  for (const auto& m : r.modes)
    mw.beginRow().add(m.frequencyHz).add(m.frequencyStderrHz).add(m.dampingRatio).add(m.dampingStderr)
        .add(m.lossFactor).add(m.lossFactorStderr).add(m.halfPowerFrequencyHz).add(m.halfPowerDampingRatio)
        .add(m.hasAxis ? m.axis.arm : kNaN).add(m.armStderr).add(m.hasAxis ? m.axis.betaDeg : kNaN)
        .add(m.betaStderrDeg).add(m.mpc).add(static_cast<double>(m.order)).add(static_cast<double>(m.stableCount))
        .add(m.coherence);
  writeFileAtomically(dir / "modes.csv", mw.getText());
}

// stabilisation.csv: every pole of the diagram with its stability flags.
void writeStabilisationTable(const FrfResult& r, const std::filesystem::path& dir) {
  CsvWriter sw({"order", "frequency_hz", "damping_ratio", "stable_frequency", "stable_damping"});
  for (const auto& p : r.diagram)
    sw.beginRow().add(static_cast<double>(p.order)).add(p.frequencyHz).add(p.dampingRatio)
        .add(p.stableFrequency ? 1.0 : 0.0).add(p.stableDamping ? 1.0 : 0.0);
  writeFileAtomically(dir / "stabilisation.csv", sw.getText());
}

nlohmann::json formatModeJson(const ModeResult& m) {
  using nlohmann::json;
  auto orNull = [](double v) { return std::isnan(v) ? json() : json(v); };
  json e{{"frequency_hz", m.frequencyHz}, {"frequency_hz_stderr", m.frequencyStderrHz},
         {"damping_ratio", m.dampingRatio}, {"damping_ratio_stderr", m.dampingStderr},
         {"loss_factor", m.lossFactor}, {"loss_factor_stderr", m.lossFactorStderr},
         {"model_order", m.order}, {"stable_poles", m.stableCount}, {"label", m.label},
         {"coherence_at_resonance", m.coherence}};
  e["half_power"] = {{"frequency_hz", orNull(m.halfPowerFrequencyHz)}, {"damping_ratio", orNull(m.halfPowerDampingRatio)}};
  if (m.hasAxis)
    e["modal_axis"] = {{"arm_m", m.axis.arm}, {"arm_m_stderr", m.armStderr}, {"beta_deg", m.axis.betaDeg},
                       {"beta_deg_stderr", m.betaStderrDeg}, {"mpc", m.mpc},
                       {"point_m", {m.axis.point[0], 0.0, m.axis.point[1]}},
                       {"direction", {m.axis.direction[0], 0.0, m.axis.direction[1]}}};
  return e;
}

// frf.json: hits, window, the automatic (or given) band and orders with their reasons, indicator peaks,
// modes, labels and diagnostics.
void writeFrfJson(const FrfTest& test, const FrfResult& r, const std::filesystem::path& dir) {
  using nlohmann::json;
  const auto& o = r.options;
  json j;
  j["test"] = test.file.string();
  j["frame"] = test.frame;
  j["hits_used"] = r.usedHits;
  j["hits_rejected"] = r.rejectedHits;
  j["averages"] = r.frf.averages;
  j["frequency_resolution_hz"] = r.frf.df;
  j["window"] = {{"force_window", test.forceWindow}, {"exponential_end_value", r.window.endValue},
                 {"exponential_reason", r.window.description},
                 {"added_decay_rate_per_s", r.frf.windowDecayRate}};
  j["method"] = "LSCF (common-denominator, z-domain), stable poles clustered over model orders; "
                "stderr = jackknife over hits combined with the scatter over orders";
  j["band_hz"] = {o.fMin, o.fMax};
  j["band"] = {{"automatic", r.automaticBand}, {"reason", r.band.description}};
  j["model_order"] = {o.minOrder, o.maxOrder};
  j["model_order_reason"] = r.orderReason;
  json peaks = json::array();
  for (const auto& p : r.indicatorPeaks)
    peaks.push_back({{"frequency_hz", p.frequencyHz}, {"relative_amplitude", p.relativeAmplitude}, {"coherence", p.coherence}});
  j["indicator_peaks"] = peaks;
  json modes = json::array();
  for (const auto& m : r.modes) modes.push_back(formatModeJson(m));
  j["modes"] = modes;
  j["modal_axes_from"] = test.axesFromModalModel ? "modal_model" : "ods";
  j["bending_mode"] = r.bendingIndex;
  j["torsion_mode"] = r.torsionIndex;
  j["diagnostics"] = r.diagnostics;
  writeFileAtomically(dir / "frf.json", j.dump(2) + "\n");
}

// Plot: measured H1 (points) and modal model (lines), magnitude over phase.
void plotFrfMagnitudePhase(const FrfTest& test, const FrfResult& r, const std::filesystem::path& dir) {
  std::ostringstream mp;
  mp << "set datafile separator ','\nset key autotitle columnhead\nset multiplot layout 2,1\n"
     << "set logscale y\nset grid\nset ylabel '|H1| (response/N)'\nset xrange [" << r.options.fMin << ":"
     << calcPlotTop(r) << "]\n"
     << "set title 'FRF magnitude and phase: measured H1 (points) and fitted modal model (lines)'\nplot ";
  for (size_t c = 0; c < test.channels.size(); ++c) {
    const int base = 2 + 9 * static_cast<int>(c);
    mp << (c ? ", " : "") << "'frf.csv' using 1:" << base + 2 << " with points pt 7 ps 0.3 lc " << c + 1
       << " title " << gnuplotQuote(test.channels[c].name + " H1") << ", '' using 1:" << base + 7 << " with lines lc "
       << c + 1 << " title " << gnuplotQuote(test.channels[c].name + " model");
  }
  mp << "\nunset logscale y\nset ylabel 'phase (deg)'\nset xlabel 'frequency (Hz)'\nset yrange [-180:180]\nset ytics 90\n"
     << "unset title\nplot ";
  for (size_t c = 0; c < test.channels.size(); ++c) {
    const int base = 2 + 9 * static_cast<int>(c);
    mp << (c ? ", " : "") << "'frf.csv' using 1:" << base + 3 << " with points pt 7 ps 0.3 lc " << c + 1
       << " notitle, '' using 1:" << base + 8 << " with lines lc " << c + 1 << " notitle";
  }
  mp << "\nunset multiplot\nset yrange [*:*]\nset ytics auto\n";
  renderGnuplot(dir, "frf_magnitude_phase", mp.str());
}

void plotCoherence(const FrfTest& test, const FrfResult& r, const std::filesystem::path& dir) {
  std::ostringstream co;
  co << "set datafile separator ','\nset grid\nset xlabel 'frequency (Hz)'\nset ylabel 'coherence'\n"
     << "set yrange [0:1.02]\nset xrange [" << r.options.fMin << ":" << calcPlotTop(r) << "]\nset title 'H1 coherence ("
     << r.frf.averages << " hits)'\nplot ";
  for (size_t c = 0; c < test.channels.size(); ++c)
    co << (c ? ", " : "") << "'frf.csv' using 1:" << 2 + 9 * c + 4 << " with lines lc " << c + 1 << " title "
       << gnuplotQuote(test.channels[c].name);
  renderGnuplot(dir, "coherence", co.str() + "\n");
}

void plotStabilisation(const FrfTest& test, const FrfResult& r, const std::filesystem::path& dir) {
  const auto& o = r.options;
  std::ostringstream st;
  st << "set datafile separator ','\nset grid\nset xlabel 'frequency (Hz)'\nset ylabel 'model order'\n"
     << "set y2label 'sum of |H1|^2'\nset logscale y2\nset y2tics\nset xrange [" << o.fMin << ":" << o.fMax << "]\n"
     << "set yrange [" << o.minOrder - 1 << ":" << o.maxOrder + 1 << "]\n"
     << "set title 'Stabilisation diagram (LSCF): o new, + stable frequency, * stable frequency and damping'\n"
     << "plot 'stabilisation.csv' using 2:($4==0 ? $1 : 1/0) with points pt 6 ps 0.6 lc rgb '#999999' title 'new', "
     << "'' using 2:($4==1 && $5==0 ? $1 : 1/0) with points pt 1 lc rgb '#1f77b4' title 'stable f', "
     << "'' using 2:($5==1 ? $1 : 1/0) with points pt 3 lc rgb '#d62728' title 'stable f, zeta', "
     << "'frf.csv' using 1:(";
  for (size_t c = 0; c < test.channels.size(); ++c) st << (c ? "+" : "") << "$" << 2 + 9 * c + 2 << "**2";
  st << ") axes x1y2 with lines lc rgb 'black' title 'sum |H1|^2'\n";
  renderGnuplot(dir, "stabilisation", st.str());
}

void plotModalAxes(const FrfTest& test, const FrfResult& r, const std::filesystem::path& dir) {
  std::vector<PlotAxis> axes;
  for (const auto& m : r.modes) {
    if (!m.hasAxis) continue;
    char label[96];
    std::snprintf(label, sizeof label, "%s%.1f Hz (beta %.1f deg)", m.label.empty() ? "" : (m.label + " ").c_str(),
                  m.frequencyHz, m.axis.betaDeg);
    axes.push_back({label, m.axis.point, m.axis.direction});
  }
  if (axes.empty()) return;
  std::vector<PlotMarker> ch;
  for (const auto& c : test.channels) ch.push_back({c.name, c.position});
  writeAxesPlot(dir, "modal_axes",
                test.axesFromModalModel ? "Modal twist axes from the modal-model residues"
                                        : "Modal twist axes from the ODS at each resonance",
                ch, test.forcePoint, axes);
}

}  // namespace

void writeFrfOutputs(const FrfTest& test, const FrfResult& r, const std::filesystem::path& dir) {
  writeFrfTable(test, r, dir);
  writeModesTable(r, dir);
  writeStabilisationTable(r, dir);
  writeFrfJson(test, r, dir);
  plotFrfMagnitudePhase(test, r, dir);
  plotCoherence(test, r, dir);
  plotStabilisation(test, r, dir);
  plotModalAxes(test, r, dir);
}

}  // namespace motostab::swingarm::identification
