#pragma once
// Strict numeric CSV reading and full-precision CSV writing.
#include <filesystem>
#include <string>
#include <vector>

#include "io/number.h"  // formatNumber, the cells' format

namespace motostab::io {

/// A numeric table read from a CSV file with a header row. Lines starting with '#' and blank
/// lines are comments.
/// Column j of row-major numeric rows (rows[i][j]), in row order; units those of the column.
std::vector<double> extractColumn(const std::vector<std::vector<double>>& rows, int j);

/// A table read by readCsv: fields are separated by commas and may be quoted as RFC 4180 says ("weave",
/// "a, b", "" for a quote), within one line; blanks around fields are dropped.
struct CsvTable {
  std::string source;                     ///< file path, for messages
  std::vector<std::string> header;        ///< column names
  std::vector<std::vector<double>> rows;  ///< rows[i][j]: row i, column j
  std::vector<int> lineNumbers;           ///< 1-based file line of each row
  int headerLine = 0;                     ///< 1-based file line of the header
  /// Cells of the text columns asked for (readCsv's textColumns), text[i][k] for row i and the
  /// k-th such column; their numeric cells in `rows` are NaN.
  std::vector<std::vector<std::string>> text;

  /// Index of a named column; throws InputError naming the file and the column if absent.
  int getColumnIndex(const std::string& name) const;
  /// One column's values by name.
  std::vector<double> getColumn(const std::string& name) const;
};

/// Reads a CSV file: a regular file of at most kMaxTableFileBytes (io/input_file.h); a leading UTF-8
/// byte order mark is skipped; a column name given twice is an InputError. Every non-comment row must have as many numeric cells as the header; a bad
/// cell is an InputError naming the file, line and column name. Columns named in `textColumns`
/// (if present) are kept as text (CsvTable::text) instead.
CsvTable readCsv(const std::filesystem::path& path, const std::vector<std::string>& textColumns = {});

/// Splits `text` at every `separator`; a trailing separator yields a trailing empty field.
std::vector<std::string> splitFields(const std::string& text, char separator);

/// Builds CSV text row by row; cells are strings or numbers (written with 17 significant digits).
/// Every number is checked: a non-finite one is a ResultError naming its column and row, so no output
/// holds "nan" or "inf". A value that may be undefined by design (no crossing, a root at the origin's
/// damping ratio) goes through addOrEmpty: an empty cell where the JSON outputs have null.
class CsvWriter {
 public:
  explicit CsvWriter(const std::vector<std::string>& header);
  CsvWriter& beginRow();
  /// A finite number; a NaN or infinity throws ResultError.
  CsvWriter& add(double value);
  /// A number, or an empty cell when it is not finite (undefined).
  CsvWriter& addOrEmpty(double value);
  CsvWriter& add(const std::string& text);
  /// The whole CSV text, newline-terminated.
  std::string getText() const { return rowStarted_ ? text_ + "\n" : text_; }

 private:
  std::vector<std::string> header_;
  std::string text_;
  size_t rows_ = 0;    ///< rows begun
  size_t column_ = 0;  ///< cells of the current row so far
  bool rowStarted_ = false;
};

}  // namespace motostab::io
