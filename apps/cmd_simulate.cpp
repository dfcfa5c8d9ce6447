// motostab simulate SCENARIO --speed V --perturb SPEC... --duration T: nonlinear perturbation response
// from the trim, written to DIR/timeseries.csv with a plot, and modes identified from it (--identify).
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "apps/option_checks.h"
#include "io/input_error.h"
#include "io/output_folder.h"
#include "io/result_error.h"
#include "output/response_output.h"
#include "output/scenario_output.h"
#include "apps/simulate_identify.h"
#include "output/simulation_output.h"

namespace motostab::cli {

using io::InputError;
using io::OutputFolder;
using output::writeResponsePlot;
using output::writeTimeseries;
using scenario::Scenario;

namespace {

struct SimulateArgs {
  std::string scenario, out, speedControl = "pi", integrator = "auto";
  std::vector<std::string> perturb, overrides;
  double fallLimitDeg = 60, rollDeg = 0;
  bool identify = false, strict = false;
  simulation::SimulationOptions options;
};

// A text progress bar on stdout, drawn only when stdout is a terminal.
class ProgressBar {
 public:
  explicit ProgressBar(double duration) : duration_(duration), enabled_(isatty(STDOUT_FILENO)) {}
  void update(double t) {
    if (!enabled_) return;
    const int width = 40, filled = static_cast<int>(width * std::min(1.0, t / duration_));
    if (filled == last_) return;
    last_ = filled;
    std::printf("\r[%s%s] %5.1f%%", std::string(filled, '#').c_str(), std::string(width - filled, ' ').c_str(),
                100.0 * std::min(1.0, t / duration_));
    std::fflush(stdout);
  }
  void finish() {
    if (enabled_ && last_ >= 0) std::printf("\n");
  }

 private:
  double duration_;
  bool enabled_;
  int last_ = -1;
};

nlohmann::json describeSettings(const SimulateArgs& a) {
  const auto& o = a.options;
  return {{"scenario", a.scenario},       {"speed_mps", o.speed},
          {"duration_s", o.duration},     {"output_step_s", o.outputStep},
          {"perturbations", a.perturb},   {"speed_control", a.speedControl},
          {"integrator", simulation::getIntegratorName(o.integrator)}, {"accuracy", o.accuracy},
          {"fall_limit_deg", a.fallLimitDeg}, {"roll_deg", a.rollDeg}};
}

void runSimulate(SimulateArgs a) {
  a.options = makeSimulationOptions(a.options, a.perturb, a.speedControl, a.integrator, a.fallLimitDeg, a.rollDeg);
  auto& o = a.options;
  const Scenario scenario = loadScenarioReporting(a.scenario, a.overrides, a.strict);
  const std::filesystem::path target = getOutputFolder(a.out, scenario.name, "simulate");
  OutputFolder folder(target);
  const std::filesystem::path& out = folder.getPath();

  ProgressBar bar(o.duration);
  if (o.duration >= 5) o.progress = [&bar](double t) { bar.update(t); };
  const auto result = simulation::runSimulation(scenario, o);
  bar.finish();

  writeTimeseries(out, result);  // complete, also after a fall or a failure
  output::writeScenarioJson(out, scenario);
  std::cout << "Simulated " << result.endTime << " s of " << scenario.name << " at " << o.speed << " m/s in "
            << result.wallSeconds << " s wall (" << result.steps << " " << result.integrator << " steps, "
            << result.endTime / std::max(result.wallSeconds, 1e-9) << "x real time)\n";
  if (result.status != simulation::SimulationStatus::Completed) std::cout << result.message << "\n";
  std::cout << "Wrote " << (target / "timeseries.csv").string() << "\n";
  if (result.rows.size() >= 2) {
    writeResponsePlot(out, result, scenario.name + " at " + std::to_string(o.speed).substr(0, 5) + " m/s");
    std::cout << "Wrote " << (target / "response.{png,svg,gp}").string() << "\n";
  }
  if (a.identify) {
    const double t0 = simulation::getFreeResponseStart(o.perturbations);
    const std::vector<std::string> signals{"roll_rate", "steer_rate"};
    const auto modes = writeSimulatedModes(out, result, t0, describeSettings(a), signals);
    std::cout << output::formatModesTable(modes, signals) << "Wrote " << (target / "modes.json").string() << "\n";
  }
  folder.commit();  // also after a fall or a failure: the samples up to it are the run's outputs
  // A failure is reported after the data up to it has been written.
  if (result.status == simulation::SimulationStatus::Failed) throw io::ResultError(result.message);
}

}  // namespace

void registerSimulateCommands(CLI::App& app) {
  auto a = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand("simulate", "Nonlinear perturbation response from the trim at one speed");
  cmd->add_option("scenario", a->scenario, "Scenario YAML file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--speed", a->options.speed, "Trim and target forward speed, m/s")
      ->required()
      ->check(makeNumberCheck(kSpeedMps));
  cmd->add_option("--perturb", a->perturb,
                  "Perturbation (repeatable):\n" + simulation::getPerturbationSyntax());
  cmd->add_option("--duration", a->options.duration, "Simulated time, s")->required()->check(makeNumberCheck(0, 1e6, true));
  addOutOption(*cmd, a->out, "the scenario's name");
  cmd->add_option("--speed-control", a->speedControl, "none (coast) or pi (drive-torque PI controller)")
      ->capture_default_str();
  cmd->add_option("--integrator", a->integrator, "auto (ROS34PW2 without constraints, else RungeKuttaMerson), ROS34PW2, RungeKuttaMerson, RungeKutta3, CPodes or Verlet")
      ->capture_default_str();
  cmd->add_option("--accuracy", a->options.accuracy, "Integrator relative accuracy")
      ->capture_default_str()
      ->check(makeNumberCheck(0, 1, true));
  cmd->add_option("--output-step", a->options.outputStep, "Sampling interval of the outputs, s")
      ->capture_default_str()
      ->check(makeNumberCheck(0, 1e6, true));
  cmd->add_option("--fall-limit", a->fallLimitDeg, "Roll angle that ends the run as a fall, deg")
      ->capture_default_str()
      ->check(makeNumberCheck(0, 180, true));
  cmd->add_option("--roll-deg", a->rollDeg,
                  "Start from the steady turn at this roll angle (deg, > 0 right; --speed is then the rear contact "
                  "point's speed along its path)")
      ->check(makeRollCheck());
  cmd->add_flag("--identify", a->identify, "Identify modes from roll and steer rate after the last pulse: modes.json");
  cmd->add_option("--set", a->overrides, "Override a scenario value, e.g. --set geometry.trail_m=0.1");
  addStrictOption(cmd, a->strict);
  cmd->callback([a]() { runSimulate(*a); });
}

}  // namespace motostab::cli
