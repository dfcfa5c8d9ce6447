#include "output/sweep_output.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <algorithm>
#include <map>
#include <sstream>
#include <stdexcept>

#include "output/plot_window.h"
#include "output/writer_tools.h"

namespace motostab::output {

using analysis::CriticalSpeed;
using analysis::FailedSpeed;
using analysis::LinearModel;
using analysis::ModeBranch;
using analysis::ModeContent;
using analysis::ModeLabel;
using analysis::findLabelledBranch;
using analysis::StableRange;
using analysis::SweepResult;
using analysis::calcStableGridRanges;
using analysis::calcStableSpeedRanges;

double calcFrequencyHz(std::complex<double> l) { return l.imag() / (2 * M_PI); }

double calcDampingRatio(std::complex<double> l) {
  const double mag = std::abs(l);
  return mag > 0 ? -l.real() / mag : std::numeric_limits<double>::quiet_NaN();
}

namespace {

const ModeLabel kPlottedModes[] = {ModeLabel::Weave, ModeLabel::Capsize, ModeLabel::Castor, ModeLabel::Wobble};
// Line colours of the plotted modes, in the order above.
const char* kModeColours[] = {"#1f5fbf", "#c0392b", "#2e8b3e", "#8e44ad"};

// The legend entry of the speed marks.
const char* kSpeedMarkKey = "keyentry with points pt 6 ps 1.2 lc rgb 'black' title 'speed (m/s), arrows: increasing speed'";

const std::vector<ModeLabel> kNamedModes(std::begin(kPlottedModes), std::end(kPlottedModes));

// gnuplot: true on a row of eigenvalues.csv whose mode is none of the plotted ones.
std::string isOtherRow() {
  std::string cond;
  for (ModeLabel m : kPlottedModes) cond += std::string(cond.empty() ? "" : " && ") + "strcol(2) ne '" + toString(m) + "'";
  return cond;
}

// The root locus from eigenvalues.csv, upper half-plane: the other roots grey, each plotted mode in its
// colour, speed marks, the legend's notes (roots off the axes).
std::string plotLocus(const SweepResult& sweep, const std::string& note) {
  std::string cmd = "  plot 'eigenvalues.csv' using ((" + isOtherRow() +
                    ") && $4 >= 0 ? $3 : NaN):5 with points pt 7 ps 0.35 lc rgb '#b0b0b0' title 'other roots'";
  for (size_t m = 0; m < std::size(kPlottedModes); ++m) {
    bool present = false;
    for (const auto& b : sweep.branches)
      present = present || std::find(b.labels.begin(), b.labels.end(), kPlottedModes[m]) != b.labels.end();
    if (!present) continue;
    const std::string name = toString(kPlottedModes[m]);
    cmd += ", \\\n       'eigenvalues.csv' using (strcol(2) eq '" + name + "' && $4 >= 0 ? $3 : NaN):5 with points pt 7 ps 0.55 lc rgb '" +
           kModeColours[m] + "' title " + gnuplotText(name);
  }
  cmd += ", \\\n       " + std::string(kSpeedMarkKey);
  if (!note.empty()) cmd += ", \\\n       keyentry with points pt -1 title " + gnuplotText(note);
  return cmd + "\n";
}

std::string formatSpeed(double v, int decimals) {
  if (decimals < 0) return formatNumber(v);
  std::ostringstream os;
  os << std::fixed << std::setprecision(decimals) << v;
  return os.str();
}

// Shaded stable ranges, or a note that there is none (gnuplot objects and labels numbered from 1).
std::string markStableRanges(const SweepResult& sweep, const std::vector<StableRange>& stable) {
  std::ostringstream os;
  os << "  # Stable speed ranges: every mode but the neutral ones has a negative real part.\n";
  if (stable.empty())
    os << "  set label 1 'no stable speed range in " << formatSpeed(sweep.speeds.front(), 1) << " - "
       << formatSpeed(sweep.speeds.back(), 1) << " m/s' at graph 0.5, graph 0.05 center front\n";
  for (size_t i = 0; i < stable.size(); ++i) {
    const std::string a = formatSpeed(stable[i].start, -1), b = formatSpeed(stable[i].stop, -1);
    os << "  set object " << i + 1 << " rect from " << a << ", graph 0 to " << b
       << ", graph 1 behind fillcolor rgb '#d9efd9' fillstyle solid 1.0 noborder\n"
       << "  set label " << i + 1 << " 'stable " << formatSpeed(stable[i].start, 3) << " - "
       << formatSpeed(stable[i].stop, 3) << " m/s' at " << (stable[i].start + stable[i].stop) / 2
       << ", graph 0.05 center front\n";
  }
  return os.str();
}

// A labelled vertical line at each critical speed (arrows and labels numbered after the ranges').
std::string markCriticalSpeeds(const SweepResult& sweep, size_t firstTag) {
  std::ostringstream os;
  os << "  # Critical speeds: sign changes of a root's real part, named by the root's mode there.\n";
  for (size_t i = 0; i < sweep.criticalSpeeds.size(); ++i) {
    const auto& c = sweep.criticalSpeeds[i];
    const std::string v = formatSpeed(c.speed, -1);
    os << "  set arrow " << firstTag + i << " from " << v << ", graph 0 to " << v
       << ", graph 1 nohead front dashtype 3 linewidth 1.5 linecolor rgb '#303030'\n"
       << "  set label " << firstTag + i << " " << gnuplotText(std::string(toString(c.mode)) + " " + formatSpeed(c.speed, 3) + " m/s") << " at " << v
       << ", graph 0.98 rotate by 90 right offset -0.9,0 front boxed\n";
  }
  return os.str();
}

// Meijaard et al. (2007), Fig. 3: real parts solid, imaginary parts (rad/s) dashed, one line per
// tracked branch. eigenvalues.csv holds one row per branch and speed, speed-major, so `every N::B`
// picks branch B's rows in speed order.
std::string plotBranches(const SweepResult& sweep, const std::string& note) {
  const size_t n = sweep.branches.size();
  std::string cmd = "  plot ";
  bool first = true;
  auto add = [&](const std::string& series) {
    cmd += (first ? "" : ", \\\n       ") + series;
    first = false;
  };
  const std::string style = sweep.speeds.size() > 1 ? "lines" : "linespoints pointtype 7";  // one speed: a point
  bool otherTitled = false;  // the other roots' real parts, thin and grey, behind the plotted modes
  for (size_t b = 0; b < n; ++b) {
    if (std::find(std::begin(kPlottedModes), std::end(kPlottedModes), sweep.branches[b].label) != std::end(kPlottedModes)) continue;
    add("'eigenvalues.csv' every " + std::to_string(n) + "::" + std::to_string(b) + " using 1:3 with " + style +
        " linecolor rgb '#b8b8b8' linewidth 1 " + (otherTitled ? "notitle" : "title 'other roots, real part'"));
    otherTitled = true;
  }
  for (size_t m = 0; m < std::size(kPlottedModes); ++m) {
    const std::string colour = std::string("linecolor rgb '") + kModeColours[m] + "' linewidth 2";
    bool titled = false, imagDrawn = false;
    for (size_t b = 0; b < n; ++b) {
      const ModeBranch& br = sweep.branches[b];
      if (br.label != kPlottedModes[m]) continue;
      const std::string rows = "'eigenvalues.csv' every " + std::to_string(n) + "::" + std::to_string(b);
      const std::string name = toString(br.label);
      add(rows + " using 1:3 with " + style + " " + colour + " dashtype 1 " +
          (titled ? "notitle" : "title " + gnuplotText(name + ", real part")));
      titled = true;
      bool complex = false;  // one dashed line per complex pair, |imag| in rad/s where it is complex
      for (const auto& l : br.eigenvalue) complex = complex || std::abs(l.imag()) > 1e-9;
      if (!complex || imagDrawn) continue;
      add(rows + " using 1:(abs($4) > 1e-9 ? abs($4) : NaN) with " + style + " " + colour + " dashtype 2 title " +
          gnuplotText(name + ", imaginary part"));
      imagDrawn = true;
    }
  }
  if (!note.empty()) add("keyentry with lines linecolor rgb '#b8b8b8' title " + gnuplotText(note));
  return first ? "  plot NaN notitle\n" : cmd + "\n";
}

std::string makeRootLocusPlot(const std::string& name, const SweepResult& sweep) {
  const LocusWindow window = calcLocusWindow(collectNamedPoints(sweep.branches, kNamedModes));
  const std::string note = formatLocusNote(findHiddenRoots(window, collectOtherRoots(sweep.branches, kNamedModes)));
  return "  set datafile separator ','\n  set datafile columnheaders\n  set grid\n  set key below\n"
         "  set title " + gnuplotText("Root locus: " + name) + "\n"
         "  set xlabel 'real part (1/s)'\n  set ylabel 'frequency (Hz)'\n  set yzeroaxis linetype -1\n" +
         formatLocusRanges(window) + makeSpeedMarks(sweep, kNamedModes, window, 101) + plotLocus(sweep, note);
}

std::string makeEigenvaluePlot(const std::string& name, const SweepResult& sweep) {
  const std::vector<StableRange> stable = calcStableSpeedRanges(sweep);
  // One speed: a range of 1 m/s around it (gnuplot cannot draw an empty range).
  const double first = sweep.speeds.front(), last = sweep.speeds.back(), pad = first < last ? 0 : 0.5;
  // Vertical axis: the plotted modes' real parts and imaginary parts (where drawn), each where the root
  // carries the mode's label; the other roots beyond it are counted in the legend.
  std::vector<double> values;
  std::vector<std::vector<std::complex<double>>> others;
  for (const ModeBranch& b : sweep.branches) {
    const bool plotted = std::find(kNamedModes.begin(), kNamedModes.end(), b.label) != kNamedModes.end();
    const auto below = std::count_if(b.eigenvalue.begin(), b.eigenvalue.end(), [](auto l) { return l.imag() < 0; });
    if (!plotted && 2 * size_t(below) <= b.eigenvalue.size()) others.push_back(b.eigenvalue);  // a pair counted once
    for (size_t k = 0; plotted && k < b.eigenvalue.size(); ++k)
      if (b.labels[k] == b.label) values.push_back(b.eigenvalue[k].real()), values.push_back(std::abs(b.eigenvalue[k].imag()));
  }
  const AxisRange yrange = calcAxisRange(values);
  return "  set datafile separator ','\n  set datafile columnheaders\n  set grid\n"
         "  set key below\n  set style textbox opaque noborder\n"
         "  set title " + gnuplotText("Eigenvalues against speed: " + name) + "\n"
         "  set xlabel 'forward speed v (m/s)'\n"
         "  set ylabel 'eigenvalue: real part (1/s, solid), imaginary part (rad/s, dashed)'\n"
         "  set xzeroaxis linetype -1\n"
         "  set xrange [" + formatSpeed(std::max(0.0, first - pad), -1) + ":" + formatSpeed(last + pad, -1) + "]\n" +
         formatRange("y", yrange) +
         markStableRanges(sweep, stable) + markCriticalSpeeds(sweep, std::max<size_t>(stable.size(), 1) + 1) +
         plotBranches(sweep, formatRealPartNote(findHiddenRealParts(yrange, others)));
}

}  // namespace

std::string makeSpeedMarks(const SweepResult& sweep, const std::vector<ModeLabel>& modes, const LocusWindow& window, int firstTag,
                           int count) {
  std::ostringstream os;
  os << std::setprecision(17) << "  # Speed marks: the speed (m/s) and an arrowhead towards the next speed of the grid.\n";
  const size_t n = sweep.speeds.size();
  if (n < 2) return os.str();
  int tag = firstTag;
  std::vector<size_t> marked;
  std::vector<std::pair<double, double>> placed;  // marks placed, as fractions of the axes
  for (int i = 0; i < count; ++i) marked.push_back(static_cast<size_t>(std::lround(i * double(n - 1) / std::max(1, count - 1))));
  marked.erase(std::unique(marked.begin(), marked.end()), marked.end());
  for (ModeLabel m : modes)
    for (size_t k : marked) {
      const ModeBranch* b = findLabelledBranch(sweep.branches, m, k);
      if (!b || b->eigenvalue[k].imag() < 0 || !window.contains(b->eigenvalue[k])) continue;
      const double x = (b->eigenvalue[k].real() - window.real.lo) / (window.real.hi - window.real.lo);
      const double y = (calcFrequencyHz(b->eigenvalue[k]) - window.frequency.lo) / (window.frequency.hi - window.frequency.lo);
      bool crowded = false;  // a mark within 3 % of the axes of one already placed would hide it
      for (const auto& [px, py] : placed) crowded = crowded || (std::abs(x - px) < 0.03 && std::abs(y - py) < 0.03);
      if (crowded) continue;
      placed.push_back({x, y});
      const size_t from = k + 1 < n ? k : k - 1;  // the step to the next speed (the last mark: the step into it)
      const auto p = b->eigenvalue[k], a = b->eigenvalue[from], c = b->eigenvalue[from + 1];
      os << "  set label " << tag << " " << gnuplotQuote(formatSpeed(sweep.speeds[k], sweep.speeds[k] == std::round(sweep.speeds[k]) ? 0 : 1))
         << " at " << p.real() << ", " << calcFrequencyHz(p) << " point pt 6 ps 1.2 offset 0.7,0.7 font ',9' front\n";
      if (std::abs(c - a) > 0)
        os << "  set arrow " << tag << " from " << a.real() << ", " << calcFrequencyHz(a) << " to " << c.real() << ", "
           << calcFrequencyHz(c) << " head filled size screen 0.012,25 linecolor rgb 'black' front\n";
      ++tag;
    }
  return os.str();
}

std::vector<std::string> getPlottedModes() {
  std::vector<std::string> names;
  for (ModeLabel m : kPlottedModes) names.push_back(toString(m));
  return names;
}

nlohmann::json makeSweepSummary(const std::string& name, const SweepResult& sweep) {
  nlohmann::json j;
  j["scenario"] = name;
  j["speeds_mps"] = {{"start", sweep.speeds.front()}, {"stop", sweep.speeds.back()}, {"count", sweep.speeds.size()}};
  nlohmann::json crit = nlohmann::json::array();
  std::map<std::string, nlohmann::json> byMode;
  for (ModeLabel m : kPlottedModes) byMode[toString(m)] = nlohmann::json::array();
  for (const CriticalSpeed& c : sweep.criticalSpeeds) {
    crit.push_back({{"mode", toString(c.mode)},
                    {"speed_mps", c.speed},
                    {"direction", c.stabilising ? "stabilising" : "destabilising"},
                    {"frequency_hz", c.frequency},
                    {"refined", c.refined}});
    byMode[toString(c.mode)].push_back(c.speed);
  }
  j["critical_speeds"] = crit;
  for (const auto& [mode, speeds] : byMode)
    j[mode + "_speed_mps"] = speeds.empty() ? nlohmann::json(nullptr) : speeds[0];
  // Runs of grid speeds where every branch but the neutral ones has a negative real part.
  j["stable_grid_ranges_mps"] = nlohmann::json::array();
  for (const StableRange& r : calcStableGridRanges(sweep)) j["stable_grid_ranges_mps"].push_back({r.start, r.stop});
  // The same ranges bounded by the critical speeds (calcStableSpeedRanges), as the plot shades them.
  j["stable_speed_ranges_mps"] = nlohmann::json::array();
  for (const StableRange& r : calcStableSpeedRanges(sweep)) j["stable_speed_ranges_mps"].push_back({r.start, r.stop});
  // Speeds of the grid that did not trim (left out of everything above).
  j["failed_speeds"] = nlohmann::json::array();
  for (const FailedSpeed& f : sweep.failures)
    j["failed_speeds"].push_back({{"speed_mps", f.speed}, {"residual", f.residual}, {"message", f.message}});
  return j;
}

void writeSweepData(const std::filesystem::path& dir, const std::string& name, const SweepResult& sweep) {
  CsvWriter csv({"speed_mps", "mode", "real", "imag", "frequency_hz", "damping_ratio"});
  for (size_t k = 0; k < sweep.speeds.size(); ++k)
    for (const auto& b : sweep.branches) {
      const auto l = b.eigenvalue[k];
      csv.beginRow().add(sweep.speeds[k]).add(toString(b.labels[k])).add(l.real()).add(l.imag()).add(calcFrequencyHz(l)).addOrEmpty(
          calcDampingRatio(l));
    }
  writeFileAtomically(dir / "eigenvalues.csv", csv.getText());
  writeFileAtomically(dir / "summary.json", formatJson(makeSweepSummary(name, sweep), "summary.json"));
}

void writeSweepOutputs(const std::filesystem::path& dir, const std::string& name, const SweepResult& sweep) {
  writeSweepData(dir, name, sweep);
  renderGnuplot(dir, "root_locus", makeRootLocusPlot(name, sweep));
  renderGnuplot(dir, "real_part_vs_speed", makeEigenvaluePlot(name, sweep));
}

namespace {

// The table's columns: the lateral modes, the compliance modes, and any other label that names a
// critical speed, in label order, those present at some speed.
std::vector<ModeLabel> listTableModes(const SweepResult& sweep) {
  std::vector<bool> wanted(analysis::kNumModeLabels, false), present(analysis::kNumModeLabels, false);
  for (ModeLabel m : {ModeLabel::Weave, ModeLabel::Wobble, ModeLabel::Capsize, ModeLabel::Castor, ModeLabel::SwingarmBending,
                      ModeLabel::SwingarmTorsion, ModeLabel::SwingarmTwist, ModeLabel::ForkBending, ModeLabel::ForkTorsion,
                      ModeLabel::RiderLean})
    wanted[static_cast<int>(m)] = true;
  for (const CriticalSpeed& c : sweep.criticalSpeeds) wanted[static_cast<int>(c.mode)] = true;
  for (const auto& b : sweep.branches)
    for (ModeLabel l : b.labels) present[static_cast<int>(l)] = true;
  std::vector<ModeLabel> out;
  for (int m = 0; m < analysis::kNumModeLabels; ++m)
    if (wanted[m] && present[m]) out.push_back(static_cast<ModeLabel>(m));
  return out;
}

// "real +/- imag i" of the root labelled m at speed k (the upper member of a pair), or "absent".
std::string formatModeCell(const SweepResult& sweep, ModeLabel m, size_t k) {
  const ModeBranch* b = findLabelledBranch(sweep.branches, m, k);
  if (!b) return "absent";
  const auto l = b->eigenvalue[k];
  std::ostringstream cell;
  cell << std::setprecision(4) << std::fixed << l.real();
  if (std::abs(l.imag()) > 1e-9) cell << " +/- " << std::abs(l.imag()) << "i";
  return cell.str();
}

}  // namespace

std::string formatSweepTable(const SweepResult& sweep, int rows) {
  std::ostringstream os;
  os << std::setw(8) << "v (m/s)";
  const std::vector<ModeLabel> shown = listTableModes(sweep);
  for (ModeLabel m : shown) os << std::setw(26) << toString(m);
  os << "\n";
  const size_t n = sweep.speeds.size();
  const size_t stride = std::max<size_t>(1, (n - 1) / std::max(1, rows - 1));
  for (size_t k = 0; k < n; k += stride) {
    os << std::fixed << std::setprecision(2) << std::setw(8) << sweep.speeds[k];
    for (ModeLabel m : shown) os << std::setw(26) << formatModeCell(sweep, m, k);
    os << "\n";
  }
  os << "(absent: no root has that mode at that speed; eigenvalues.csv has every root at every speed)\n";
  os << "Critical speeds:\n";
  if (sweep.criticalSpeeds.empty()) os << "  none in the range\n";
  for (const CriticalSpeed& c : sweep.criticalSpeeds) {
    os << "  " << std::setw(8) << toString(c.mode) << " " << std::setprecision(10) << std::fixed << c.speed << " m/s ("
       << (c.stabilising ? "stabilising" : "destabilising");
    if (c.frequency > 0) os << ", " << std::setprecision(2) << c.frequency << " Hz";
    if (!c.refined) os << ", interpolated: a speed near it did not trim";
    os << ")\n";
  }
  const std::vector<StableRange> stable = calcStableSpeedRanges(sweep);
  if (stable.empty())
    os << "No stable speed range in " << formatSpeed(sweep.speeds.front(), 2) << " - " << formatSpeed(sweep.speeds.back(), 2)
       << " m/s\n";
  for (const StableRange& r : stable)
    os << "Stable from " << formatSpeed(r.start, 4) << " to " << formatSpeed(r.stop, 4) << " m/s\n";
  for (const FailedSpeed& f : sweep.failures)
    os << "Not trimmed: " << formatSpeed(f.speed, 4) << " m/s (residual " << io::formatNumber(f.residual, 3) << ")\n";
  return os.str();
}

void writeLinearModel(const std::filesystem::path& dir, const LinearModel& lin, const std::vector<ModeContent>& contents) {
  if (lin.labels.size() != static_cast<size_t>(lin.eigenvalues.size()) ||
      (!contents.empty() && contents.size() != lin.labels.size()))
    throw std::logic_error("writeLinearModel: one mode label (and content, if any) per eigenvalue needed");
  std::vector<std::string> names;
  for (const auto& s : lin.states) names.push_back(s.name);
  auto matrixCsv = [&](const Eigen::MatrixXd& M, const std::vector<std::string>& cols) {
    std::vector<std::string> header{"state"};
    header.insert(header.end(), cols.begin(), cols.end());
    CsvWriter w(header);
    for (int i = 0; i < M.rows(); ++i) {
      w.beginRow().add(names[i]);
      for (int j = 0; j < M.cols(); ++j) w.add(M(i, j));
    }
    return w.getText();
  };
  writeFileAtomically(dir / "A.csv", matrixCsv(lin.A, names));
  writeFileAtomically(dir / "B.csv", matrixCsv(lin.B, lin.inputNames));
  CsvWriter ev({"index", "mode", "real", "imag", "frequency_hz", "damping_ratio"});
  std::vector<std::string> vecHeader{"state"};
  for (int k = 0; k < lin.eigenvalues.size(); ++k) {
    const auto l = lin.eigenvalues[k];
    ev.beginRow().add(std::to_string(k)).add(toString(lin.labels[k])).add(l.real()).add(l.imag()).add(calcFrequencyHz(l)).addOrEmpty(calcDampingRatio(l));
    vecHeader.push_back("re_" + std::to_string(k));
    vecHeader.push_back("im_" + std::to_string(k));
  }
  CsvWriter vec(vecHeader);
  for (size_t i = 0; i < names.size(); ++i) {
    vec.beginRow().add(names[i]);
    for (int k = 0; k < lin.eigenvalues.size(); ++k) vec.add(lin.eigenvectors(i, k).real()).add(lin.eigenvectors(i, k).imag());
  }
  writeFileAtomically(dir / "eigenvalues.csv", ev.getText());
  writeFileAtomically(dir / "eigenvectors.csv", vec.getText());
  nlohmann::json j;
  j["speed_mps"] = lin.speed;
  j["roll_rad"] = lin.roll;
  j["heading_frame"] = lin.headingFrame;  // about a steady turn: vx, vy along and across the heading
  j["states"] = names;
  j["inputs"] = lin.inputNames;
  auto rows = [](const Eigen::MatrixXd& M) {
    nlohmann::json out = nlohmann::json::array();
    for (int i = 0; i < M.rows(); ++i) {
      std::vector<double> row(M.cols());
      for (int c = 0; c < M.cols(); ++c) row[c] = M(i, c);
      out.push_back(row);
    }
    return out;
  };
  j["A"] = rows(lin.A);
  j["B"] = rows(lin.B);
  j["eigenvalues"] = nlohmann::json::array();
  for (int k = 0; k < lin.eigenvalues.size(); ++k) j["eigenvalues"].push_back({lin.eigenvalues[k].real(), lin.eigenvalues[k].imag()});
  j["modes"] = nlohmann::json::array();  // each eigenvalue's label and content shares (by state role)
  for (int k = 0; k < lin.eigenvalues.size(); ++k) {
    nlohmann::json m{{"index", k}, {"mode", toString(lin.labels[k])}};
    if (!contents.empty()) {
      nlohmann::json shares = nlohmann::json::object();
      for (int r = 0; r < vehicle::kNumStateRoles; ++r)
        if (contents[k].role[r] > 0) shares[plugins::toString(static_cast<vehicle::StateRole>(r))] = contents[k].role[r];
      m["content"] = shares;
    }
    j["modes"].push_back(m);
  }
  writeFileAtomically(dir / "linear_model.json", formatJson(j, "linear_model.json"));
}

}  // namespace motostab::output
