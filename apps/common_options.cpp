#include "apps/common_options.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "io/input_error.h"
#include "io/number.h"

namespace motostab::cli {

void parseSpeedRange(const std::string& text, double& start, double& stop, double& step) {
  std::vector<std::optional<double>> v;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ':')) v.push_back(parseFiniteNumber(part));
  const bool ok = v.size() == 3 && v[0] && v[1] && v[2] && *v[0] >= 0 && *v[1] >= *v[0] && *v[2] > 0 &&
                  (*v[1] - *v[0]) / *v[2] <= 1e6;
  if (!ok)
    throw InputError({"--speeds", 0, 0, text},
                     "expected START:STOP:STEP, finite, with 0 <= START <= STOP, STEP > 0 and at most 1e6 speeds");
  start = *v[0], stop = *v[1], step = *v[2];
}

CLI::Validator makeNumberCheck(double low, double high, bool excludeLow) {
  std::ostringstream range;
  range << (excludeLow ? "(" : "[") << low << ", " << high << "]";
  const std::string desc = "finite number in " + range.str();
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const auto v = parseFiniteNumber(text);
        if (!v || *v < low || *v > high || (excludeLow && *v == low)) return "'" + text + "' is not a " + desc;
        return "";
      },
      desc);
}

CLI::Validator makeSpeedRangeCheck() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double a, b, c;
        try {
          parseSpeedRange(text, a, b, c);
        } catch (const InputError& e) {
          return e.getReason() + " (got '" + text + "')";
        }
        return "";
      },
      "START:STOP:STEP");
}

CLI::Validator makeThreadsCheck() { return CLI::Range(1, 256); }

}  // namespace motostab::cli
