#include "apps/common_options.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "apps/option_checks.h"
#include "io/input_error.h"
#include "io/number.h"

namespace motostab::cli {

using io::InputError;
using io::InputLocation;
using io::parseFiniteNumber;


void parseSpeedRange(const std::string& text, double& start, double& stop, double& step) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ':')) v.push_back(parseFiniteNumber(part).value_or(NAN));
  const InputLocation where{"--speeds", 0, 0, text};
  if (v.size() != 3) checkSpeedRange(NAN, NAN, NAN, where);
  checkSpeedRange(v[0], v[1], v[2], where);
  start = v[0], stop = v[1], step = v[2];
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

CLI::Validator makeNumberCheck(const NumberRange& range) { return makeNumberCheck(range.low, range.high, range.excludeLow); }

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

CLI::Validator makeRollCheck() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto v = parseFiniteNumber(text);
        if (!v || !isRollInRange(*v))
          return "'" + text + "' is not a roll angle strictly between -89 and 89 deg: give a smaller --roll-deg";
        return "";
      },
      "deg in (-89, 89)");
}

std::vector<double> parseRollAngles(const std::string& text) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ':')) v.push_back(parseFiniteNumber(part).value_or(NAN));
  const InputLocation where{"--roll-deg", 0, 0, text};
  if (v.size() == 1 && isRollInRange(v[0])) return {v[0] * M_PI / 180};
  if (v.size() == 3) return makeRollAngles(v[0], v[1], v[2], where);
  return makeRollAngles(NAN, NAN, NAN, where);
}

CLI::Validator makeRollAnglesCheck() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          parseRollAngles(text);
        } catch (const InputError& e) {
          return e.getReason() + " (got '" + text + "')";
        }
        return "";
      },
      "PHI or A:B:STEP (deg)");
}

CLI::Validator makeThreadsCheck() { return CLI::Range(1, 256); }

}  // namespace motostab::cli
