// The Kooijman (2008) diagnosis with every candidate and the robustness reruns on two threads (goal:
// under 30 s on 2 cores). Yardstick, timed in the same run just before: a sweep of the Silvercity over its own
// speed range (0-10 m/s at 0.1 m/s). Counters: seconds per diagnosis (wall), cpu_seconds (the
// process's CPU time over all threads), the ratio to the yardstick, and scenario_reads (times the
// scenario file was opened by the diagnosis).
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>

#include "analysis/sweep.h"
#include "diagnosis/diagnosis.h"
#include "scenario/scenario.h"
#include "io/yaml_map.h"
#include "vehicle/vehicle_model.h"

namespace {

const std::string kScenario = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/kooijman-silvercity.yaml";
const std::string kData = std::string(MOTOSTAB_SOURCE_DIR) + "/examples/diagnosis/kooijman2008.yaml";

double timeYardstick() {
  const auto t0 = std::chrono::steady_clock::now();
  const motostab::vehicle::VehicleModel model(motostab::scenario::loadScenario(kScenario));
  benchmark::DoNotOptimize(motostab::analysis::runSweep(model, motostab::analysis::SweepOptions()));
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void BM_KooijmanDiagnosis(benchmark::State& state) {
  const motostab::diagnosis::MeasuredData data = motostab::diagnosis::loadMeasuredData(kData);
  motostab::diagnosis::DiagnosisOptions opt;
  opt.threads = 2;
  opt.robustness = true;  // the reruns with each data source left out and at mid speeds
  double seconds = 0, ratio = 0, cpu = 0, reads = 0;
  for (auto _ : state) {
    const double yard = timeYardstick();
    const long opened = motostab::io::getYamlFileOpenCount(kScenario);
    const std::clock_t c0 = std::clock();
    const auto t0 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(motostab::diagnosis::runDiagnosis(kScenario, data, opt));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    cpu += static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    reads += static_cast<double>(motostab::io::getYamlFileOpenCount(kScenario) - opened);
    seconds += s;
    ratio += s / yard;
  }
  state.counters["seconds"] = seconds / state.iterations();
  state.counters["cpu_seconds"] = cpu / state.iterations();
  state.counters["scenario_reads"] = reads / state.iterations();
  state.counters["ratio_to_sweep"] = ratio / state.iterations();
}
BENCHMARK(BM_KooijmanDiagnosis)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
