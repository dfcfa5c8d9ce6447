#pragma once
// Mode identification of CSV records: the work behind `motostab identify response`, reusable by
// `motostab simulate --identify`. Their outputs (modes.json, fit plot) are written by output/response_output.h.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "response/mode_identification.h"

namespace motostab::response {

/// Which columns of which CSV to fit, and how.
struct CsvIdentificationRequest {
  std::filesystem::path csv;
  std::vector<std::string> signalColumns;  ///< one or more; fitted jointly with shared modes
  std::string timeColumn;                  ///< s; empty = the first column
  IdentificationOptions options;
};

/// A record read for identification.
struct ResponseRecord {
  std::string source;                      ///< file, for messages
  std::string timeColumn;
  std::vector<std::string> signalColumns;
  std::vector<double> time;                ///< s, strictly increasing
  std::vector<std::vector<double>> signals;  ///< one vector per signal column
};

/// Parses "T0:T1" (s) into the options' window. Throws InputError (key "--window") naming `source`.
void setWindowFromText(const std::string& text, const std::string& source, IdentificationOptions& options);

/// Reads the time and signal columns of `request.csv`. Throws InputError naming the file, line and column
/// for a missing column, a malformed cell, or time that is not strictly increasing.
ResponseRecord readResponseRecord(const CsvIdentificationRequest& request);

/// Reads the CSV and identifies its modes. Bad input (including a window outside the data) is an InputError
/// naming the file and the columns.
IdentificationResult identifyModesFromCsv(const CsvIdentificationRequest& request, ResponseRecord* record = nullptr);

}  // namespace motostab::response
