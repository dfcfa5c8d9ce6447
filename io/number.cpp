#include "io/number.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace motostab::io {

std::optional<double> parseFiniteNumber(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return std::nullopt;
  const auto last = text.find_last_not_of(" \t\r\n");
  const std::string t(text.substr(first, last - first + 1));
  // Digits, sign, point and exponent only: strtod would also take "nan", "inf" and "0x1p3".
  if (t.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (end != t.c_str() + t.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string formatNumber(double value, int significantDigits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significantDigits, value);
  return buf;
}

std::string formatShortest(double value) {
  char buf[40];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
    const auto back = parseFiniteNumber(buf);
    if (back && *back == value) break;
  }
  return buf;
}

}  // namespace motostab::io
