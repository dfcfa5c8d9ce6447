#pragma once
// The one parser of numbers in user input (YAML values, CSV cells, command-line fields): decimal or
// scientific notation, surrounding blanks allowed, the whole text consumed, finite only (no NaN, no
// infinity, no hexadecimal). Every reader of numbers goes through it. And the one formatter of
// numbers as text (printf's %g): every writer of numbers goes through formatNumber or formatShortest.
#include <optional>
#include <string>
#include <string_view>

namespace motostab::io {

/// The finite number `text` spells, or nothing (empty, trailing characters, nan, inf, 1e999, hex).
std::optional<double> parseFiniteNumber(std::string_view text);

/// `value` with `significantDigits` significant digits, as printf's %g (17 round-trips a double
/// exactly; 6 is what a default std::ostream writes).
std::string formatNumber(double value, int significantDigits = 17);

/// The shortest text of 15 to 17 significant digits that parseFiniteNumber reads back to exactly
/// `value` (17 digits for a value that is not finite).
std::string formatShortest(double value);

/// The magnitudes motostab computes with: every number of a YAML input is at most kMaxMagnitude in
/// magnitude, and a quantity that must be positive (a mass, a length, a stiffness) at least
/// kMinMagnitude. Beyond them (a mass of 1e300 kg, a radius of 1e-300 m) no parameter is physical and the
/// double-precision computation overflows (io/yaml_map.h applies them).
constexpr double kMaxMagnitude = 1e12, kMinMagnitude = 1e-12;

}  // namespace motostab::io
