#include "output/swingarm_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "output/writer_tools.h"

namespace motostab::output {

using swingarm::identification::CogResult;
using swingarm::identification::CogTest;
using swingarm::identification::FrfResult;
using swingarm::identification::FrfTest;
using swingarm::identification::InertiaResult;
using swingarm::identification::InertiaTest;
using swingarm::identification::ModeResult;
using swingarm::identification::PlatePoint;
using swingarm::identification::StaticResult;
using swingarm::identification::StaticTest;
using swingarm::identification::SwingarmIdentification;
using swingarm::identification::formatSwingarmYaml;

namespace {

using cd = std::complex<double>;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---- Twist-axis plots ----------------------------------------------------------------------------

// A named sensor position on the plate.
struct PlotMarker {
  std::string label;
  PlatePoint position;
};

// A named axis line through `point` with direction `direction` (x, z).
struct PlotAxis {
  std::string label;
  Eigen::Vector2d point, direction;
};

// Writes DIR/NAME_points.dat, DIR/NAME_axes.dat, DIR/NAME_plate.dat and renders DIR/NAME.png/.svg:
// the plate (bounding box of the sensors and the force point), the sensors, the force point, the
// swingarm line from the pivot (origin) to the force point, and each axis.
void writeAxesPlot(const std::filesystem::path& dir, const std::string& name, const std::string& title,
                   const std::vector<PlotMarker>& sensors, const PlatePoint& forcePoint,
                   const std::vector<PlotAxis>& axes) {
  double x0 = std::min(0.0, forcePoint.x), x1 = std::max(0.0, forcePoint.x);
  double z0 = forcePoint.z, z1 = forcePoint.z;
  double px0 = forcePoint.x, px1 = forcePoint.x, pz0 = forcePoint.z, pz1 = forcePoint.z;
  std::ostringstream pts;
  pts << "# x_m z_m label\n";
  for (const auto& s : sensors) {
    px0 = std::min(px0, s.position.x), px1 = std::max(px1, s.position.x);
    pz0 = std::min(pz0, s.position.z), pz1 = std::max(pz1, s.position.z);
    pts << formatNumber(s.position.x, 8) << " " << formatNumber(s.position.z, 8) << " \"" << s.label << "\"\n";
  }
  for (const auto& a : axes) x0 = std::min(x0, a.point[0]), x1 = std::max(x1, a.point[0]);
  const double margin = 0.02;
  px0 -= margin, px1 += margin, pz0 -= margin, pz1 += margin;
  x0 = std::min(x0, px0) - 0.05, x1 = std::max(x1, px1) + 0.05;
  z0 = std::min(z0, pz0) - 0.05, z1 = std::max(z1, pz1) + 0.05;
  const double span = std::max(x1 - x0, z1 - z0);
  const double cz = 0.5 * (z0 + z1);
  z0 = cz - 0.3 * span, z1 = cz + 0.3 * span;
  std::ostringstream plate, ax;
  plate << px0 << " " << pz0 << "\n" << px1 << " " << pz0 << "\n" << px1 << " " << pz1 << "\n"
        << px0 << " " << pz1 << "\n" << px0 << " " << pz0 << "\n\n\n0 0\n"
        << forcePoint.x << " " << forcePoint.z << "\n\n\n" << forcePoint.x << " " << forcePoint.z << "\n";
  for (const auto& a : axes) {
    const Eigen::Vector2d p = a.point - 2 * span * a.direction, q = a.point + 2 * span * a.direction;
    ax << "# " << a.label << "\n" << formatNumber(p[0], 8) << " " << formatNumber(p[1], 8) << "\n"
       << formatNumber(a.point[0], 8) << " " << formatNumber(a.point[1], 8) << "\n"
       << formatNumber(q[0], 8) << " " << formatNumber(q[1], 8) << "\n\n\n";
  }
  writeFileAtomically(dir / (name + "_points.dat"), pts.str());
  writeFileAtomically(dir / (name + "_plate.dat"), plate.str());
  writeFileAtomically(dir / (name + "_axes.dat"), ax.str());
  std::ostringstream gp;
  gp << "set title " << gnuplotQuote(title) << "\nset xlabel 'x (m), pivot at 0'\nset ylabel 'z (m)'\n"
     << "set size ratio -1\nset grid\nset key below\n"
     << "set xrange [" << x0 << ":" << x1 << "]\nset yrange [" << z0 << ":" << z1 << "]\n"
     << "plot '" << name << "_plate.dat' index 0 with lines lc rgb '#777777' lw 2 title 'reference plate', \\\n"
     << "  '' index 1 with lines dt 2 lc rgb '#aaaaaa' title 'swingarm (pivot to hub)', \\\n"
     << "  '" << name << "_points.dat' using 1:2 with points pt 7 ps 1 lc rgb 'red' title 'sensors', \\\n"
     << "  '' using 1:2:3 with labels offset 1.5,0.8 notitle, \\\n"
     << "  '" << name << "_plate.dat' index 2 with points pt 7 ps 2.5 lc rgb 'black' title 'force point'";
  const char* colours[] = {"black", "#1f77b4", "#d62728", "#2ca02c", "#9467bd"};
  for (size_t i = 0; i < axes.size(); ++i)
    gp << ", \\\n  '" << name << "_axes.dat' index " << i << " with lines lw " << (i == 0 ? 3 : 2) << " lc rgb '"
       << colours[i % 5] << "' title " << gnuplotText(axes[i].label);
  gp << "\n";
  renderGnuplot(dir, name, gp.str());
}

// ---- Hammer test ---------------------------------------------------------------------------------

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
    mw.beginRow().add(m.frequencyHz).addOrEmpty(m.frequencyStderrHz).add(m.dampingRatio).addOrEmpty(m.dampingStderr)
        .add(m.lossFactor).addOrEmpty(m.lossFactorStderr).addOrEmpty(m.halfPowerFrequencyHz).addOrEmpty(m.halfPowerDampingRatio)
        .addOrEmpty(m.hasAxis ? m.axis.arm : kNaN).addOrEmpty(m.armStderr).addOrEmpty(m.hasAxis ? m.axis.betaDeg : kNaN)
        .addOrEmpty(m.betaStderrDeg).addOrEmpty(m.mpc).add(static_cast<double>(m.order)).add(static_cast<double>(m.stableCount))
        .addOrEmpty(m.coherence);
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
  writeFileAtomically(dir / "frf.json", formatJson(j, "frf.json"));
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
       << " title " << gnuplotText(test.channels[c].name + " H1") << ", '' using 1:" << base + 7 << " with lines lc "
       << c + 1 << " title " << gnuplotText(test.channels[c].name + " model");
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
  co << "set datafile separator ','\nset grid\nset xlabel 'frequency (Hz)'\nset ylabel 'coherence (-)'\n"
     << "set yrange [0:1.02]\nset xrange [" << r.options.fMin << ":" << calcPlotTop(r) << "]\nset title 'H1 coherence ("
     << r.frf.averages << " hits)'\nplot ";
  for (size_t c = 0; c < test.channels.size(); ++c)
    co << (c ? ", " : "") << "'frf.csv' using 1:" << 2 + 9 * c + 4 << " with lines lc " << c + 1 << " title "
       << gnuplotText(test.channels[c].name);
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

void writeStaticOutputs(const StaticTest& test, const StaticResult& r, const std::filesystem::path& dir) {
  using nlohmann::json;
  const Eigen::Vector2d dirStderr = Eigen::Vector2d(std::abs(std::sin(r.betaDeg * M_PI / 180)),
                                                    std::abs(std::cos(r.betaDeg * M_PI / 180))) *
                                    (r.betaStderrDeg * M_PI / 180);
  json j;
  j["test"] = test.file.string();
  j["frame"] = test.frame;
  j["k_lat_N_per_m"] = r.kLat;
  j["k_lat_N_per_m_stderr"] = r.kLatStderr;
  j["a_tw_m"] = r.aTw;
  j["a_tw_m_stderr"] = r.aTwStderr;
  j["k_tw_Nm_per_rad"] = r.kTw;
  j["k_tw_Nm_per_rad_stderr"] = r.kTwStderr;
  j["beta_deg"] = r.betaDeg;
  j["beta_deg_stderr"] = r.betaStderrDeg;
  j["axis_point_m"] = {r.axis.point[0], 0.0, r.axis.point[1]};
  j["axis_point_m_stderr"] = {r.axisPointStderr[0], 0.0, r.axisPointStderr[1]};
  j["axis_direction"] = {r.axis.direction[0], 0.0, r.axis.direction[1]};
  j["axis_direction_stderr"] = {dirStderr[0], 0.0, dirStderr[1]};
  j["rotation_per_N_rad_per_N"] = r.rotationPerN;
  j["rotation_per_N_rad_per_N_stderr"] = r.rotationPerNStderr;
  j["y_lat_per_N_m_per_N"] = r.yLatPerN;
  j["y_lat_per_N_m_per_N_stderr"] = r.yLatPerNStderr;
  j["y_lat_at_max_load_m"] = r.yLatPerN * r.maxForce;
  j["y_lat_at_max_load_m_stderr"] = r.yLatPerNStderr * r.maxForce;
  j["max_load_N"] = r.maxForce;
  j["force_point_m"] = {test.forcePoint.x, 0.0, test.forcePoint.z};
  j["reading_sigma_m"] = r.sigma;
  j["reading_sigma_residual_m"] = r.sigmaResidual;
  j["residual_dof"] = r.residualDof;
  j["sensor_resolution_m"] = test.sensorResolution;
  json levels = json::array();
  for (const auto& lv : r.levels)
    levels.push_back({{"force_N", lv.force}, {"d0_m", lv.plane[0]}, {"dx_rad", lv.plane[1]}, {"dz_rad", lv.plane[2]},
                      {"residual_rms_m", lv.residualRms}});
  j["load_levels"] = levels;
  j["conventions"] =
      "axis point = foot of the perpendicular from the force point, in (x, y, z) with y = 0 the plate plane; "
      "axis_direction is oriented so that a_tw > 0 (y at the force point = theta * a_tw); beta_deg = atan2(e_z, e_x)";
  writeFileAtomically(dir / "static.json", formatJson(j, "static.json"));
  std::vector<PlotMarker> sensors;
  for (const auto& s : test.sensors) sensors.push_back({s.name, s.position});
  char title[160];
  std::snprintf(title, sizeof title, "Static twist axis: {/Symbol b} = %.2f deg, a_{tw} = %.4f m, k_{tw} = %.4g Nm/rad",
                r.betaDeg, r.aTw, r.kTw);
  writeAxesPlot(dir, "static_axis", title, sensors, test.forcePoint, {{"static twist axis", r.axis.point, r.axis.direction}});
}

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

void writeSwingarmOutputs(const SwingarmIdentification& id, const StaticTest& stat, const FrfTest& frf,
                          const std::filesystem::path& dir) {
  writeFileAtomically(dir / "swingarm.yaml",
                      formatSwingarmYaml(id, stat.file.string(), frf.file.string(), stat.forcePoint));
  std::vector<PlotMarker> sensors;
  for (const auto& s : stat.sensors) sensors.push_back({s.name + " (laser)", s.position});
  for (const auto& c : frf.channels) {
    bool shared = false;
    for (auto& s : sensors)
      if (std::hypot(s.position.x - c.position.x, s.position.z - c.position.z) < 1e-4) s.label += "/" + c.name, shared = true;
    if (!shared) sensors.push_back({c.name + " (acc.)", c.position});
  }
  char t[3][96];
  std::snprintf(t[0], 96, "static twist axis, k_{tw} %.4g Nm/rad", id.twist.stiffness.value);
  std::snprintf(t[1], 96, "bending axis, k_{b} %.4g Nm/rad", id.bending.stiffness.value);
  std::snprintf(t[2], 96, "torsion axis, k_{t} %.4g Nm/rad", id.torsion.stiffness.value);
  writeAxesPlot(dir, "swingarm_axes", "Static and modal twist axes (seed Fig. 3, 5, 8)", sensors, stat.forcePoint,
                {{t[0], id.twist.point, id.twist.direction},
                 {t[1], id.bending.point, id.bending.direction},
                 {t[2], id.torsion.point, id.torsion.direction}});
}

void writeCogOutputs(const CogTest& t, const CogResult& r, const std::filesystem::path& dir) {
  nlohmann::json j;
  j["test"] = t.file.string();
  j["frame"] = t.frame;
  j["mass_kg"] = r.mass;
  j["mass_kg_stderr"] = r.massStderr;
  j["cog_m"] = {r.cog[0], r.cog[1], r.cog[2]};
  j["cog_m_stderr"] = {r.cogStderr[0], r.cogStderr[1], r.cogStderr[2]};
  j["centre_of_pressure_fit_rms_m"] = r.residualRms;
  j["method"] = "x_p = x_G - z_G tan(tilt), least squares over all tilt angles (seed section 2.4)";
  writeFileAtomically(dir / "cog.json", formatJson(j, "cog.json"));
  CsvWriter w({"tilt_deg", "tan_tilt", "centre_of_pressure_x_m", "fit_m"});
  const Eigen::Vector3d g = r.cog + t.partOrigin;
  for (size_t i = 0; i < t.tiltDeg.size(); ++i) {
    const double tt = std::tan(t.tiltDeg[i] * M_PI / 180);
    w.beginRow().add(t.tiltDeg[i]).add(tt).add(r.centreOfPressureX[i]).add(g[0] - g[2] * tt);
  }
  writeFileAtomically(dir / "cog_fit.csv", w.getText());
  renderGnuplot(dir, "cog_fit",
                "set datafile separator ','\nset key autotitle columnhead\nset grid\nset xlabel 'tan(tilt)'\n"
                "set ylabel 'centre of pressure x (m)'\nset title 'Tilting rig: x_p = x_G - z_G tan(tilt)'\n"
                "plot 'cog_fit.csv' using 2:3 with points pt 7 title 'measured', '' using 2:4 with lines title 'fit'\n");
}

void writeInertiaOutputs(const InertiaTest& t, const InertiaResult& r, const std::filesystem::path& dir) {
  nlohmann::json j;
  j["test"] = t.file.string();
  j["plate_inertia_kg_m2"] = r.plateInertia;
  j["plate_inertia_kg_m2_stderr"] = r.plateInertiaStderr;
  const char* names[6] = {"I_xx", "I_yy", "I_zz", "I_xy", "I_xz", "I_yz"};
  const int idx[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  for (int k = 0; k < (r.fullTensor ? 6 : 3); ++k) {
    j[std::string(names[k]) + "_kg_m2"] = r.tensor(idx[k][0], idx[k][1]);
    j[std::string(names[k]) + "_kg_m2_stderr"] = r.tensorStderr(idx[k][0], idx[k][1]);
  }
  j["full_tensor"] = r.fullTensor;
  j["about"] = "the part's centre of gravity, part frame; products of inertia I_xy = sum(m x y) sign convention "
               "as entries of the inertia matrix (n^T I n = moment about n)";
  CsvWriter w({"setup", "axis_x", "axis_y", "axis_z", "inertia_kg_m2", "inertia_kg_m2_stderr", "model_kg_m2"});
  nlohmann::json js = nlohmann::json::array();
  for (size_t i = 0; i < t.setups.size(); ++i) {
    const auto& u = t.setups[i];
    const double model = u.axis.dot(r.tensor * u.axis);
    w.beginRow().add(static_cast<double>(i + 1)).add(u.axis[0]).add(u.axis[1]).add(u.axis[2]).add(r.setupInertia[i])
        .add(r.setupInertiaStderr[i]).add(model);
    js.push_back({{"name", u.name}, {"inertia_kg_m2", r.setupInertia[i]}, {"inertia_kg_m2_stderr", r.setupInertiaStderr[i]},
                  {"model_kg_m2", model}});
  }
  j["setups"] = js;
  writeFileAtomically(dir / "inertia.json", formatJson(j, "inertia.json"));
  writeFileAtomically(dir / "inertia_setups.csv", w.getText());
  renderGnuplot(dir, "inertia_setups",
                "set datafile separator ','\nset grid\nset xlabel 'set-up'\nset ylabel 'moment of inertia about CoG (kg m^2)'\n"
                "set title 'Trifilar pendulum: measured (error bars) and fitted tensor'\nset xrange [0.5:*]\nset offsets 0,0.5,0,0\n"
                "plot 'inertia_setups.csv' using 1:5:6 with yerrorbars pt 7 title 'measured', '' using 1:7 with points pt 4 ps 2 title 'n^T I n'\n");
}

}  // namespace motostab::output
