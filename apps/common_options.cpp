#include "apps/common_options.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <vector>

#include "apps/option_checks.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "io/number.h"
#include "io/output_folder.h"
#include "plugins/builtin.h"
#include "scenario/plausibility.h"
#include "scenario/scenario.h"

namespace motostab::cli {

using io::InputError;
using io::InputLocation;
using io::parseFiniteNumber;


std::vector<double> parseRangeFields(const std::string& text, const std::string& option, bool allowSingle,
                                     const std::string& expected) {
  const std::vector<std::string> fields = io::splitFields(text, ':');
  std::vector<double> out;
  for (const std::string& f : fields) {
    const auto v = parseFiniteNumber(f);
    if (!v) break;
    out.push_back(*v);
  }
  const bool complete = out.size() == fields.size() && (out.size() == 3 || (allowSingle && out.size() == 1));
  if (!complete) {
    const bool blank = std::any_of(fields.begin(), fields.end(), [](const std::string& f) {
      return f.find_first_not_of(" \t") == std::string::npos;
    });
    throw InputError({option, 0, 0, text}, std::string(blank ? "a bound or step is missing: " : "") + "expected " + expected);
  }
  return out;
}

void parseSpeedRange(const std::string& text, double& start, double& stop, double& step) {
  const std::string expected = "START:STOP:STEP, finite, with 0 <= START <= STOP, STEP > 0, STOP <= 150 m/s and at most " + std::to_string(scenario::SpeedRange::kMaxSpeeds) + " speeds";
  const std::vector<double> v = parseRangeFields(text, "--speeds", false, expected);
  checkSpeedRange(v[0], v[1], v[2], {"--speeds", 0, 0, text});
  start = v[0], stop = v[1], step = v[2];
}

std::string getOutputFolder(const std::string& out, const std::string& name, const std::string& command) {
  if (!out.empty()) return out;
  const std::string folder = name.empty() ? command : name + "-" + command;
  if (const std::string why = io::describeBadFolderName(folder); !why.empty())
    throw InputError({"command line", 0, 0, "--out"}, "the default output folder '" + folder + "' " + why + ": give --out");
  return folder;
}

CLI::Option* addOutOption(CLI::App& command, std::string& out, const std::string& name) {
  return command.add_option("--out", out, "Output folder (default: " + name + "-" + command.get_name() +
                                              " in the working folder; replaced whole only if motostab wrote it)");
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
  const std::string expected =
      "PHI or A:B:STEP in degrees, each strictly between -89 and 89, with B >= A, STEP > 0 and at most 1000 angles";
  const std::vector<double> v = parseRangeFields(text, "--roll-deg", true, expected);
  const InputLocation where{"--roll-deg", 0, 0, text};
  if (v.size() == 1 && isRollInRange(v[0])) return {v[0] * M_PI / 180};
  if (v.size() == 3) return makeRollAngles(v[0], v[1], v[2], where);
  throw InputError(where, "expected " + expected);
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

void reportScenarioWarnings(scenario::Scenario& s, bool strict, bool print) {
  plugins::makeBuiltinRegistry().readScenarioSections(s);
  for (const scenario::ScenarioWarning& w : s.warnings) {
    if (strict && w.check != scenario::ScenarioWarning::Check::PluginInput) throw InputError(w.where, w.message + " (a plausibility warning; --strict makes it an error)");
    if (print) std::cerr << "motostab: warning: " << scenario::formatWarning(w) << "\n";
  }
}

scenario::Scenario loadScenarioReporting(const std::string& file, const std::vector<std::string>& overrides, bool strict) {
  scenario::Scenario s = scenario::loadScenario(file, overrides);
  reportScenarioWarnings(s, strict);
  return s;
}

}  // namespace motostab::cli
