#include "simulation/simulation_output.h"

#include <algorithm>

#include "io/atomic_file.h"
#include "io/csv.h"
#include "io/plot.h"
#include "response/response_csv.h"

namespace motostab::simulation {

void writeTimeseries(const std::filesystem::path& dir, const SimulationResult& result) {
  CsvWriter csv(result.columns);
  for (const auto& row : result.rows) {
    csv.beginRow();
    for (double v : row) csv.add(v);
  }
  writeFileAtomically(dir / "timeseries.csv", csv.getText());
}

void writeResponsePlot(const std::filesystem::path& dir, const SimulationResult& result, const std::string& title) {
  static const std::vector<std::string> rigid{"yaw", "roll", "pitch", "height", "x", "y",
                                              "steer", "rear_wheel_angle", "front_wheel_angle"};
  // Panels: column name, scale to plotted units, axis label.
  struct Panel {
    std::string column;
    std::string label;
  };
  std::vector<Panel> panels{{"roll", "roll (deg)"}, {"steer", "steer (deg)"}, {"yaw_rate", "yaw rate (deg/s)"}};
  for (int j = 1; j <= result.numQ; ++j) {
    const std::string& n = result.columns[j];
    if (std::find(rigid.begin(), rigid.end(), n) == rigid.end()) panels.push_back({n, n + " (rad or m)"});
  }
  std::string body = "  set datafile separator ','\n  set grid\n  set key off\n  set xlabel 'time (s)'\n";
  body += "  set multiplot layout " + std::to_string(panels.size()) + ",1 title " + gnuplotQuote(title) + "\n";
  for (const auto& p : panels) {
    const int col = result.getColumnIndex(p.column) + 1;
    const bool angle = p.label.find("deg") != std::string::npos;
    body += "  set ylabel " + gnuplotQuote(p.label) + " noenhanced\n  plot 'timeseries.csv' skip 1 using 1:($" +
            std::to_string(col) + (angle ? "*180/pi" : "") + ") with lines lw 2\n";
  }
  body += "  unset multiplot\n";
  renderGnuplot(dir, "response", body);
}

double getFreeResponseStart(const std::vector<Perturbation>& perturbations) {
  double t = 0;
  for (const auto& p : perturbations)
    if (p.isPulse()) t = std::max(t, p.start + p.duration);
  return t;
}

namespace {
response::ResponseRecord makeRecord(const SimulationResult& result, const std::vector<std::string>& signals) {
  response::ResponseRecord record;
  record.source = "simulation";
  record.timeColumn = "time";
  record.signalColumns = signals;
  record.time = result.getColumn("time");
  for (const auto& s : signals) record.signals.push_back(result.getColumn(s));
  return record;
}
}  // namespace

response::IdentificationResult identifySimulatedModes(const SimulationResult& result, double windowStart,
                                                      const std::vector<std::string>& signals,
                                                      response::IdentificationOptions options) {
  const auto record = makeRecord(result, signals);
  options.windowStart = std::max(options.windowStart, windowStart);
  return response::identifyModes(record.time, record.signals, options);
}

response::IdentificationResult writeSimulatedModes(const std::filesystem::path& dir, const SimulationResult& result,
                                                   double windowStart, const nlohmann::json& settings,
                                                   const std::vector<std::string>& signals) {
  const auto record = makeRecord(result, signals);
  const auto modes = identifySimulatedModes(result, windowStart, signals);
  response::writeResponseReport(dir, record, modes, {{"simulation", settings}});
  return modes;
}

}  // namespace motostab::simulation
