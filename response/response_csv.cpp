#include "response/response_csv.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "io/csv.h"
#include "io/input_error.h"
#include "io/number.h"

namespace motostab::response {

using io::CsvTable;
using io::InputError;
using io::formatNumber;
using io::parseFiniteNumber;
using io::readCsv;

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
  } catch (const InputError& e) {  // bad samples or window: located in the CSV file
    throw InputError({record.source, 0, 0, joinColumns(record.signalColumns)},
                     e.getReason() + " (time column '" + record.timeColumn + "')");
  }
  if (recordOut) *recordOut = std::move(record);
  return result;
}

}  // namespace motostab::response
