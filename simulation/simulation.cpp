// runSimulation: trim, model with the perturbation force, initial state, integration to the output grid.
#include "simulation/simulation.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <memory>
#include <sstream>

#include "io/csv.h"
#include "io/input_error.h"
#include "simulation/simulation_detail.h"

namespace motostab::simulation {

using analysis::TrimResult;
using analysis::calcTrim;
using io::InputError;
using io::extractColumn;
using plugins::BuildContext;
using plugins::PluginRegistry;
using plugins::makeBuiltinRegistry;
using scenario::Scenario;
using scenario::calcMassSummary;
using vehicle::ModelExtension;
using vehicle::VehicleModel;


using SimTK::State;

namespace {

void checkOptions(const SimulationOptions& o) {
  auto bad = [](const std::string& key, const std::string& why) { throw InputError({"command line", 0, 0, key}, why); };
  if (!(o.speed >= 0) || !std::isfinite(o.speed)) bad("--speed", "must be a finite speed >= 0 m/s");
  if (!(o.duration > 0) || !std::isfinite(o.duration)) bad("--duration", "must be > 0 s");
  if (!(o.outputStep > 0)) bad("--output-step", "must be > 0 s");
  if (!(o.duration / o.outputStep <= kMaxOutputSamples))
    bad("--output-step", "--duration " + io::formatNumber(o.duration, 6) + " s / --output-step " + io::formatNumber(o.outputStep, 6) +
                             " s gives " + io::formatNumber(std::ceil(o.duration / o.outputStep), 6) +
                             " output samples; at most 1e5 (each is kept in memory and written): a longer --output-step "
                             "or a shorter --duration");
  if (!(o.accuracy > 0 && o.accuracy < 1)) bad("--accuracy", "must be in (0, 1)");
  if (!(o.maxStep >= 0)) bad("maxStep", "must be >= 0 s (0: the integrator's default)");
  if (!(o.fallRollLimit > 0)) bad("--fall-limit", "must be > 0");
}

// Segment boundaries: pulse switch times and road-step times inside (0, duration), from 0. Switch
// times closer than 1e-12 s (e.g. 0.1 + 0.2 and 0.3) are one switch, at the later time: a pulse
// ending there is then off, and a road step there is applied once.
std::vector<double> calcSegmentStarts(const SimulationOptions& opt) {
  std::vector<double> segmentStarts{0.0};
  for (const auto& p : opt.perturbations)
    if (p.isPulse())
      for (double t : p.getSwitchTimes())
        if (t > 0 && t < opt.duration) segmentStarts.push_back(t);
  for (const auto& p : opt.perturbations)
    if (p.kind == PerturbationKind::RoadStep && p.start > 0 && p.start < opt.duration) segmentStarts.push_back(p.start);
  std::sort(segmentStarts.begin(), segmentStarts.end());
  std::vector<double> merged;
  for (double t : segmentStarts)
    if (!merged.empty() && t - merged.back() < 1e-12) merged.back() = t;
    else merged.push_back(t);
  return merged;
}

std::vector<Perturbation> listPulses(const SimulationOptions& opt) {
  std::vector<Perturbation> pulses;
  for (const auto& p : opt.perturbations)
    if (p.isPulse()) pulses.push_back(p);
  return pulses;
}

}  // namespace

SpeedControl parseSpeedControl(const std::string& name) {
  const std::string n = toLowerCase(name);
  if (n == "none") return SpeedControl::None;
  if (n == "pi") return SpeedControl::PI;
  throw InputError({"command line", 0, 0, "--speed-control"}, "unknown speed control '" + name + "' (none or pi)");
}

int SimulationResult::getColumnIndex(const std::string& name) const {
  for (size_t j = 0; j < columns.size(); ++j)
    if (columns[j] == name) return static_cast<int>(j);
  throw std::out_of_range("simulation result has no column '" + name + "'");
}

std::vector<double> SimulationResult::getColumn(const std::string& name) const {
  return extractColumn(rows, getColumnIndex(name));
}

SimulationResult runSimulation(const Scenario& scenario, const SimulationOptions& options) {
  PluginRegistry registry = makeBuiltinRegistry();
  return runSimulation(scenario, registry, options);
}

SimulationResult runSimulation(const Scenario& scenario, PluginRegistry& registry, const SimulationOptions& opt) {
  using namespace detail;
  checkOptions(opt);
  // The trim runs on the bare model: the controller's integral state would make it singular.
  PluginRegistry trimRegistry = registry;  // a copy: the caller's registry gains the libraries below
  const VehicleModel trimModel(scenario, trimRegistry);
  checkPerturbations(trimModel, opt.perturbations);
  const TrimResult trim = calcTrim(trimModel, opt.speed, opt.trim);

  const std::vector<Perturbation> pulses = listPulses(opt);
  const std::vector<double> segmentStarts = calcSegmentStarts(opt);
  const bool control = opt.speedControl == SpeedControl::PI;
  const double massRadius = calcMassSummary(scenario).mass * scenario.rearWheel.radius;
  const PerturbationForce* force = nullptr;
  ModelExtension extension = [&](BuildContext& ctx, const VehicleModel& m) {
    auto* impl = new PerturbationForce(ctx.forces, m, pulses, segmentStarts, control, opt.speedGainP * massRadius,
                                       opt.speedGainI * massRadius,
                                       trim.turn ? calcHeadingSpeed(trimModel, trim.state) : opt.speed);
    SimTK::Force::Custom(ctx.forces, impl);  // the subsystem owns impl
    force = impl;
    return control ? std::vector<vehicle::AuxiliaryState>{{"speed_control_integral", vehicle::StateRole::Controller}}
                   : std::vector<vehicle::AuxiliaryState>{};
  };
  const VehicleModel model(scenario, registry, {extension});

  State s = makeInitialState(model, trimModel, trim, *force);
  SimulationResult res;
  res.columns = listColumns(model, opt);
  res.numQ = model.getNumQ();
  SampleRecorder recorder(model, *force, opt, s, res);
  res.trimRow = recorder.makeRow(0, s.getY(), 0);
  applyInitialRates(model, s, opt.perturbations);
  applyRoadSteps(model, s, opt.perturbations, 0.0);

  const auto wall0 = std::chrono::steady_clock::now();
  const StepperOptions so = makeStepperOptions(model, opt, s);
  std::unique_ptr<Stepper> integ;
  try {
    integ = makeStepper(model.getSystem(), s, so);
    res.integrator = integ->getName();
    integrate(*integ, model, *force, opt, segmentStarts, recorder);
  } catch (const std::exception& e) {
    res.status = SimulationStatus::Failed;
    std::ostringstream os;
    os << "integration failed after t = " << res.endTime << " s: " << e.what();
    res.message = os.str();
  }
  res.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  if (integ) res.steps = integ->getNumSteps();
  return res;
}

}  // namespace motostab::simulation
