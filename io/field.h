#pragma once
// Declared fields of a scenario section, in the spirit of Drake's Serialize(Archive*): each key is
// declared once, with its unit, its range, whether it is a measured property of the vehicle (and what
// it measures) and its meaning. The section's reader reads through the declaration, the parameter list
// that diagnosis varies takes the measured fields with their quantity, and the
// scenario-format tables of docs/scenario-format.md are printed from it (a test compares them).
#include <array>
#include <string>
#include <vector>

#include "io/yaml_map.h"

namespace motostab::io {

/// What a measured field measures: sets the default standard deviation diagnosis assumes for a
/// parameter the scenario gives no uncertainty for (10 mm for lengths, 1 degree for angles, 10 %
/// otherwise) and the scale of inertia entries.
enum class Quantity { Length, Mass, Inertia, Angle, Other };

/// The values a number admits (checked by the reader, printed in the docs tables).
enum class Range {
  Any,
  Positive,     ///< > 0
  NonNegative,  ///< >= 0
  Fraction,     ///< 0 < x < 1
  Custom        ///< checked by the section's reader; Field::rangeNote gives it
};

/// How a field is written.
enum class Shape {
  Number,
  Vector3,  ///< [x, y, z]
  Inertia,  ///< {xx, yy, zz, xy, xz, yz}
  Other     ///< a mapping, list or string that the section's reader reads itself
};

/// One key of a section.
struct Field {
  std::string key;
  std::string unit;      ///< "m", "kg m^2", "N m s/rad"; empty for dimensionless values and non-numbers
  Shape shape = Shape::Number;
  Range range = Range::Any;
  std::string rangeNote;  ///< the range in words when the reader checks it itself (Range::Custom)
  bool required = true;
  double fallback = 0;    ///< the default of an optional number
  bool hasFallback = false;
  bool measured = false;  ///< a measured property of the vehicle: listed for diagnosis and the Python module
  Quantity quantity = Quantity::Other;
  bool keepsSign = false;  ///< a fit keeps a positive value above a tenth of it (Range::Positive, or set)
  bool inPlane = false;    ///< an [x, y, z] point whose y must be 0: its y is no parameter
  std::string meaning;

  /// A number: key, unit, range, meaning.
  static Field number(std::string key, std::string unit, Range range, std::string meaning);
  /// A field of another shape (Range::Custom with `rangeNote`, or none).
  static Field of(Shape shape, std::string key, std::string unit, std::string rangeNote, std::string meaning);
  /// The same field, optional with this default.
  Field withDefault(double value) const;
  /// The same field, optional without a default (absent: the element is off, or the reader derives it).
  Field optional() const;
  /// The same field with a range its section's reader checks itself, given in words ("-90 < x < 90").
  Field within(std::string note) const;
  /// The same field, a measured property of the vehicle of this quantity.
  Field measures(Quantity q) const;
  /// The same field, whose fitted value keeps the sign of a positive given value (a trail, a radius).
  Field keepingSign() const;
  /// The same [x, y, z] field, a point in the plane of symmetry (y = 0, checked by the reader).
  Field inPlaneOfSymmetry() const;
};

/// The declared fields of one section, `path` as --set addresses it ("rider_lean", "swingarm.suspension").
/// A plugin of a selectable kind declares its keys for when the selector names it: `contact` when
/// `contact.model` is `relaxation_linear` (whenPath "contact.model", whenValue "relaxation_linear").
struct SectionFields {
  std::string path;
  std::vector<Field> fields;
  std::string whenPath = {};   ///< the key path of the selector; empty: the section's keys always apply
  std::string whenValue = {};  ///< the selector's value for which they apply
  /// Whether these keys apply to a scenario tree: no selector, or the selector has the value.
  bool isSelectedIn(const YAML::Node& tree) const;
  /// The same section, applying when the key at `selectorPath` is `value` (`contact.model`, `magic_formula`).
  SectionFields selectedBy(std::string selectorPath, std::string value) const;
  /// Whether `other` declares keys of the same section: the same path and selector.
  bool isSameSectionAs(const SectionFields& other) const;
  /// The field of `key`; std::logic_error if none is declared (a reader asking for an undeclared key is a bug).
  const Field& get(const std::string& key) const;
  /// The key path of one of its keys, as --set takes it ("swingarm.suspension.damping_Ns_per_m"; at the top level the key).
  std::string getKeyPath(const std::string& key) const;
};

/// Reads a number field from `m`: its range checked (InputError at the key), the default when an
/// optional field is absent (an optional field without a default must be asked with has() first).
double readNumber(YamlMap& m, const Field& field);

/// Reads an [x, y, z] field.
std::array<double, 3> readVector3(YamlMap& m, const Field& field);

/// The range as the docs tables print it: "> 0", ">= 0", "0 < x < 1", "any" (a non-number: "-"), or the note.
std::string formatRange(const Field& field);

/// For an "unknown key" error at `keyPath` ("geometry.trial_m"): what the sections of its parent path
/// declare, " (did you mean `trail_m`?)" for a declared key within a few typing errors, else
/// " (`geometry` declares: wheelbase_m, trail_m, ...)"; "" when no section of that path always applies
/// (none declared, a top-level key, or only sections with a selector such as the contact models').
std::string describeDeclaredKeys(const std::vector<SectionFields>& sections, const std::string& keyPath);

/// The heading of a section's table: "Section `PATH`" ("Top level" for the path ""), with its
/// selector: "Section `contact` (`contact.model`: `relaxation_linear`)".
std::string formatSectionHeading(const SectionFields& section);

/// The section's markdown table: | key | unit | range | default | meaning |, one row per field.
std::string formatFieldTable(const SectionFields& section);

}  // namespace motostab::io
