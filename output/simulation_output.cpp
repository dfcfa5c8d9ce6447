#include "output/simulation_output.h"

#include <algorithm>

#include "output/writer_tools.h"

namespace motostab::output {

using simulation::SimulationResult;

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
  body += "  set multiplot layout " + std::to_string(panels.size()) + ",1 title " + gnuplotText(title) + "\n";
  for (const auto& p : panels) {
    const int col = result.getColumnIndex(p.column) + 1;
    const bool angle = p.label.find("deg") != std::string::npos;
    body += "  set ylabel " + gnuplotQuote(p.label) + " noenhanced\n  plot 'timeseries.csv' skip 1 using 1:($" +
            std::to_string(col) + (angle ? "*180/pi" : "") + ") with lines lw 2\n";
  }
  body += "  unset multiplot\n";
  renderGnuplot(dir, "response", body);
}

}  // namespace motostab::output
