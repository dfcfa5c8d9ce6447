#pragma once
// Strict reader of MF-Tyre property files (.tir, MF 6.1 and 6.2, FITTYP 61 or 62). The format: an
// ASCII file of `[SECTION]` headers and `KEY = VALUE` lines, where a value is a number or a quoted
// string ('Left'); `$` starts a comment anywhere on a line, lines starting with `!` are header
// comments, and a line `{...}` starts a table (rows of numbers, e.g. [SHAPE]) whose rows are kept
// out of the keys. Anything else is malformed: an InputError naming file:line. A number of magnitude
// above io::kMaxMagnitude (1e12, as in YAML and --set) is an InputError at its line and column. A key given twice in
// one section is an error at its second line. The [UNITS] section must say meter, newton, radians,
// kg and second, and pascal if it names PRESSURE (no unit conversion is done). Keys are case-insensitive (stored upper-case).
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "io/input_error.h"

namespace motostab::tyres {

/// One `KEY = VALUE` of a .tir file.
struct TirEntry {
  std::string section;    ///< upper-case section name without brackets
  std::string text;       ///< the value as written (quotes removed)
  bool isNumber = false;
  double number = 0;      ///< the value when isNumber
  int line = 0;           ///< 1-based line
  int column = 0;         ///< 1-based column of the value in its line
};

class TirFile {
 public:
  /// The largest .tir file read, bytes (published property files are tens of kB).
  static constexpr std::uintmax_t kMaxBytes = 4 << 20;
  /// Reads and checks a .tir file (syntax, units, FITTYP 61 or 62). InputError at file:line:column; a
  /// path that is not a regular file (a folder, a device such as /dev/zero, a pipe) or a file larger than
  /// kMaxBytes is an InputError at the path.
  static TirFile load(const std::string& path);
  /// The same from text; `source` names it in errors.
  static TirFile parse(const std::string& text, const std::string& source);

  /// The entry of `key` outside [UNITS] (and [MDI_HEADER]), or nothing. A key present in two such
  /// sections is an InputError at its second line.
  const TirEntry* find(const std::string& key) const;
  /// The number at `key`; InputError at its line if it is a string, at the file if it is missing.
  double getNumber(const std::string& key) const;
  /// 61 or 62 (from [MODEL] FITTYP).
  int getFitType() const { return fitType_; }
  const std::string& getSource() const { return source_; }
  /// Every entry outside [UNITS] and [MDI_HEADER], by upper-case key.
  const std::map<std::string, TirEntry>& getEntries() const { return entries_; }
  /// An InputError at the line and column of `key`'s value (or the file when absent) with `message`.
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  std::string source_;
  int fitType_ = 0;
  std::map<std::string, TirEntry> entries_;  ///< by upper-case key (sections other than UNITS, MDI_HEADER)
  std::map<std::string, TirEntry> units_;    ///< [UNITS] entries
};

}  // namespace motostab::tyres
