#include "response/response_csv.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "io/number.h"
#include "io/plot.h"
#include "response/modes_json.h"

namespace motostab::response {
namespace {

double parseTime(const std::string& text, const std::string& source, const std::string& window) {
  const auto v = parseFiniteNumber(text);
  if (!v) throw InputError({source, 0, 0, "--window"}, "'" + window + "' is not T0:T1 (two finite times in s)");
  return *v;
}

std::string joinColumns(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ",") + n;
  return out;
}

}  // namespace

void setWindowFromText(const std::string& text, const std::string& source, IdentificationOptions& options) {
  const auto colon = text.find(':');
  if (colon == std::string::npos)
    throw InputError({source, 0, 0, "--window"}, "'" + text + "' is not T0:T1 (two times in s)");
  options.windowStart = parseTime(text.substr(0, colon), source, text);
  options.windowEnd = parseTime(text.substr(colon + 1), source, text);
  if (!(options.windowStart < options.windowEnd))
    throw InputError({source, 0, 0, "--window"}, "'" + text + "': T0 must be before T1");
}

ResponseRecord readResponseRecord(const CsvIdentificationRequest& request) {
  const CsvTable table = readCsv(request.csv);
  ResponseRecord record;
  record.source = table.source;
  if (table.rows.empty()) throw InputError({record.source, 0, 0, ""}, "no data rows");
  if (request.signalColumns.empty()) throw InputError({record.source, 0, 0, ""}, "no signal column given");
  record.timeColumn = request.timeColumn.empty() ? table.header.front() : request.timeColumn;
  record.time = table.getColumn(record.timeColumn);
  for (size_t i = 1; i < record.time.size(); ++i)
    if (!(record.time[i] > record.time[i - 1]))
      throw InputError({record.source, table.lineNumbers[i], table.getColumnIndex(record.timeColumn) + 1,
                        record.timeColumn},
                       "time is not strictly increasing (" + formatNumber(record.time[i], 8) + " after " +
                           formatNumber(record.time[i - 1], 8) + ")");
  for (const auto& name : request.signalColumns) {
    if (name == record.timeColumn)
      throw InputError({record.source, 0, 0, name}, "the signal column is the time column");
    record.signals.push_back(table.getColumn(name));
  }
  record.signalColumns = request.signalColumns;
  return record;
}

IdentificationResult identifyModesFromCsv(const CsvIdentificationRequest& request, ResponseRecord* recordOut) {
  ResponseRecord record = readResponseRecord(request);
  IdentificationResult result;
  try {
    result = identifyModes(record.time, record.signals, request.options);
  } catch (const std::invalid_argument& e) {
    throw InputError({record.source, 0, 0, joinColumns(record.signalColumns)},
                     std::string(e.what()) + " (time column '" + record.timeColumn + "')");
  }
  if (recordOut) *recordOut = std::move(record);
  return result;
}

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

}  // namespace motostab::response
