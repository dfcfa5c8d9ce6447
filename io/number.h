#pragma once
// The one parser of numbers in user input (YAML values, CSV cells, command-line fields): decimal or
// scientific notation, surrounding blanks allowed, the whole text consumed, finite only (no NaN, no
// infinity, no hexadecimal). Every reader of numbers goes through it.
#include <optional>
#include <string_view>

namespace motostab::io {

/// The finite number `text` spells, or nothing (empty, trailing characters, nan, inf, 1e999, hex).
std::optional<double> parseFiniteNumber(std::string_view text);

}  // namespace motostab::io
