#include "output/map_output.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

#include "output/sweep_output.h"
#include "output/plot_window.h"
#include "output/writer_tools.h"

namespace motostab::output {

using analysis::FailedRoll;
using analysis::ModeBranch;
using analysis::ModeLabel;
using analysis::SweepResult;
using analysis::TurnMapResult;
using analysis::findLabelledBranch;

namespace {

const ModeLabel kMapModes[] = {ModeLabel::Weave, ModeLabel::Wobble};

double toDegrees(double rad) { return rad * 180 / M_PI; }

// "roll_+05.0deg": a folder name per roll that sorts by angle.
std::string makeRollFolder(double roll) {
  std::ostringstream os;
  os << "roll_" << std::showpos << std::fixed << std::setprecision(1) << std::internal << std::setfill('0') << std::setw(6)
     << toDegrees(roll) << "deg";
  return os.str();
}

// The root labelled `label` at speed k (the upper member of a complex pair), or NaN when none is.
std::complex<double> findModeEigenvalue(const SweepResult& sweep, ModeLabel label, size_t k) {
  const ModeBranch* b = findLabelledBranch(sweep.branches, label, k);
  return b ? b->eigenvalue[k] : std::complex<double>(NAN, NAN);
}

// Every speed of the map (each roll's sweep has those that trimmed), ascending.
std::vector<double> listMapSpeeds(const TurnMapResult& map) {
  std::vector<double> v;
  for (const auto& s : map.sweeps) v.insert(v.end(), s.speeds.begin(), s.speeds.end());
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

void writeModeBlocks(const TurnMapResult& map, ModeLabel mode, const std::string& separator, std::ostream& os);

// DIR/map_<mode>.dat: one block per roll (gnuplot `index`), rows speed roll_deg real imag freq damping;
// DIR/grid_<mode>.dat the same as one data set of scans (single blank lines), for pm3d.
void writeModeData(const std::filesystem::path& dir, const TurnMapResult& map, ModeLabel mode) {
  for (const char* kind : {"map_", "grid_"}) {
    std::ostringstream os;
    writeModeBlocks(map, mode, kind[0] == 'm' ? "\n\n" : "\n", os);
    writeFileAtomically(dir / (kind + std::string(toString(mode)) + ".dat"), os.str());
  }
}

// Every speed of the map in every roll's block (NaN where the mode is absent or the point did not trim),
// so that the scans form a grid.
void writeModeBlocks(const TurnMapResult& map, ModeLabel mode, const std::string& separator, std::ostream& os) {
  os << std::setprecision(17) << "# speed_mps roll_deg real imag frequency_hz damping_ratio\n";
  const std::vector<double> speeds = listMapSpeeds(map);
  for (size_t j = 0; j < map.rolls.size(); ++j) {
    const SweepResult& s = map.sweeps[j];
    for (double v : speeds) {
      const size_t k = std::find(s.speeds.begin(), s.speeds.end(), v) - s.speeds.begin();
      const auto l = k < s.speeds.size() ? findModeEigenvalue(s, mode, k) : std::complex<double>(NAN, NAN);
      os << v << " " << toDegrees(map.rolls[j]) << " " << l.real() << " " << l.imag() << " " << calcFrequencyHz(l) << " "
         << calcDampingRatio(l) << "\n";
    }
    os << separator;
  }
}

// One series per mode over every roll's block of its data file (each block a line), coloured by the
// roll angle (column 2) through the palette; weave solid, wobble dashed.
std::string plotPerRoll(const std::string& mode, const std::string& columns, bool first) {
  return (first ? "  plot " : ", \\\n       ") + std::string("'map_") + mode + ".dat' using " + columns +
         ":2 with linespoints pt 7 ps 0.4 lw 1.5 lc palette z dt " + (first ? "1" : "2") + " title " +
         gnuplotText(mode + (first ? " (solid)" : " (dashed)"));
}

// A palette without repeats, dark enough on white at both ends, over the rolls (colour bar in deg).
std::string setRollPalette(const TurnMapResult& map) {
  const double lo = toDegrees(map.rolls.front()), hi = toDegrees(map.rolls.back());
  std::ostringstream os;
  os << std::setprecision(17) << "  set palette defined (0 '#0d0887', 1 '#6a00a8', 2 '#b12a90', 3 '#e16462', 4 '#f2844b', 5 '#c8a000')\n"
     << "  set cbrange [" << lo << ":" << (hi > lo ? hi : lo + 1) << "]\n  set cblabel 'roll angle (deg)'\n";
  if (map.rolls.size() <= 12) {  // a tic at each roll of the map
    os << "  set cbtics (";
    for (size_t j = 0; j < map.rolls.size(); ++j) os << (j ? ", " : "") << toDegrees(map.rolls[j]);
    os << ")\n";
  }
  return os.str();
}

// The map's sweep nearest straight running (smallest |roll|).
size_t findLeastRoll(const TurnMapResult& map) {
  size_t best = 0;
  for (size_t j = 1; j < map.rolls.size(); ++j)
    if (std::abs(map.rolls[j]) < std::abs(map.rolls[best])) best = j;
  return best;
}

void writeMapCsv(const std::filesystem::path& dir, const TurnMapResult& map) {
  CsvWriter csv({"roll_deg", "speed_mps", "mode", "real", "imag", "frequency_hz", "damping_ratio"});
  for (size_t j = 0; j < map.rolls.size(); ++j)
    for (const auto& b : map.sweeps[j].branches)
      for (size_t k = 0; k < map.sweeps[j].speeds.size(); ++k) {
        const auto l = b.eigenvalue[k];
        csv.beginRow().add(toDegrees(map.rolls[j])).add(map.sweeps[j].speeds[k]).add(toString(b.labels[k])).add(l.real()).add(l.imag())
            .add(calcFrequencyHz(l)).addOrEmpty(calcDampingRatio(l));
      }
  writeFileAtomically(dir / "map.csv", csv.getText());
}

}  // namespace

// The plotted modes (weave, wobble) that some roll's sweep has at some speed.
std::vector<ModeLabel> listPresentModes(const TurnMapResult& map) {
  std::vector<ModeLabel> out;
  for (ModeLabel m : kMapModes) {
    bool present = false;
    for (const auto& s : map.sweeps)
      for (const auto& b : s.branches) present = present || std::find(b.labels.begin(), b.labels.end(), m) != b.labels.end();
    if (present) out.push_back(m);
  }
  return out;
}

void writeTurnMapOutputs(const std::filesystem::path& dir, const std::string& name, const TurnMapResult& map) {
  writeMapCsv(dir, map);
  nlohmann::json summary;
  summary["scenario"] = name;
  summary["rolls"] = nlohmann::json::array();
  for (size_t j = 0; j < map.rolls.size(); ++j) {
    nlohmann::json r = makeSweepSummary(name, map.sweeps[j]);
    r["roll_deg"] = toDegrees(map.rolls[j]);
    r["folder"] = makeRollFolder(map.rolls[j]);
    summary["rolls"].push_back(r);
    writeSweepOutputs(dir / makeRollFolder(map.rolls[j]), name + ", roll " + makeRollFolder(map.rolls[j]).substr(5),
                      map.sweeps[j]);
  }
  summary["failed_rolls"] = nlohmann::json::array();  // roll angles where no speed trimmed
  for (const FailedRoll& f : map.failedRolls) summary["failed_rolls"].push_back({{"roll_deg", toDegrees(f.roll)}, {"message", f.message}});
  summary["failed_points"] = map.countFailedPoints();  // the rolls' failed_speeds, counted
  writeFileAtomically(dir / "map_summary.json", formatJson(summary, "map_summary.json"));
  std::vector<std::string> modes;
  for (ModeLabel m : listPresentModes(map)) modes.push_back(toString(m));
  for (ModeLabel m : listPresentModes(map)) writeModeData(dir, map, m);
  if (modes.empty()) return;  // nothing to plot
  std::ostringstream damping;
  damping << "  set multiplot layout 1," << modes.size() << " title " << gnuplotText("Damping ratio over speed and roll: " + name)
          << "\n  set view map\n  set pm3d at b corners2color c1\n  set palette defined (-0.1 'red', 0 'white', 0.3 'blue')\n"
          << "  set cbrange [-0.1:0.3]\n  set cblabel 'damping ratio (-), below 0: unstable'\n"
          << "  set xlabel 'forward speed v (m/s)'\n  set ylabel 'roll angle (deg)'\n  unset key\n";
  for (const auto& m : modes)
    damping << "  set title " << gnuplotText(m) << "\n  splot 'grid_" << m << ".dat' using 1:2:6 with pm3d\n";
  damping << "  unset multiplot\n";
  renderGnuplot(dir, "damping_map", damping.str());
  std::vector<std::complex<double>> named;  // the plotted modes at every roll: the axes
  std::vector<double> reals;
  for (const SweepResult& s : map.sweeps) {
    const auto points = collectNamedPoints(s.branches, listPresentModes(map));
    named.insert(named.end(), points.begin(), points.end());
    for (const auto& l : points) reals.push_back(l.real());
  }
  const LocusWindow window = calcLocusWindow(named);
  const size_t marked = findLeastRoll(map);
  std::ostringstream rollName;
  rollName << std::fixed << std::setprecision(1) << toDegrees(map.rolls[marked]);
  const std::string common = "  set grid\n  set key below\n" + setRollPalette(map);
  std::string loci, realParts, which;
  for (size_t i = 0; i < modes.size(); ++i) {
    loci += plotPerRoll(modes[i], "3:5", i == 0);
    realParts += plotPerRoll(modes[i], "1:3", i == 0);
    which += (i ? " and " : "") + modes[i];
  }
  loci += ", \\\n       keyentry with points pt 6 ps 1.2 lc rgb 'black' title " +
          gnuplotText("speed (m/s) along the " + rollName.str() + " deg loci, arrows: increasing speed");
  renderGnuplot(dir, "root_loci",
                common + "  set title " + gnuplotText("Root loci of " + which + " at each roll: " + name) +
                    "\n  set xlabel 'real part (1/s)'\n  set ylabel 'frequency (Hz)'\n  set yzeroaxis lt -1\n" +
                    formatLocusRanges(window) + makeSpeedMarks(map.sweeps[marked], listPresentModes(map), window, 101) + loci + "\n");
  renderGnuplot(dir, "real_part_vs_speed",
                common + "  set title " + gnuplotText("Real part against speed per roll, " + which + ": " + name) +
                    "\n  set xlabel 'forward speed v (m/s)'\n  set ylabel 'real part (1/s)'\n  set xzeroaxis lt -1\n" +
                    formatRange("y", calcAxisRange(reals)) + realParts + "\n");
}

namespace {

// A damping ratio for the terminal table, "-" where the mode is absent (never "nan").
std::string formatZeta(std::complex<double> l) {
  const double z = calcDampingRatio(l);
  if (!std::isfinite(z)) return "-";
  std::ostringstream os;
  os << std::fixed << std::setprecision(4) << z;
  return os.str();
}

}  // namespace

std::string formatTurnMapTable(const TurnMapResult& map) {
  std::ostringstream os;
  os << std::setw(10) << "roll (deg)" << std::setw(10) << "v (m/s)" << std::setw(16) << "weave zeta" << std::setw(16)
     << "wobble zeta" << "\n";
  for (size_t j = 0; j < map.rolls.size(); ++j) {
    const SweepResult& s = map.sweeps[j];
    const size_t stride = std::max<size_t>(1, (s.speeds.size() - 1) / 4);
    for (size_t k = 0; k < s.speeds.size(); k += stride)
      os << std::fixed << std::setprecision(1) << std::setw(10) << toDegrees(map.rolls[j]) << std::setprecision(2)
         << std::setw(10) << s.speeds[k] << std::setprecision(4) << std::setw(16)
         << formatZeta(findModeEigenvalue(s, ModeLabel::Weave, k)) << std::setw(16)
         << formatZeta(findModeEigenvalue(s, ModeLabel::Wobble, k)) << "\n";
    for (const auto& c : s.criticalSpeeds)
      os << "    critical: " << toString(c.mode) << " " << std::setprecision(4) << c.speed << " m/s ("
         << (c.stabilising ? "stabilising" : "destabilising") << ")\n";
    for (const auto& f : s.failures)
      os << "    not trimmed: " << std::setprecision(4) << f.speed << " m/s (residual " << io::formatNumber(f.residual, 3) << ")\n";
  }
  for (const FailedRoll& f : map.failedRolls)
    os << std::fixed << std::setprecision(1) << std::setw(10) << toDegrees(f.roll) << "  no speed trimmed: " << f.message << "\n";
  os << "(-: the mode is absent at that speed)\n";
  return os.str();
}

}  // namespace motostab::output
