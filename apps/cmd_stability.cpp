// motostab sweep | linearize: scenario -> model -> trim -> linearise -> modes -> outputs.
#include <iostream>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "output/sweep_output.h"

namespace motostab::cli {

void registerStabilityCommands(CLI::App& app) {
  struct SweepArgs {
    std::string scenario, speeds, out;
    std::vector<std::string> overrides;
  };
  auto sweepArgs = std::make_shared<SweepArgs>();
  CLI::App* sweep = app.add_subcommand("sweep", "Linear stability sweep over speed: eigenvalues, modes, critical speeds, plots");
  sweep->add_option("scenario", sweepArgs->scenario, "Scenario YAML file")->required()->check(CLI::ExistingFile);
  sweep->add_option("--speeds", sweepArgs->speeds, "START:STOP:STEP in m/s (default: the scenario's speeds_mps)");
  sweep->add_option("--out", sweepArgs->out, "Output folder (default: named after the scenario)");
  sweep->add_option("--set", sweepArgs->overrides, "Override a scenario value, e.g. --set geometry.trail_m=0.1");
  sweep->callback([sweepArgs]() {
    const Scenario scenario = loadScenario(sweepArgs->scenario, sweepArgs->overrides);
    const VehicleModel model(scenario);
    SweepOptions opt;
    opt.start = scenario.speeds.start;
    opt.stop = scenario.speeds.stop;
    opt.step = scenario.speeds.step;
    if (!sweepArgs->speeds.empty()) parseSpeedRange(sweepArgs->speeds, opt.start, opt.stop, opt.step);
    const SweepResult result = runSweep(model, opt);
    const std::string out = sweepArgs->out.empty() ? scenario.name : sweepArgs->out;
    writeSweepOutputs(out, scenario.name, result);
    std::cout << "Scenario " << scenario.name << ": " << result.speeds.size() << " speeds\n"
              << formatSweepTable(result) << "Wrote " << out << "/{eigenvalues.csv, summary.json, root_locus.{png,svg,gp}, "
              << "real_part_vs_speed.{png,svg,gp}}\n";
  });

  struct LinArgs {
    std::string scenario, out;
    double speed = 0;
    std::vector<std::string> overrides;
  };
  auto linArgs = std::make_shared<LinArgs>();
  CLI::App* lin = app.add_subcommand("linearize", "Trim at one speed and write A, B and the eigenvectors");
  lin->add_option("scenario", linArgs->scenario, "Scenario YAML file")->required()->check(CLI::ExistingFile);
  lin->add_option("--speed", linArgs->speed, "Forward speed, m/s")->required();
  lin->add_option("--out", linArgs->out, "Output folder")->required();
  lin->add_option("--set", linArgs->overrides, "Override a scenario value");
  lin->callback([linArgs]() {
    const Scenario scenario = loadScenario(linArgs->scenario, linArgs->overrides);
    const VehicleModel model(scenario);
    const TrimResult trim = calcTrim(model, linArgs->speed);
    const LinearModel lm = linearize(model, trim);
    writeLinearModel(linArgs->out, lm);
    std::cout << "Trim at " << linArgs->speed << " m/s: residual " << trim.residualNorm << " after " << trim.iterations
              << " iterations; " << lm.states.size() << " states. Wrote " << linArgs->out
              << "/{A.csv, B.csv, eigenvalues.csv, eigenvectors.csv, linear_model.json}\n";
  });
}

}  // namespace motostab::cli
