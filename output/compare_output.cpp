#include "output/compare_output.h"

#include <array>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "output/scenario_output.h"
#include "output/sweep_output.h"
#include "output/plot_window.h"
#include "output/writer_tools.h"

namespace motostab::output {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Distinct line colours, one per scenario (repeating after eight).
const char* kScenarioColours[] = {"#1f5fbf", "#c0392b", "#2e8b3e", "#8e44ad", "#d35400", "#16a085", "#7f8c8d", "#b7950b"};
const char* getColour(size_t i) { return kScenarioColours[i % std::size(kScenarioColours)]; }

// Point type (root locus) and dash type (real parts) of each plotted mode, by its place in getPlottedModes().
int getPointType(size_t mode) { return std::array<int, 4>{7, 5, 9, 13}[mode % 4]; }
int getDashType(size_t mode) { return static_cast<int>(mode % 4) + 1; }

nlohmann::json toJsonOrNull(double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); }

std::string formatCell(double v, bool sign) {
  if (std::isnan(v)) return "-";
  std::ostringstream os;
  os << std::fixed << std::setprecision(4) << (sign ? std::showpos : std::noshowpos) << v;
  return os.str();
}

std::vector<analysis::ModeLabel> getNamedModes() {
  std::vector<analysis::ModeLabel> out;
  for (const std::string& m : getPlottedModes()) out.push_back(*analysis::parseModeLabel(m));
  return out;
}

// Root locus: every scenario's labelled modes as points (upper half-plane), colour per scenario, point
// type per mode; the axes fitted to all of them; the speed marked along the first scenario's loci.
std::string makeRootLocusPlot(const std::vector<ComparedSweep>& sweeps) {
  const std::vector<std::string> modes = getPlottedModes();
  std::vector<std::complex<double>> named;
  for (const ComparedSweep& c : sweeps) {
    const auto points = collectNamedPoints(c.sweep.branches, getNamedModes());
    named.insert(named.end(), points.begin(), points.end());
  }
  const LocusWindow window = calcLocusWindow(named);
  std::string cmd;
  for (size_t i = 0; i < sweeps.size(); ++i)
    for (size_t m = 0; m < modes.size(); ++m) {
      bool present = false;
      for (const auto& b : sweeps[i].sweep.branches) present = present || analysis::toString(b.label) == modes[m];
      if (!present) continue;
      cmd += std::string(cmd.empty() ? "  plot " : ", \\\n       ") + gnuplotQuote(sweeps[i].label + "/eigenvalues.csv") +
             " using (strcol(2) eq '" + modes[m] + "' && $4 >= 0 ? $3 : NaN):5 with points pt " + std::to_string(getPointType(m)) +
             " ps 0.6 linecolor rgb '" + getColour(i) + "' title " + gnuplotText(sweeps[i].label + " " + modes[m]);
    }
  if (!cmd.empty())
    cmd += ", \\\n       keyentry with points pt 6 ps 1.2 lc rgb 'black' title " +
           gnuplotText("speed (m/s) along " + sweeps.front().label + ", arrows: increasing speed");
  return "  set datafile separator ','\n  set datafile columnheaders\n  set grid\n  set key below\n"
         "  set title 'Root loci compared'\n  set xlabel 'real part (1/s)'\n  set ylabel 'frequency (Hz)'\n"
         "  set yzeroaxis linetype -1\n" +
         formatLocusRanges(window) + makeSpeedMarks(sweeps.front().sweep, getNamedModes(), window, 101) + (cmd.empty() ? "  plot NaN notitle" : cmd) + "\n";
}

// Real parts against speed: one line per labelled branch (eigenvalues.csv holds one row per branch
// and speed, speed-major, so `every N::B` is branch B), colour per scenario, dash type per mode.
std::string makeRealPartPlot(const std::vector<ComparedSweep>& sweeps) {
  const std::vector<std::string> modes = getPlottedModes();
  std::string cmd;
  std::vector<double> values;  // the drawn real parts where the root carries the mode's label: the vertical axis
  for (size_t i = 0; i < sweeps.size(); ++i) {
    const auto& branches = sweeps[i].sweep.branches;
    std::set<size_t> titled;
    for (size_t b = 0; b < branches.size(); ++b)
      for (size_t m = 0; m < modes.size(); ++m) {
        if (analysis::toString(branches[b].label) != modes[m]) continue;
        const std::string title = titled.insert(m).second ? "title " + gnuplotText(sweeps[i].label + " " + modes[m]) : "notitle";
        for (size_t k = 0; k < branches[b].eigenvalue.size(); ++k)
          if (analysis::toString(branches[b].labels[k]) == modes[m]) values.push_back(branches[b].eigenvalue[k].real());
        cmd += std::string(cmd.empty() ? "  plot " : ", \\\n       ") + gnuplotQuote(sweeps[i].label + "/eigenvalues.csv") +
               " every " + std::to_string(branches.size()) + "::" + std::to_string(b) + " using 1:3 with lines linecolor rgb '" +
               getColour(i) + "' dashtype " + std::to_string(getDashType(m)) + " linewidth 2 " + title;
      }
  }
  return "  set datafile separator ','\n  set datafile columnheaders\n  set grid\n  set key below\n"
         "  set title 'Real parts against speed compared (below zero: stable)'\n  set xlabel 'forward speed v (m/s)'\n"
         "  set ylabel 'real part (1/s)'\n  set xzeroaxis linetype -1\n" + formatRange("y", calcAxisRange(values)) +
         (cmd.empty() ? "  plot NaN notitle" : cmd) + "\n";
}

void writeCriticalSpeedsCsv(const std::filesystem::path& dir, const std::vector<ComparedSweep>& sweeps,
                            const std::vector<CriticalSpeedRow>& rows) {
  std::vector<std::string> header{"mode", "direction", "occurrence"};
  for (size_t i = 0; i < sweeps.size(); ++i) {
    header.push_back(sweeps[i].label + "_speed_mps");
    if (i > 0) header.push_back(sweeps[i].label + "_difference_mps");
  }
  CsvWriter csv(header);
  for (const CriticalSpeedRow& r : rows) {
    csv.beginRow().add(r.mode).add(r.direction).add(std::to_string(r.occurrence));
    for (size_t i = 0; i < sweeps.size(); ++i) {
      csv.add(r.speeds[i]);
      if (i > 0) csv.add(r.differences[i]);
    }
  }
  writeFileAtomically(dir / "critical_speeds.csv", csv.getText());
}

}  // namespace

std::vector<std::string> makeCompareLabels(const std::vector<std::string>& names) {
  std::vector<std::string> out;
  std::map<std::string, int> seen;
  for (const std::string& name : names) {
    std::string label = name.empty() ? "scenario" : name;
    for (char& c : label)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-')) c = '_';
    if (label == "." || label == "..") label = "scenario";
    const int n = ++seen[label];
    out.push_back(n == 1 ? label : label + "-" + std::to_string(n));
  }
  return out;
}

std::vector<CriticalSpeedRow> matchCriticalSpeeds(const std::vector<ComparedSweep>& sweeps) {
  std::vector<CriticalSpeedRow> rows;
  std::map<std::tuple<std::string, std::string, int>, size_t> index;
  for (size_t i = 0; i < sweeps.size(); ++i) {
    std::map<std::pair<std::string, std::string>, int> count;
    const nlohmann::json summary = makeSweepSummary(sweeps[i].label, sweeps[i].sweep);
    for (const auto& c : summary.at("critical_speeds")) {
      const std::string mode = c.at("mode"), direction = c.at("direction");
      const int k = ++count[{mode, direction}];
      auto [it, added] = index.insert({{mode, direction, k}, rows.size()});
      if (added) rows.push_back({mode, direction, k, std::vector<double>(sweeps.size(), kNaN), {}});
      rows[it->second].speeds[i] = c.at("speed_mps").get<double>();
    }
  }
  for (CriticalSpeedRow& r : rows)
    for (double v : r.speeds) r.differences.push_back(v - r.speeds[0]);
  return rows;
}

nlohmann::json makeCompareSummary(const std::vector<ComparedSweep>& sweeps) {
  nlohmann::json j;
  const auto& speeds = sweeps.front().sweep.speeds;
  j["speeds_mps"] = {{"start", speeds.front()}, {"stop", speeds.back()}, {"count", speeds.size()}};
  j["reference"] = sweeps.front().label;
  j["scenarios"] = nlohmann::json::array();
  for (const ComparedSweep& c : sweeps)
    j["scenarios"].push_back({{"label", c.label},
                              {"name", c.scenario.name},
                              {"file", c.scenario.sourceFile},
                              {"summary", makeSweepSummary(c.scenario.name, c.sweep)}});
  j["critical_speeds"] = nlohmann::json::array();
  for (const CriticalSpeedRow& r : matchCriticalSpeeds(sweeps)) {
    nlohmann::json s = nlohmann::json::array(), d = nlohmann::json::array();
    for (size_t i = 0; i < r.speeds.size(); ++i) s.push_back(toJsonOrNull(r.speeds[i])), d.push_back(toJsonOrNull(r.differences[i]));
    j["critical_speeds"].push_back(
        {{"mode", r.mode}, {"direction", r.direction}, {"occurrence", r.occurrence}, {"speeds_mps", s}, {"differences_mps", d}});
  }
  return j;
}

std::string formatCompareTable(const std::vector<ComparedSweep>& sweeps) {
  const std::vector<CriticalSpeedRow> rows = matchCriticalSpeeds(sweeps);
  std::ostringstream os;
  os << "Critical speeds (m/s) and differences against " << sweeps.front().label << ":\n";
  os << std::left << std::setw(10) << "  mode" << std::setw(15) << "direction";
  for (size_t i = 0; i < sweeps.size(); ++i) os << " " << std::setw(i == 0 ? 14 : 26) << sweeps[i].label;
  os << "\n";
  for (const CriticalSpeedRow& r : rows) {
    os << "  " << std::setw(8) << r.mode << std::setw(15) << r.direction + (r.occurrence > 1 ? " #" + std::to_string(r.occurrence) : "");
    for (size_t i = 0; i < sweeps.size(); ++i)
      os << " " << std::setw(i == 0 ? 14 : 26)
         << (i == 0 ? formatCell(r.speeds[i], false) : formatCell(r.speeds[i], false) + " (" + formatCell(r.differences[i], true) + ")");
    os << "\n";
  }
  if (rows.empty()) os << "  none in the range\n";
  return os.str();
}

void writeCompareOutputs(const std::filesystem::path& dir, const std::vector<ComparedSweep>& sweeps) {
  for (const ComparedSweep& c : sweeps) {
    writeSweepData(dir / c.label, c.scenario.name, c.sweep);
    writeScenarioJson(dir / c.label, c.scenario);
  }
  writeFileAtomically(dir / "summary.json", makeCompareSummary(sweeps).dump(2) + "\n");
  writeCriticalSpeedsCsv(dir, sweeps, matchCriticalSpeeds(sweeps));
  renderGnuplot(dir, "root_locus", makeRootLocusPlot(sweeps));
  renderGnuplot(dir, "real_part_vs_speed", makeRealPartPlot(sweeps));
}

}  // namespace motostab::output
