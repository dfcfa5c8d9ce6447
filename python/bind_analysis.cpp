// trim, linearize, sweep, turn_map and simulate: the calls of `motostab trim`, `linearize`, `sweep`
// (with --roll-deg A:B:STEP for a map) and `simulate`, without their files.
#include <array>
#include <cmath>
#include <optional>

#include "apps/option_checks.h"
#include "output/turn_output.h"
#include "python/bind_scenario.h"
#include "simulation/simulation.h"

namespace motostab::python {

using analysis::SweepOptions;
using analysis::TrimOptions;
using analysis::TrimResult;
using vehicle::VehicleModel;

namespace {

using SpeedTuple = std::optional<std::array<double, 3>>;

// The sweep options of `motostab sweep`: the scenario's speeds unless `speeds` is given, `threads`.
SweepOptions makeSweepOptions(const ScenarioHandle& s, const SpeedTuple& speeds, int threads) {
  SweepOptions opt;
  const auto& d = s.scenario->speeds;
  const std::array<double, 3> grid = speeds ? *speeds : std::array<double, 3>{d.start, d.stop, d.step};
  if (speeds) cli::checkSpeedRange(grid[0], grid[1], grid[2], argumentLocation("speeds"));
  opt.start = grid[0], opt.stop = grid[1], opt.step = grid[2];
  cli::checkThreads(threads, argumentLocation("threads"));
  opt.threads = threads;
  opt.linearize.computeB = true;  // as `motostab sweep` (for linear_models.mat): the same A to the last bit
  return opt;
}

// Where a turn's speeds come from, for its error.
io::InputLocation speedsLocation(const SpeedTuple& speeds) {
  return argumentLocation(speeds ? "speeds" : "speeds_mps (the scenario's; pass speeds=)");
}

py::dict trim(const ScenarioHandle& s, std::optional<double> speed, double rollDeg, bool handsFree, const SpeedTuple& speeds) {
  if (!handsFree && !speed) throw io::InputError(argumentLocation("speed"), "required unless hands_free: give the turn's speed in m/s");
  if (speed) cli::checkNumber(*speed, cli::kTurnSpeedMps, argumentLocation("speed"));
  cli::checkRoll(rollDeg, argumentLocation("roll_deg"));
  const auto& d = s.scenario->speeds;
  const std::array<double, 3> grid = speeds ? *speeds : std::array<double, 3>{d.start, d.stop, d.step};
  if (speeds) cli::checkSpeedRange(grid[0], grid[1], grid[2], argumentLocation("speeds"));
  nlohmann::json figures = callQuietly([&] {
    const VehicleModel model(*s.scenario);
    TrimOptions opt;
    opt.roll = rollDeg * M_PI / 180;
    if (!handsFree) return output::makeTrimJson(model, analysis::calcTrim(model, *speed, opt));
    const auto turns = cli::calcHandsFreeTurns(model, grid[0], grid[1], grid[2], opt, argumentLocation("roll_deg"),
                                               argumentLocation("speeds"));
    return output::makeHandsFreeJson(model, turns, analysis::chooseHandsFreeTurn(turns, speed.value_or(NAN)));
  });
  return toPython(figures).cast<py::dict>();
}

py::dict linearize(const ScenarioHandle& s, double speed, std::optional<double> rollDeg) {
  cli::checkNumber(speed, cli::kSpeedMps, argumentLocation("speed"));
  TrimOptions trimOptions;
  if (rollDeg) {
    cli::checkRoll(*rollDeg, argumentLocation("roll_deg"));
    cli::checkTurnSpeeds(speed, argumentLocation("speed"));
    trimOptions.roll = *rollDeg * M_PI / 180;
  }
  struct Out {
    analysis::LinearModel lin;
    std::vector<std::string> labels;
    nlohmann::json trim;
  };
  Out out = callQuietly([&] {
    const VehicleModel model(*s.scenario);
    const TrimResult trim = analysis::calcTrim(model, speed, trimOptions);
    analysis::LinearModel lin = analysis::linearize(model, trim);
    std::vector<std::string> labels = cli::labelModesOfModel(lin);
    return Out{std::move(lin), std::move(labels), output::makeTrimJson(model, trim)};
  });
  py::dict result = convertLinearModel(std::move(out.lin), std::move(out.labels));
  result["trim"] = toPython(out.trim);
  return result;
}

py::dict sweep(const ScenarioHandle& s, const SpeedTuple& speeds, std::optional<double> rollDeg, int threads) {
  SweepOptions opt = makeSweepOptions(s, speeds, threads);
  if (rollDeg) {
    cli::checkTurnSpeeds(opt.start, speedsLocation(speeds));
    cli::checkRoll(*rollDeg, argumentLocation("roll_deg"));
    opt.trim.roll = *rollDeg * M_PI / 180;
  }
  analysis::SweepResult result = callQuietly([&] { return analysis::runSweep(VehicleModel(*s.scenario), opt); });
  return convertSweep(std::move(result), s.scenario->name);
}

py::dict turnMap(const ScenarioHandle& s, const SpeedTuple& speeds, const std::array<double, 3>& rollDeg, int threads) {
  analysis::TurnMapOptions mo;
  mo.sweep = makeSweepOptions(s, speeds, threads);
  cli::checkTurnSpeeds(mo.sweep.start, speedsLocation(speeds));
  mo.rolls = cli::makeRollAngles(rollDeg[0], rollDeg[1], rollDeg[2], argumentLocation("roll_deg"));
  cli::checkMapPoints(mo.sweep.start, mo.sweep.stop, mo.sweep.step, mo.rolls.size(), speedsLocation(speeds));
  analysis::TurnMapResult map = callQuietly([&] { return analysis::runTurnMap(VehicleModel(*s.scenario), mo); });
  return convertTurnMap(std::move(map), s.scenario->name);
}

// The samples as one (samples x columns) array, C order; the Python side views its columns.
py::dict simulate(const ScenarioHandle& s, double speed, double duration, const std::vector<std::string>& perturb,
                  const std::string& speedControl, const std::string& integrator, double accuracy, double outputStep,
                  double fallLimitDeg, double rollDeg) {
  simulation::SimulationOptions o;
  o.speed = speed, o.duration = duration, o.accuracy = accuracy, o.outputStep = outputStep;
  o = cli::makeSimulationOptions(o, perturb, speedControl, integrator, fallLimitDeg, rollDeg);
  simulation::SimulationResult r = callQuietly([&] { return simulation::runSimulation(*s.scenario, o); });
  const size_t rows = r.rows.size(), cols = r.columns.size();
  std::vector<double> samples(rows * cols);
  for (size_t k = 0; k < rows; ++k) std::copy(r.rows[k].begin(), r.rows[k].end(), samples.begin() + k * cols);
  py::dict out;
  out["columns"] = r.columns;
  out["samples"] = makeArray2(std::move(samples), rows, cols);
  out["trim_row"] = makeArray(std::move(r.trimRow));
  static const char* kStatus[] = {"completed", "fell", "failed"};
  out["status"] = kStatus[static_cast<int>(r.status)];
  out["message"] = r.message;
  out["end_time_s"] = r.endTime;
  out["steps"] = r.steps;
  out["integrator"] = r.integrator;
  out["wall_seconds"] = r.wallSeconds;
  return out;
}

}  // namespace

void bindAnalysis(py::module_& m) {
  m.def("trim", &trim, py::arg("scenario"), py::arg("speed"), py::arg("roll_deg"), py::arg("hands_free"), py::arg("speeds"));
  m.def("linearize", &linearize, py::arg("scenario"), py::arg("speed"), py::arg("roll_deg"));
  m.def("sweep", &sweep, py::arg("scenario"), py::arg("speeds"), py::arg("roll_deg"), py::arg("threads"));
  m.def("turn_map", &turnMap, py::arg("scenario"), py::arg("speeds"), py::arg("roll_deg"), py::arg("threads"));
  m.def("simulate", &simulate, py::arg("scenario"), py::arg("speed"), py::arg("duration"), py::arg("perturb"),
        py::arg("speed_control"), py::arg("integrator"), py::arg("accuracy"), py::arg("output_step"),
        py::arg("fall_limit_deg"), py::arg("roll_deg"));
}

}  // namespace motostab::python
