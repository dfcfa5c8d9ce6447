// Speed goal of the cornering map: a 41-speed x 10-roll map of the enduro (10-50 m/s at 1 m/s, roll
// 0-45 deg at 5 deg, serial) against its yardstick, 10 upright 41-speed sweeps of the same speeds, in
// the same run. Map and yardstick alternate, so both see the same machine state: counter ratio =
// median over pairs of map / yardstick wall time (goal <= 1.5).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>

#include "analysis/turn_map.h"
#include "scenario/scenario.h"

namespace {

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

motostab::SweepOptions makeSpeeds() {
  motostab::SweepOptions opt;
  opt.start = 10, opt.stop = 50, opt.step = 1;
  return opt;
}

double timeUpright(const motostab::VehicleModel& model) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < 10; ++k) {
    auto r = motostab::runSweep(model, makeSpeeds());
    benchmark::DoNotOptimize(r.criticalSpeeds.data());
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double timeMap(const motostab::VehicleModel& model) {
  motostab::TurnMapOptions opt;
  opt.sweep = makeSpeeds();
  for (int k = 0; k < 10; ++k) opt.rolls.push_back(k * 5 * M_PI / 180);
  const auto t0 = std::chrono::steady_clock::now();
  auto r = motostab::runTurnMap(model, opt);
  benchmark::DoNotOptimize(r.sweeps.data());
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void BM_EnduroTurnMap41x10(benchmark::State& st) {
  const motostab::VehicleModel model(motostab::loadScenario(kEnduro));
  std::vector<double> ratios, uprightMs, mapMs;
  for (auto _ : st) {
    const double a = timeUpright(model), b = timeMap(model);
    uprightMs.push_back(a * 1e3), mapMs.push_back(b * 1e3), ratios.push_back(b / a);
  }
  st.counters["ratio"] = median(ratios);
  st.counters["upright_10_sweeps_ms"] = median(uprightMs);
  st.counters["map_ms"] = median(mapMs);
}

}  // namespace

BENCHMARK(BM_EnduroTurnMap41x10)->Iterations(5)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
