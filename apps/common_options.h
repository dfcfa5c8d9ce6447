#pragma once
// Options and checks shared by the motostab subcommands. Every number on the command line passes
// through parseFiniteNumber (io/number.h) in a CLI11 validator, so NaN, infinities and values out
// of range are CLI11 validation errors: exit code 2, like every other input error.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "scenario/scenario.h"

namespace motostab::cli {

struct NumberRange;  // apps/option_checks.h

/// Upper bounds of the count options (docs/commands.md, "Limits"): speeds of a sweep (also the
/// scenario's speeds_mps, scenario::SpeedRange::kMaxSpeeds; with roll angles, kMaxMapPoints), roll angles of a map, slip angles of `tyre`,
/// samples of `uncertainty`.
constexpr long kMaxRollAngles = 1000;
constexpr long kMaxSlipPoints = 100000;
constexpr long kMaxSamples = 100000;

/// The numbers of a range option "A:B:STEP" (or "A" alone when `allowSingle`): every field present and
/// a finite number, else an InputError naming `option` and saying what is `expected` ("5:" lacks a bound).
std::vector<double> parseRangeFields(const std::string& text, const std::string& option, bool allowSingle,
                                     const std::string& expected);

/// The output folder of a command, the one convention of every command (docs/commands.md): `out` when
/// given, else "NAME-COMMAND" in the working folder (NAME the scenario's name, or the input file's stem;
/// just COMMAND when `name` is empty). InputError (key --out) if that is not a plain folder name.
std::string getOutputFolder(const std::string& out, const std::string& name, const std::string& command);

/// Adds the --out option of that convention to `command`; `name` says what NAME is in the help text.
CLI::Option* addOutOption(CLI::App& command, std::string& out, const std::string& name);

/// Parses "START:STOP:STEP" (m/s; 0 <= START <= STOP <= 150, STEP > 0, finite, at most scenario::SpeedRange::kMaxSpeeds speeds);
/// throws InputError naming the option on bad input.
void parseSpeedRange(const std::string& text, double& start, double& stop, double& step);

/// A CLI11 check: a finite number in [low, high] (low itself excluded when `excludeLow`).
CLI::Validator makeNumberCheck(double low, double high, bool excludeLow = false);
/// The same for a range the Python module checks too (apps/option_checks.h).
CLI::Validator makeNumberCheck(const NumberRange& range);
/// A CLI11 check of "START:STOP:STEP" by parseSpeedRange.
CLI::Validator makeSpeedRangeCheck();
/// A CLI11 check of a roll angle in degrees: finite and strictly between -89 and 89.
CLI::Validator makeRollCheck();
/// Parses a roll angle "PHI" or a range "A:B:STEP" (deg; each strictly between -89 and 89, STEP > 0,
/// B >= A, at most 1000 angles) into radians; throws InputError naming --roll-deg on bad input.
std::vector<double> parseRollAngles(const std::string& text);
/// A CLI11 check of parseRollAngles.
CLI::Validator makeRollAnglesCheck();

/// The worker-thread option range, 1..256.
CLI::Validator makeThreadsCheck();

/// Adds `--strict` (plausibility warnings are errors, exit 2) to a command that reads a scenario.
void addStrictOption(CLI::App* command, bool& strict);
/// Completes the load of `scenario`: its plugin sections are read once (PluginRegistry::
/// readScenarioSections: the files they name are kept, their warnings added), then each warning is
/// printed to stderr as "motostab: warning: FILE:LINE:COL: KEY: ..." (when `print`), or with `strict`
/// the first plausibility warning (scenario/plausibility.h) is an InputError.
void reportScenarioWarnings(scenario::Scenario& scenario, bool strict, bool print = true);
/// loadScenario(file, overrides), then reportScenarioWarnings.
scenario::Scenario loadScenarioReporting(const std::string& file, const std::vector<std::string>& overrides, bool strict);

}  // namespace motostab::cli
