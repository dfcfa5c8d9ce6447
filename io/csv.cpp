#include "io/csv.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "io/input_error.h"
#include "io/input_file.h"
#include "io/number.h"
#include "io/result_error.h"

namespace motostab::io {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

// The fields of one CSV record (RFC 4180, within one line): a field in double quotes may hold commas, and
// "" for a quote; blanks around a field are dropped. An unclosed quote, or text after a closing one, is
// an InputError at its line and column.
std::vector<std::string> splitRecord(const std::string& line, const std::string& source, int lineNo) {
  std::vector<std::string> out;
  size_t i = 0;
  auto fail = [&](const std::string& why) { throw InputError({source, lineNo, static_cast<int>(i + 1), ""}, why); };
  while (true) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::string field;
    if (i < line.size() && line[i] == '"') {
      const size_t open = i++;
      for (;; ++i) {
        if (i >= line.size()) i = open, fail("a quoted field is not closed (a quote inside is written \"\")");
        if (line[i] != '"') field += line[i];
        else if (i + 1 < line.size() && line[i + 1] == '"') field += '"', ++i;
        else break;
      }
      ++i;
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      if (i < line.size() && line[i] != ',') fail("text after a quoted field's closing quote");
    } else {
      const size_t comma = line.find(',', i);
      field = trim(line.substr(i, comma == std::string::npos ? std::string::npos : comma - i));
      if (field.find('"') != std::string::npos) fail("a quote inside an unquoted field (quote the whole field)");
      i = comma == std::string::npos ? line.size() : comma;
    }
    out.push_back(field);
    if (i >= line.size()) return out;
    ++i;  // the comma: another field follows, empty at the end of the line
  }
}

}  // namespace

std::vector<std::string> splitFields(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::string part;
  std::stringstream ss(text);
  while (std::getline(ss, part, separator)) out.push_back(part);
  if (!text.empty() && text.back() == separator) out.push_back("");
  return out;
}

int CsvTable::getColumnIndex(const std::string& name) const {
  for (size_t j = 0; j < header.size(); ++j)
    if (header[j] == name) return static_cast<int>(j);
  std::string have;
  for (const auto& h : header) have += (have.empty() ? "" : ", ") + h;
  throw InputError({source, 0, 0, name}, "no such column (columns: " + have + ")");
}

std::vector<double> extractColumn(const std::vector<std::vector<double>>& rows, int j) {
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& r : rows) out.push_back(r[j]);
  return out;
}

std::vector<double> CsvTable::getColumn(const std::string& name) const { return extractColumn(rows, getColumnIndex(name)); }

CsvTable readCsv(const std::filesystem::path& path, const std::vector<std::string>& textColumns) {
  CsvTable table;
  table.source = path.string();
  std::istringstream in{std::string(stripByteOrderMark(readInputFile(path, kMaxTableFileBytes)))};
  std::string line;
  int lineNo = 0;
  std::vector<int> textIndex;  // per column: its index among the text columns, or -1
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto cells = splitRecord(t, table.source, lineNo);
    if (table.header.empty()) {
      for (size_t j = 0; j < cells.size(); ++j) {
        const std::string& name = cells[j];
        for (size_t k = 0; k < j; ++k)
          if (table.header[k] == name)
            throw InputError({table.source, lineNo, static_cast<int>(j + 1), name},
                             "column '" + name + "' is given twice (columns " + std::to_string(k + 1) + " and " +
                                 std::to_string(j + 1) + ")");
        table.header.push_back(name);
      }
      table.headerLine = lineNo;
      textIndex.assign(cells.size(), -1);
      for (size_t k = 0; k < textColumns.size(); ++k)
        for (size_t j = 0; j < cells.size(); ++j)
          if (table.header[j] == textColumns[k]) textIndex[j] = static_cast<int>(k);
      continue;
    }
    if (cells.size() != table.header.size())
      throw InputError({table.source, lineNo, 0, ""},
                       "expected " + std::to_string(table.header.size()) + " cells, found " +
                           std::to_string(cells.size()));
    std::vector<double> row(cells.size());
    std::vector<std::string> text(textColumns.size());
    for (size_t j = 0; j < cells.size(); ++j) {
      const std::string& c = cells[j];
      if (textIndex[j] >= 0) {
        text[textIndex[j]] = c;
        row[j] = std::nan("");
        continue;
      }
      const auto v = parseFiniteNumber(c);
      if (!v)
        throw InputError({table.source, lineNo, static_cast<int>(j + 1), table.header[j]},
                         "not a finite number: '" + c + "'");
      row[j] = *v;
    }
    table.rows.push_back(std::move(row));
    table.text.push_back(std::move(text));
    table.lineNumbers.push_back(lineNo);
  }
  if (table.header.empty()) throw InputError({table.source, 0, 0, ""}, "no header row");
  return table;
}

CsvWriter::CsvWriter(const std::vector<std::string>& header) : header_(header) {
  for (size_t j = 0; j < header.size(); ++j) text_ += (j ? "," : "") + header[j];
  text_ += "\n";
}

CsvWriter& CsvWriter::beginRow() {
  if (rowStarted_) text_ += "\n";
  rowStarted_ = true;
  column_ = 0;
  ++rows_;
  return *this;
}

CsvWriter& CsvWriter::add(const std::string& cell) {
  if (column_ > 0) text_ += ",";
  text_ += cell;
  ++column_;
  return *this;
}

CsvWriter& CsvWriter::add(double value) {
  if (!std::isfinite(value)) {
    const std::string column = column_ < header_.size() ? "'" + header_[column_] + "'" : std::to_string(column_ + 1);
    const size_t lineStart = text_.rfind('\n');
    throw ResultError("a computed value is not finite (" + formatNumber(value) + "): column " + column + " of row " +
                      std::to_string(rows_) + ", which begins '" + text_.substr(lineStart + 1) +
                      "'; no output was written");
  }
  return add(formatNumber(value));
}

CsvWriter& CsvWriter::addOrEmpty(double value) { return std::isfinite(value) ? add(value) : add(std::string()); }

}  // namespace motostab::io
