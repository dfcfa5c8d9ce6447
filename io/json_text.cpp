#include "io/json_text.h"

#include <cmath>
#include <optional>
#include <utility>

#include "io/result_error.h"

namespace motostab::io {
namespace {

// The key path and value of the first non-finite number under `value` (`path` is value's own).
std::optional<std::pair<std::string, double>> findNonFinite(const nlohmann::json& value, const std::string& path) {
  if (value.is_number_float()) {
    const double v = value.get<double>();
    if (std::isfinite(v)) return std::nullopt;
    return std::make_pair(path.empty() ? std::string("(top level)") : path, v);
  }
  if (value.is_array())
    for (size_t i = 0; i < value.size(); ++i)
      if (auto bad = findNonFinite(value[i], path + "[" + std::to_string(i) + "]")) return bad;
  if (value.is_object())
    for (const auto& [key, child] : value.items())
      if (auto bad = findNonFinite(child, path.empty() ? key : path + "." + key)) return bad;
  return std::nullopt;
}

}  // namespace

std::string formatJson(const nlohmann::json& value, const std::string& file) {
  if (const auto bad = findNonFinite(value, ""))
    throw ResultError("the computation gave " + std::string(std::isnan(bad->second) ? "NaN" : "an infinite value") +
                      " for " + bad->first + " in " + file + "; nothing was written");
  return value.dump(2) + "\n";
}

}  // namespace motostab::io
