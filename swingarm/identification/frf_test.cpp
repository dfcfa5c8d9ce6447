#include "swingarm/identification/frf_test.h"

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
#include "swingarm/identification/yaml_input.h"

namespace motostab::identification {
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
  YamlMap fp = root.getMap("force_point");
  t.forcePoint = {fp.getDouble("x"), fp.getDouble("z")};
  fp.finish();
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

FrfResult identifyFrf(const FrfTest& test, const std::vector<modal::ImpactRecord>& hits) {
  FrfResult res;
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
  modal::WindowOptions w;
  w.forceWindow = test.forceWindow;
  w.exponentialEndValue = test.exponentialEndValue;
  res.frf = modal::estimateH1(good, w);
  const auto& frf = res.frf;
  const double nyquist = frf.frequency.back();
  auto& o = res.options;
  o.fMin = test.bandMinHz > 0 || test.bandMaxHz > 0 ? test.bandMinHz : 5 * frf.df;
  o.fMax = test.bandMaxHz > 0 ? std::min(test.bandMaxHz, nyquist) : 0.8 * nyquist;
  o.minOrder = test.minOrder;
  o.maxOrder = test.maxOrder;
  o.windowDecayRate = frf.windowDecayRate;
  const modal::LscfEstimator est(frf.frequency, frf.h1, o);
  res.diagram = modal::calcStabilisationDiagram(est);
  const auto modes = modal::selectStableModes(res.diagram, o);
  const auto jack = modal::calcJackknifeStdErr(frf, o, modes);
  res.peaks = modal::findHalfPowerPeaks(frf.frequency, modal::calcPowerIndicator(frf.h1), o.fMin, o.fMax,
                                        frf.windowDecayRate);
  std::vector<cd> rawPoles;
  for (const auto& m : modes) rawPoles.push_back(m.rawLambda);
  for (const auto& h : frf.h1)
    res.models.push_back(modal::fitModalModel(frf.frequency, h, o.fMin, o.fMax, rawPoles, true));

  std::vector<PlatePoint> pts;
  for (const auto& c : test.channels) pts.push_back(c.position);
  const bool axes = pts.size() >= 3;
  const Eigen::MatrixXd P = axes ? calcPlaneFitOperator(pts) : Eigen::MatrixXd();
  const size_t nHits = good.size();
  for (size_t i = 0; i < modes.size(); ++i) {
    ModeResult m;
    m.frequencyHz = modes[i].frequencyHz;
    m.dampingRatio = modes[i].dampingRatio;
    const double jf = std::isnan(jack[i].first) ? 0.0 : jack[i].first;
    const double jz = std::isnan(jack[i].second) ? 0.0 : jack[i].second;
    m.frequencyStderrHz = std::hypot(jf, modes[i].frequencyScatterHz);
    m.dampingStderr = std::hypot(jz, modes[i].dampingScatter);
    m.lossFactor = 2 * m.dampingRatio;
    m.lossFactorStderr = 2 * m.dampingStderr;
    m.order = modes[i].order;
    m.stableCount = modes[i].count;
    m.halfPowerFrequencyHz = m.halfPowerDampingRatio = kNaN;
    const size_t peakBin = getNearestBin(frf, modes[i].rawLambda.imag() / (2 * M_PI));
    m.coherence = 1;
    for (const auto& c : frf.coherence) m.coherence = std::min(m.coherence, c[peakBin]);
    for (const auto& p : res.peaks)
      if (std::abs(p.frequencyHz - m.frequencyHz) < 3 * frf.df &&
          (std::isnan(m.halfPowerFrequencyHz) ||
           std::abs(p.frequencyHz - m.frequencyHz) < std::abs(m.halfPowerFrequencyHz - m.frequencyHz)))
        m.halfPowerFrequencyHz = p.frequencyHz, m.halfPowerDampingRatio = p.dampingRatio;
    if (axes) {
      const size_t bin = getNearestBin(frf, modes[i].rawLambda.imag() / (2 * M_PI));
      // Complex shape of mode i at the channels: the measured ODS at the resonance bin, or the residues of
      // the modal model (LSFD with all identified poles, so neighbouring modes are removed).
      auto getShape = [&](const std::vector<std::vector<cd>>& h) {
        if (!test.axesFromModalModel) return getOds(h, bin);
        std::vector<cd> u;
        for (const auto& hc : h) u.push_back(modal::fitModalModel(frf.frequency, hc, o.fMin, o.fMax, rawPoles).residues[i]);
        return u;
      };
      const Eigen::VectorXd v = calcRealShape(getShape(frf.h1), &m.mpc);
      try {
        m.axis = calcTwistAxis(P * v, test.forcePoint);
        m.hasAxis = true;
      } catch (const std::invalid_argument&) {
        m.hasAxis = false;
      }
      if (m.hasAxis && nHits >= 3) {
        std::vector<double> arms, betas;
        for (size_t k = 0; k < nHits; ++k) {
          std::vector<bool> use(nHits, true);
          use[k] = false;
          std::vector<std::vector<cd>> h;
          modal::calcH1FromSpectra(frf, use, h);
          const TwistAxis a = calcTwistAxis(P * calcRealShape(getShape(h), nullptr), test.forcePoint);
          arms.push_back(a.arm);
          betas.push_back(wrapDegrees(a.betaDeg - m.axis.betaDeg));
        }
        m.armStderr = modal::calcJackknifeSpread(arms);
        m.betaStderrDeg = modal::calcJackknifeSpread(betas);
      }
    }
    res.modes.push_back(m);
  }
  // Bending / torsion labels.
  auto nearest = [&](double f) {
    int best = -1;
    for (size_t i = 0; i < res.modes.size(); ++i)
      if (best < 0 || std::abs(res.modes[i].frequencyHz - f) < std::abs(res.modes[best].frequencyHz - f)) best = i;
    return best;
  };
  auto lowestWith = [&](bool normalToX, int exclude) {
    for (size_t i = 0; i < res.modes.size(); ++i) {
      const auto& m = res.modes[i];
      if (static_cast<int>(i) == exclude || !m.hasAxis) continue;
      const double s = std::abs(std::sin(m.axis.betaDeg * M_PI / 180));
      if (normalToX ? s >= std::sqrt(0.5) : s < std::sqrt(0.5)) return static_cast<int>(i);
    }
    return -1;
  };
  res.bendingIndex = test.bendingModeHz > 0 ? nearest(test.bendingModeHz) : lowestWith(true, -1);
  res.torsionIndex = test.torsionModeHz > 0 ? nearest(test.torsionModeHz) : lowestWith(false, res.bendingIndex);
  if (res.bendingIndex >= 0) res.modes[res.bendingIndex].label = "bending";
  if (res.torsionIndex >= 0 && res.torsionIndex != res.bendingIndex) res.modes[res.torsionIndex].label = "torsion";
  return res;
}

void writeFrfOutputs(const FrfTest& test, const FrfResult& r, const std::filesystem::path& dir) {
  using nlohmann::json;
  const auto& frf = r.frf;
  const auto& o = r.options;
  const double fTop = std::min(frf.frequency.back(), o.fMax + 0.2 * (o.fMax - o.fMin));
  // FRF table.
  std::vector<std::string> header{"frequency_hz"};
  for (const auto& c : test.channels)
    for (const char* s : {"_re", "_im", "_mag", "_phase_deg", "_coherence", "_model_re", "_model_im", "_model_mag",
                          "_model_phase_deg"})
      header.push_back(c.name + s);
  CsvWriter fw(header);
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
  // Modes.
  CsvWriter mw({"frequency_hz", "frequency_hz_stderr", "damping_ratio", "damping_ratio_stderr", "loss_factor",
                "loss_factor_stderr", "half_power_frequency_hz", "half_power_damping_ratio", "arm_m", "arm_m_stderr",
                "beta_deg", "beta_deg_stderr", "mpc", "model_order", "stable_poles", "coherence"});
  json jm = json::array();
  for (const auto& m : r.modes) {
    mw.beginRow().add(m.frequencyHz).add(m.frequencyStderrHz).add(m.dampingRatio).add(m.dampingStderr)
        .add(m.lossFactor).add(m.lossFactorStderr).add(m.halfPowerFrequencyHz).add(m.halfPowerDampingRatio)
        .add(m.hasAxis ? m.axis.arm : kNaN).add(m.armStderr).add(m.hasAxis ? m.axis.betaDeg : kNaN)
        .add(m.betaStderrDeg).add(m.mpc).add(static_cast<double>(m.order)).add(static_cast<double>(m.stableCount))
        .add(m.coherence);
    json e{{"frequency_hz", m.frequencyHz}, {"frequency_hz_stderr", m.frequencyStderrHz},
           {"damping_ratio", m.dampingRatio}, {"damping_ratio_stderr", m.dampingStderr},
           {"loss_factor", m.lossFactor}, {"loss_factor_stderr", m.lossFactorStderr},
           {"model_order", m.order}, {"stable_poles", m.stableCount}, {"label", m.label},
           {"coherence_at_resonance", m.coherence}};
    e["half_power"] = {{"frequency_hz", std::isnan(m.halfPowerFrequencyHz) ? json() : json(m.halfPowerFrequencyHz)},
                       {"damping_ratio", std::isnan(m.halfPowerDampingRatio) ? json() : json(m.halfPowerDampingRatio)}};
    if (m.hasAxis)
      e["modal_axis"] = {{"arm_m", m.axis.arm}, {"arm_m_stderr", m.armStderr}, {"beta_deg", m.axis.betaDeg},
                         {"beta_deg_stderr", m.betaStderrDeg}, {"mpc", m.mpc},
                         {"point_m", {m.axis.point[0], 0.0, m.axis.point[1]}},
                         {"direction", {m.axis.direction[0], 0.0, m.axis.direction[1]}}};
    jm.push_back(e);
  }
  writeFileAtomically(dir / "modes.csv", mw.getText());
  CsvWriter sw({"order", "frequency_hz", "damping_ratio", "stable_frequency", "stable_damping"});
  for (const auto& p : r.diagram)
    sw.beginRow().add(static_cast<double>(p.order)).add(p.frequencyHz).add(p.dampingRatio)
        .add(p.stableFrequency ? 1.0 : 0.0).add(p.stableDamping ? 1.0 : 0.0);
  writeFileAtomically(dir / "stabilisation.csv", sw.getText());
  json j;
  j["test"] = test.file.string();
  j["frame"] = test.frame;
  j["hits_used"] = r.usedHits;
  j["hits_rejected"] = r.rejectedHits;
  j["averages"] = frf.averages;
  j["frequency_resolution_hz"] = frf.df;
  j["window"] = {{"force_window", test.forceWindow}, {"exponential_end_value", test.exponentialEndValue},
                 {"added_decay_rate_per_s", frf.windowDecayRate}};
  j["method"] = "LSCF (common-denominator, z-domain), stable poles clustered over model orders; "
                "stderr = jackknife over hits combined with the scatter over orders";
  j["band_hz"] = {o.fMin, o.fMax};
  j["model_order"] = {o.minOrder, o.maxOrder};
  j["modes"] = jm;
  j["modal_axes_from"] = test.axesFromModalModel ? "modal_model" : "ods";
  j["bending_mode"] = r.bendingIndex;
  j["torsion_mode"] = r.torsionIndex;
  writeFileAtomically(dir / "frf.json", j.dump(2) + "\n");

  // Plots.
  std::ostringstream mp;
  mp << "set datafile separator ','\nset key autotitle columnhead\nset multiplot layout 2,1\n"
     << "set logscale y\nset grid\nset ylabel '|H1| (response/N)'\nset xrange [" << o.fMin << ":" << fTop << "]\n"
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
  std::ostringstream co;
  co << "set datafile separator ','\nset grid\nset xlabel 'frequency (Hz)'\nset ylabel 'coherence'\n"
     << "set yrange [0:1.02]\nset xrange [" << o.fMin << ":" << fTop << "]\nset title 'H1 coherence ("
     << frf.averages << " hits)'\nplot ";
  for (size_t c = 0; c < test.channels.size(); ++c)
    co << (c ? ", " : "") << "'frf.csv' using 1:" << 2 + 9 * c + 4 << " with lines lc " << c + 1 << " title "
       << gnuplotQuote(test.channels[c].name);
  renderGnuplot(dir, "coherence", co.str() + "\n");
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
  std::vector<PlotAxis> axes;
  for (const auto& m : r.modes) {
    if (!m.hasAxis) continue;
    char label[96];
    std::snprintf(label, sizeof label, "%s%.1f Hz (beta %.1f deg)", m.label.empty() ? "" : (m.label + " ").c_str(),
                  m.frequencyHz, m.axis.betaDeg);
    axes.push_back({label, m.axis.point, m.axis.direction});
  }
  if (!axes.empty()) {
    std::vector<PlotMarker> ch;
    for (const auto& c : test.channels) ch.push_back({c.name, c.position});
    writeAxesPlot(dir, "modal_axes", test.axesFromModalModel ? "Modal twist axes from the modal-model residues" : "Modal twist axes from the ODS at each resonance", ch, test.forcePoint, axes);
  }
}

}  // namespace motostab::identification
