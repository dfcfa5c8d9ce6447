// Speed figures: real-time factor (simulated seconds per wall second, counter "rtf") of
// `motostab simulate` runs at the default accuracy (1e-6, auto integrator, PI speed control, 0.01 s
// samples; auto picks ROS34PW2 for the enduro, RungeKuttaMerson for the constrained Whipple). The
// headline figure is the enduro torsion model at 20 m/s; Whipple at 5 m/s for comparison.
// Wall time counts the integration and sampling only (SimulationResult::wallSeconds), not the trim.
#include <benchmark/benchmark.h>

#include "simulation/simulation.h"

using motostab::simulation::SimulationOptions;


namespace {


void runRealTimeFactor(benchmark::State& st, const std::string& scenarioFile, const std::vector<std::string>& sets,
                       double speed, const std::string& perturb, double duration) {
  const motostab::scenario::Scenario scenario = motostab::scenario::loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + scenarioFile, sets);
  SimulationOptions opt;
  opt.speed = speed;
  opt.duration = duration;
  opt.perturbations = {motostab::simulation::parsePerturbation(perturb)};
  double simulated = 0, wall = 0;
  int steps = 0;
  for (auto _ : st) {
    const auto r = motostab::simulation::runSimulation(scenario, opt);
    simulated += r.endTime;
    wall += r.wallSeconds;
    steps += r.steps;
  }
  st.counters["rtf"] = simulated / wall;
  st.counters["steps_per_s"] = steps / simulated;
}

void BM_EnduroTorsion20mps(benchmark::State& st) {
  runRealTimeFactor(st, "/scenarios/enduro.yaml", {"swingarm.compliance=torsion"}, 20, "steer-torque:10:0.1:0.05", 10);
}
BENCHMARK(BM_EnduroTorsion20mps)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_Whipple5mps(benchmark::State& st) {
  runRealTimeFactor(st, "/scenarios/whipple-benchmark.yaml", {}, 5, "steer-torque:1:0.1:0.1:halfsine", 10);
}
BENCHMARK(BM_Whipple5mps)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
