#include "tyres/tir_file.h"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "io/number.h"

namespace motostab::tyres {

using io::InputError;
using io::InputLocation;
using io::parseFiniteNumber;


namespace {

std::string trim(const std::string& s) {
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

// The line without its `$` comment (a `$` inside a quoted string is kept).
std::string stripComment(const std::string& line) {
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\'') quoted = !quoted;
    if (line[i] == '$' && !quoted) return line.substr(0, i);
  }
  return line;
}

bool isNumberRow(const std::string& text) {
  std::istringstream in(text);
  std::string field;
  bool any = false;
  while (in >> field) {
    if (!parseFiniteNumber(field)) return false;
    any = true;
  }
  return any;
}

struct Parser {
  std::string source;
  InputLocation at(int line, const std::string& key = "", int column = 0) const { return {source, line, column, key}; }
};

// The value of `key` at `line`: a 'quoted' string, or a finite number (kept as text too).
TirEntry parseEntry(const Parser& p, int line, int column, const std::string& section, const std::string& key,
                    const std::string& value) {
  TirEntry e;
  e.section = section;
  e.line = line;
  e.column = column;
  if (value.size() >= 2 && value.front() == '\'' && value.back() == '\'' &&
      value.find('\'', 1) == value.size() - 1) {
    e.text = value.substr(1, value.size() - 2);
  } else if (const auto number = parseFiniteNumber(value)) {
    if (std::abs(*number) > io::kMaxMagnitude)  // as every YAML number and --set value
      throw InputError(p.at(line, key, column), "'" + value + "': a magnitude above 1e12, beyond any physical parameter");
    e.text = value;
    e.isNumber = true;
    e.number = *number;
  } else {
    throw InputError(p.at(line, key, column), "malformed value '" + value + "' (expected a finite number or a 'quoted' string)");
  }
  return e;
}

// Units: the equations take SI values; nothing is converted. Each [UNITS] entry but PRESSURE (Pa when
// absent) must be given, and in SI.
void checkUnits(const Parser& p, const std::map<std::string, TirEntry>& units) {
  const std::pair<const char*, std::vector<std::string>> si[] = {{"LENGTH", {"METER", "METRE", "M"}},
                                                               {"FORCE", {"NEWTON", "N"}},
                                                               {"ANGLE", {"RADIANS", "RADIAN", "RAD"}},
                                                               {"MASS", {"KG", "KILOGRAM"}},
                                                               {"TIME", {"SECOND", "SEC", "S"}},
                                                               {"PRESSURE", {"PASCAL", "PA", "N/M2", "N/M^2"}}};
  for (const auto& [name, allowed] : si) {
    const auto it = units.find(name);
    if (it == units.end()) {
      if (std::string(name) == "PRESSURE") continue;  // optional: Pa when absent
      throw InputError(p.at(0, name), std::string("[UNITS] ") + name + " missing (the units must be stated; SI only)");
    }
    const std::string u = upper(it->second.text);
    if (std::find(allowed.begin(), allowed.end(), u) == allowed.end())
      throw InputError(p.at(it->second.line, name, it->second.column), "unit '" + it->second.text + "' is not supported (SI only: " +
                                                         allowed.front() + ")");
  }
}

}  // namespace

TirFile TirFile::load(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError({path, 0, 0, ""}, "cannot open the tyre property file: no such file");
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError({path, 0, 0, ""}, "not a regular file (a tyre property file must be a plain .tir file)");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxBytes)
    throw InputError({path, 0, 0, ""}, "larger than " + std::to_string(kMaxBytes >> 20) + " MiB: not a tyre property file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0, ""}, "cannot open the tyre property file");
  std::string text(static_cast<size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  text.resize(static_cast<size_t>(in.gcount()));
  return parse(text, path);
}

TirFile TirFile::parse(const std::string& text, const std::string& source) {
  TirFile f;
  f.source_ = source;
  const Parser p{source};
  std::istringstream in(text);
  std::string raw, section;
  bool inTable = false;
  std::map<std::string, int> seenInSection;
  for (int line = 1; std::getline(in, raw); ++line) {
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    const std::string t = trim(stripComment(raw));
    if (t.empty() || t[0] == '!') continue;
    if (t[0] == '[') {
      if (t.back() != ']' || t.size() < 3) throw InputError(p.at(line), "malformed section header '" + t + "'");
      section = upper(trim(t.substr(1, t.size() - 2)));
      inTable = false;
      seenInSection.clear();
      continue;
    }
    if (t[0] == '{') {
      if (t.back() != '}') throw InputError(p.at(line), "malformed table header '" + t + "'");
      inTable = true;
      continue;
    }
    if (inTable && isNumberRow(t)) continue;
    const size_t eq = t.find('=');
    if (eq == std::string::npos) throw InputError(p.at(line), "malformed line (expected KEY = VALUE): '" + t + "'");
    if (section.empty()) throw InputError(p.at(line), "a value before the first [SECTION]");
    const std::string key = upper(trim(t.substr(0, eq)));
    const std::string value = trim(t.substr(eq + 1));
    if (key.empty() || key.find_first_of(" \t'") != std::string::npos)
      throw InputError(p.at(line), "malformed key '" + trim(t.substr(0, eq)) + "'");
    inTable = false;
    const int column = static_cast<int>(raw.find(value, raw.find('=') + 1)) + 1;  // of the value
    const TirEntry e = parseEntry(p, line, column, section, key, value);
    if (!seenInSection.emplace(key, line).second)
      throw InputError(p.at(line, key, column), "given twice in [" + section + "] (first at line " +
                                            std::to_string(seenInSection[key]) + ")");
    if (section == "UNITS") {
      f.units_[key] = e;
      continue;
    }
    if (section == "MDI_HEADER") continue;
    const auto [it, fresh] = f.entries_.emplace(key, e);
    if (!fresh)
      throw InputError(p.at(line, key, column), "also given in [" + it->second.section + "] at line " +
                                            std::to_string(it->second.line) + ": ambiguous");
  }
  checkUnits(p, f.units_);
  const TirEntry* fit = f.find("FITTYP");
  if (!fit) throw InputError(p.at(0, "FITTYP"), "missing [MODEL] FITTYP (61 or 62 expected)");
  if (!fit->isNumber || (fit->number != 61 && fit->number != 62))
    throw InputError(p.at(fit->line, "FITTYP", fit->column), "unsupported FITTYP " + fit->text +
                                                    " (this reader implements MF 6.1 and 6.2: 61 or 62)");
  f.fitType_ = static_cast<int>(fit->number);
  return f;
}

const TirEntry* TirFile::find(const std::string& key) const {
  const auto it = entries_.find(upper(key));
  return it == entries_.end() ? nullptr : &it->second;
}

double TirFile::getNumber(const std::string& key) const {
  const TirEntry* e = find(key);
  if (!e) fail(key, "missing coefficient (needed by the chosen Magic Formula equations)");
  if (!e->isNumber) fail(key, "must be a number, not '" + e->text + "'");
  return e->number;
}

void TirFile::fail(const std::string& key, const std::string& message) const {
  const TirEntry* e = find(key);
  throw InputError({source_, e ? e->line : 0, e ? e->column : 0, upper(key)}, message);
}

}  // namespace motostab::tyres
