#include "io/field.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "io/number.h"

namespace motostab::io {

Field Field::number(std::string key, std::string unit, Range range, std::string meaning) {
  Field f;
  f.key = std::move(key);
  f.unit = std::move(unit);
  f.range = range;
  f.keepsSign = range == Range::Positive || range == Range::Fraction;
  f.meaning = std::move(meaning);
  return f;
}

Field Field::of(Shape shape, std::string key, std::string unit, std::string rangeNote, std::string meaning) {
  Field f = number(std::move(key), std::move(unit), rangeNote.empty() ? Range::Any : Range::Custom, std::move(meaning));
  f.shape = shape;
  f.rangeNote = std::move(rangeNote);
  return f;
}

Field Field::withDefault(double value) const {
  Field f = *this;
  f.required = false;
  f.fallback = value;
  f.hasFallback = true;
  return f;
}

Field Field::optional() const {
  Field f = *this;
  f.required = false;
  return f;
}

Field Field::keepingSign() const {
  Field f = *this;
  f.keepsSign = true;
  return f;
}

Field Field::inPlaneOfSymmetry() const {
  Field f = *this;
  f.inPlane = true;
  f.range = Range::Custom;
  f.rangeNote = "y = 0";
  return f;
}

Field Field::within(std::string note) const {
  Field f = *this;
  f.range = Range::Custom;
  f.rangeNote = std::move(note);
  return f;
}

Field Field::measures(Quantity q) const {
  Field f = *this;
  f.measured = true;
  f.quantity = q;
  return f;
}

const Field& SectionFields::get(const std::string& key) const {
  for (const Field& f : fields)
    if (f.key == key) return f;
  throw std::logic_error("section " + path + " declares no field " + key);
}

namespace {

// Levenshtein distance of two keys (insertions, deletions, substitutions).
size_t calcEditDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string describeDeclaredKeys(const std::vector<SectionFields>& sections, const std::string& keyPath) {
  const size_t dot = keyPath.rfind('.');
  const std::string parent = dot == std::string::npos ? "" : keyPath.substr(0, dot);
  const std::string key = dot == std::string::npos ? keyPath : keyPath.substr(dot + 1);
  // Only sections that always apply: a selected one's keys may belong to another model than the file's,
  // and the top level's to another file than a scenario (a measured-data file, a fragment).
  std::vector<std::string> declared;
  for (const SectionFields& s : sections)
    if (!parent.empty() && s.path == parent && s.whenPath.empty())
      for (const Field& f : s.fields)
        if (std::find(declared.begin(), declared.end(), f.key) == declared.end()) declared.push_back(f.key);
  if (declared.empty()) return "";
  std::string closest;
  size_t best = std::max<size_t>(2, key.size() / 4) + 1;
  for (const std::string& d : declared)
    if (const size_t e = calcEditDistance(key, d); e < best) best = e, closest = d;
  if (!closest.empty()) return " (did you mean `" + closest + "`?)";
  std::string list;
  for (const std::string& d : declared) list += (list.empty() ? "" : ", ") + d;
  return " (`" + parent + "` declares: " + list + ")";
}

std::string SectionFields::getKeyPath(const std::string& key) const { return path.empty() ? key : path + "." + key; }

double readNumber(YamlMap& m, const Field& f) {
  if (f.shape != Shape::Number) throw std::logic_error(f.key + " is not a number field");
  if (!f.required && !m.has(f.key)) {
    if (!f.hasFallback) throw std::logic_error(f.key + " is optional without a default: ask has() first");
    return f.fallback;
  }
  switch (f.range) {
    case Range::Positive: return m.getPositive(f.key);
    case Range::NonNegative: return m.getNonNegative(f.key);
    case Range::Fraction: {
      const double v = m.getPositive(f.key);
      if (!(v < 1)) m.fail(f.key, "must lie strictly between 0 and 1");
      return v;
    }
    case Range::Any:
    case Range::Custom: return m.getDouble(f.key);
  }
  return 0;
}

std::array<double, 3> readVector3(YamlMap& m, const Field& f) {
  if (f.shape != Shape::Vector3) throw std::logic_error(f.key + " is not an [x, y, z] field");
  return m.getVec3(f.key);
}

std::string formatRange(const Field& f) {
  switch (f.range) {
    case Range::Any: return f.shape == Shape::Other ? "-" : "any";
    case Range::Positive: return "> 0";
    case Range::NonNegative: return ">= 0";
    case Range::Fraction: return "0 < x < 1";
    case Range::Custom: return f.rangeNote;
  }
  return "";
}

bool SectionFields::isSelectedIn(const YAML::Node& tree) const {
  if (whenPath.empty()) return true;
  const YAML::Node selector = findKeyPath(tree, whenPath);
  return selector && selector.IsScalar() && selector.Scalar() == whenValue;
}

SectionFields SectionFields::selectedBy(std::string selectorPath, std::string value) const {
  SectionFields s = *this;
  s.whenPath = std::move(selectorPath);
  s.whenValue = std::move(value);
  return s;
}

bool SectionFields::isSameSectionAs(const SectionFields& other) const {
  return path == other.path && whenPath == other.whenPath && whenValue == other.whenValue;
}

std::string formatSectionHeading(const SectionFields& s) {
  const std::string head = s.path.empty() ? "Top level" : "Section `" + s.path + "`";
  return s.whenPath.empty() ? head : head + " (`" + s.whenPath + "`: `" + s.whenValue + "`)";
}

std::string formatFieldTable(const SectionFields& section) {
  std::string out = "| key | unit | range | default | meaning |\n|---|---|---|---|---|\n";
  for (const Field& f : section.fields) {
    const std::string shape = f.shape == Shape::Vector3 ? " [x, y, z]" : f.shape == Shape::Inertia ? " {xx, yy, zz, xy, xz, yz}" : "";
    const std::string fallback = f.required ? "required" : f.hasFallback ? formatShortest(f.fallback) : "none";
    out += "| `" + f.key + "`" + shape + " | " + (f.unit.empty() ? "-" : f.unit) + " | " + formatRange(f) + " | " + fallback +
           " | " + f.meaning + " |\n";
  }
  return out;
}

}  // namespace motostab::io
