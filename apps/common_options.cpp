#include "apps/common_options.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <vector>

#include "io/input_error.h"
#include "io/number.h"
#include "scenario/plausibility.h"
#include "scenario/scenario.h"

namespace motostab::cli {

using io::InputError;
using io::parseFiniteNumber;


void parseSpeedRange(const std::string& text, double& start, double& stop, double& step) {
  std::vector<std::optional<double>> v;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ':')) v.push_back(parseFiniteNumber(part));
  const bool ok = v.size() == 3 && v[0] && v[1] && v[2] && *v[0] >= 0 && *v[1] >= *v[0] && *v[2] > 0 &&
                  (*v[1] - *v[0]) / *v[2] <= scenario::SpeedRange::kMaxSteps;
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

namespace {
constexpr double kMaxRollDeg = 89;
bool isRollInRange(double deg) { return std::abs(deg) < kMaxRollDeg; }
}  // namespace

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
  std::vector<std::optional<double>> v;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ':')) v.push_back(parseFiniteNumber(part));
  const bool allFinite = !v.empty() && std::all_of(v.begin(), v.end(), [](const auto& x) { return x.has_value(); });
  std::vector<double> out;
  if (allFinite && v.size() == 1 && isRollInRange(*v[0])) out.push_back(*v[0] * M_PI / 180);
  if (allFinite && v.size() == 3 && isRollInRange(*v[0]) && isRollInRange(*v[1]) && *v[1] >= *v[0] && *v[2] > 0 &&
      (*v[1] - *v[0]) / *v[2] <= 1000) {
    const long n = static_cast<long>(std::floor((*v[1] - *v[0]) / *v[2] + 1e-9));
    for (long i = 0; i <= n; ++i) out.push_back((*v[0] + i * *v[2]) * M_PI / 180);
  }
  if (out.empty())
    throw InputError({"--roll-deg", 0, 0, text},
                     "expected PHI or A:B:STEP in degrees, each strictly between -89 and 89, with B >= A, STEP > 0 "
                     "and at most 1000 angles");
  return out;
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

void addStrictOption(CLI::App* command, bool& strict) {
  command->add_flag("--strict", strict,
                    "Plausibility warnings (likely unit slips or swapped quantities, docs/scenario-format.md) are errors");
}

void reportScenarioWarnings(const scenario::Scenario& s, bool strict, bool print) {
  for (const scenario::ScenarioWarning& w : s.warnings) {
    if (strict) throw InputError(w.where, w.message + " (a plausibility warning; --strict makes it an error)");
    if (print) std::cerr << "motostab: warning: " << scenario::formatWarning(w) << "\n";
  }
}

scenario::Scenario loadScenarioReporting(const std::string& file, const std::vector<std::string>& overrides, bool strict) {
  scenario::Scenario s = scenario::loadScenario(file, overrides);
  reportScenarioWarnings(s, strict);
  return s;
}

}  // namespace motostab::cli
