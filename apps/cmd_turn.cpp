// motostab trim: scenario -> model -> steady turn (or straight running) -> trim.json and a table.
#include <cmath>
#include <iostream>

#include "apps/commands.h"
#include "analysis/sweep.h"
#include "apps/common_options.h"
#include "apps/option_checks.h"
#include "io/input_error.h"
#include "io/output_folder.h"
#include "output/scenario_output.h"
#include "output/turn_output.h"

namespace motostab::cli {

using analysis::HandsFreeTurn;
using analysis::TrimOptions;
using analysis::TrimResult;
using analysis::chooseHandsFreeTurn;
using analysis::calcTrim;
using io::InputError;
using io::OutputFolder;
using output::formatHandsFreeTable;
using output::formatTrimTable;
using output::writeHandsFreeJson;
using output::writeTrimJson;
using scenario::Scenario;
using vehicle::VehicleModel;


void registerTurnCommands(CLI::App& app) {
  struct TrimArgs {
    std::string scenario, out, speeds;
    double speed = NAN, rollDeg = 0;
    bool handsFree = false, strict = false;
    std::vector<std::string> overrides;
  };
  auto a = std::make_shared<TrimArgs>();
  CLI::App* trim = app.add_subcommand("trim", "Steady turn at a speed and roll angle: steer, pitch, steer torque, tyre forces");
  trim->add_option("scenario", a->scenario, "Scenario YAML file")->required()->check(CLI::ExistingFile);
  trim->add_option("--speed", a->speed,
                   "Speed of the rear contact point along its path, m/s (with --hands-free: the default turn is the one "
                   "nearest this speed)")
      ->check(makeNumberCheck(kTurnSpeedMps));
  trim->add_option("--roll-deg", a->rollDeg, "Roll angle, deg (> 0 leans right), strictly between -89 and 89")
      ->check(makeRollCheck());
  trim->add_flag("--hands-free", a->handsFree,
                 "Zero steer torque: every such turn on --speeds (default: the scenario's speeds_mps), the one continuing "
                 "from straight running marked");
  trim->add_option("--speeds", a->speeds, "START:STOP:STEP in m/s, the hands-free search range")->check(makeSpeedRangeCheck());
  addOutOption(*trim, a->out, "the scenario's name");
  trim->add_option("--set", a->overrides, "Override a scenario value, e.g. --set geometry.trail_m=0.1");
  addStrictOption(trim, a->strict);
  trim->callback([a]() {
    if (!a->handsFree && std::isnan(a->speed))
      throw InputError({"command line", 0, 0, "--speed"}, "required unless --hands-free: give the turn's speed in m/s");
    const Scenario scenario = loadScenarioReporting(a->scenario, a->overrides, a->strict);
    const std::string out = getOutputFolder(a->out, scenario.name, "trim");
    OutputFolder folder(out);
    const VehicleModel model(scenario);
    TrimOptions opt;
    opt.roll = a->rollDeg * M_PI / 180;
    if (a->handsFree) {
      double start = scenario.speeds.start, stop = scenario.speeds.stop, step = scenario.speeds.step;
      if (!a->speeds.empty()) parseSpeedRange(a->speeds, start, stop, step);
      const std::vector<HandsFreeTurn> turns = calcHandsFreeTurns(model, start, stop, step, opt, {"command line", 0, 0, "--roll-deg"},
                                                                  {"command line", 0, 0, "--speeds"});
      const size_t chosen = chooseHandsFreeTurn(turns, a->speed);
      writeHandsFreeJson(folder.getPath(), model, turns, chosen);
      output::writeScenarioJson(folder.getPath(), scenario);
      folder.commit();
      std::cout << "Scenario " << scenario.name << ": hands-free steady turns at roll " << a->rollDeg << " deg\n"
                << formatHandsFreeTable(model, turns, chosen) << "The default turn:\n"
                << formatTrimTable(model, analysis::restoreTrim(model, turns[chosen].trim)) << "Wrote " << out
                << "/{trim.json, scenario.json}\n";
      return;
    }
    const TrimResult trim = calcTrim(model, a->speed, opt);
    writeTrimJson(folder.getPath(), model, trim);
    output::writeScenarioJson(folder.getPath(), scenario);
    folder.commit();
    std::cout << "Scenario " << scenario.name << ": steady turn at roll " << a->rollDeg << " deg\n"
              << formatTrimTable(model, trim) << "Wrote " << out << "/{trim.json, scenario.json}\n";
  });
}

}  // namespace motostab::cli
