// The Kooijman (2008) diagnosis with every candidate and the robustness reruns on two threads (goal:
// under 30 s on 2 cores). Yardstick, timed in the same run just before: a sweep of the Silvercity over its own
// speed range (0-10 m/s at 0.1 m/s). Counters: seconds per diagnosis and the ratio to the yardstick.
#include <benchmark/benchmark.h>

#include <chrono>

#include "analysis/sweep.h"
#include "diagnosis/diagnosis.h"
#include "scenario/scenario.h"
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
  double seconds = 0, ratio = 0;
  for (auto _ : state) {
    const double yard = timeYardstick();
    const auto t0 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(motostab::diagnosis::runDiagnosis(kScenario, data, opt));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    seconds += s;
    ratio += s / yard;
  }
  state.counters["seconds"] = seconds / state.iterations();
  state.counters["ratio_to_sweep"] = ratio / state.iterations();
}
BENCHMARK(BM_KooijmanDiagnosis)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
