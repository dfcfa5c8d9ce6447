#include "output/response_output.h"

#include <cstdio>

#include "io/atomic_file.h"
#include "io/csv.h"
#include "io/number.h"
#include "io/plot.h"
#include "response/modes_json.h"

namespace motostab::output {

using io::CsvWriter;
using io::formatNumber;
using io::gnuplotQuote;
using io::renderGnuplot;
using io::writeFileAtomically;
using response::IdentificationResult;
using response::ResponseRecord;
using response::calcModelResponse;
using response::makeModesJson;


void writeResponseReport(const std::filesystem::path& dir, const ResponseRecord& record,
                         const IdentificationResult& result, const nlohmann::json& extra) {
  nlohmann::json json = makeModesJson(result, record.signalColumns);
  json["source"] = {{"file", record.source}, {"time_column", record.timeColumn}};
  json.update(extra);
  writeFileAtomically(dir / "modes.json", json.dump(2) + "\n");

  std::vector<std::string> header{record.timeColumn};
  header.insert(header.end(), record.signalColumns.begin(), record.signalColumns.end());
  CsvWriter data(header);
  for (size_t i = 0; i < record.time.size(); ++i) {
    data.beginRow().add(record.time[i]);
    for (const auto& s : record.signals) data.add(s[i]);
  }
  writeFileAtomically(dir / "response_data.csv", data.getText());

  // The model on a grid 10x finer than the samples (at least 500 points) over the window.
  const int points = std::max(500, 10 * result.sampleCount);
  std::vector<double> dense(points);
  for (int i = 0; i < points; ++i)
    dense[i] = result.windowStart + (result.windowEnd - result.windowStart) * i / (points - 1);
  std::vector<std::string> fitHeader{record.timeColumn};
  std::vector<std::vector<double>> model;
  for (size_t s = 0; s < record.signalColumns.size(); ++s) {
    fitHeader.push_back("model_" + record.signalColumns[s]);
    model.push_back(calcModelResponse(result, static_cast<int>(s), dense));
  }
  CsvWriter fit(fitHeader);
  for (int i = 0; i < points; ++i) {
    fit.beginRow().add(dense[i]);
    for (const auto& m : model) fit.add(m[i]);
  }
  writeFileAtomically(dir / "response_fit.csv", fit.getText());

  char title[200] = "no mode";
  if (!result.modes.empty())
    std::snprintf(title, sizeof title, "dominant mode %.4g %+.4gi 1/s (%.4g Hz, damping ratio %.3g), R^2 = %.4f",
                  result.modes.front().real, result.modes.front().imag, result.modes.front().frequencyHz,
                  result.modes.front().dampingRatio, result.rSquared);
  std::string body = "  set datafile separator ','\n  set grid\n  set key top right\n";
  body += "  set multiplot layout " + std::to_string(record.signalColumns.size()) + ",1 title " +
          gnuplotQuote(title) + " noenhanced\n";
  for (size_t s = 0; s < record.signalColumns.size(); ++s) {
    body += "  set xlabel " + gnuplotQuote(record.timeColumn) + " noenhanced\n";
    body += "  set ylabel " + gnuplotQuote(record.signalColumns[s]) + " noenhanced\n";
    for (double t : {result.windowStart, result.windowEnd})
      body += "  set arrow from " + formatNumber(t) + ", graph 0 to " + formatNumber(t) +
              ", graph 1 nohead dt 2 lc rgb 'gray50'\n";
    body += "  plot 'response_data.csv' skip 1 using 1:" + std::to_string(s + 2) +
            " with lines lc rgb 'gray40' title 'record', 'response_fit.csv' skip 1 using 1:" +
            std::to_string(s + 2) + " with lines lw 2 lc rgb 'red' title 'fitted model'\n";
    body += "  unset arrow\n";
  }
  body += "  unset multiplot";
  renderGnuplot(dir, "response_fit", body);
}

}  // namespace motostab::output
