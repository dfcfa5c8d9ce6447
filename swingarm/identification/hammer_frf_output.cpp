// The outputs of a hammer test: frf.csv, modes.csv, stabilisation.csv, frf.json and their plots.
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/atomic_file.h"
#include "io/csv.h"
#include "io/plot.h"
#include "swingarm/identification/axes_plot.h"
#include "swingarm/identification/hammer_frf.h"

namespace motostab::swingarm::identification {

using io::CsvWriter;
using io::gnuplotQuote;
using io::renderGnuplot;
using io::writeFileAtomically;
namespace {

using cd = std::complex<double>;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

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
