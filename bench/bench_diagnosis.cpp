// The Kooijman (2008) diagnosis with every candidate and the robustness reruns on two threads (goal:
// under 30 s on 2 cores). Yardstick, timed in the same run just before: a sweep of the Silvercity over its own
// speed range (0-10 m/s at 0.1 m/s). Counters: seconds per diagnosis (wall), cpu_seconds (the
// process's CPU time over all threads), the ratio to the yardstick, and scenario_reads (times the
// scenario file was opened by the diagnosis). Argument 1: linear models reused (diagnosis/sweep_cache.h;
// the default), 0: every chain computed. With reuse, the store's counters: chains asked for
// (`chains_asked`: each one model build and one chain of trims, linearisations and eigen-decompositions
// without reuse), `chains_computed` (model builds), `hits`, speeds linearised without reuse
// (`linearisations_asked`) and with it (`linearisations`), and the store's peak size (`cache_peak_MB`).
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <memory>

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
  opt.reuseLinearModels = state.range(0) != 0;
  double seconds = 0, ratio = 0, cpu = 0, reads = 0;
  motostab::diagnosis::SweepCache::Counters counters;
  for (auto _ : state) {
    const double yard = timeYardstick();
    opt.sweepCache = opt.reuseLinearModels ? std::make_shared<motostab::diagnosis::SweepCache>() : nullptr;
    const long opened = motostab::io::getYamlFileOpenCount(kScenario);
    const std::clock_t c0 = std::clock();
    const auto t0 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(motostab::diagnosis::runDiagnosis(kScenario, data, opt));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    cpu += static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    reads += static_cast<double>(motostab::io::getYamlFileOpenCount(kScenario) - opened);
    seconds += s;
    ratio += s / yard;
    if (opt.sweepCache) counters = opt.sweepCache->getCounters();
  }
  state.counters["seconds"] = seconds / state.iterations();
  state.counters["cpu_seconds"] = cpu / state.iterations();
  state.counters["scenario_reads"] = reads / state.iterations();
  state.counters["ratio_to_sweep"] = ratio / state.iterations();
  if (!opt.reuseLinearModels) return;
  state.counters["chains_asked"] = static_cast<double>(counters.lookups);
  state.counters["chains_computed"] = static_cast<double>(counters.builds);
  state.counters["hits"] = static_cast<double>(counters.hits);
  state.counters["linearisations_asked"] = static_cast<double>(counters.linearisations + counters.savedLinearisations);
  state.counters["linearisations"] = static_cast<double>(counters.linearisations);
  state.counters["cache_peak_MB"] = static_cast<double>(counters.peakBytes) / 1e6;
}
BENCHMARK(BM_KooijmanDiagnosis)->Arg(1)->Arg(0)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
