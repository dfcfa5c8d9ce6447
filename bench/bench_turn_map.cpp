// Speed goal of the cornering map: a 41-speed x 10-roll map of the enduro (10-50 m/s at 1 m/s, roll
// 0-45 deg at 5 deg, serial) against its yardstick, 10 upright 41-speed sweeps of the same speeds, in
// the same run. Map and yardstick alternate, so both see the same machine state: counter ratio =
// median over pairs of map / yardstick time (goal <= 1.5), in process CPU time (both are serial, and on
// a machine shared with other jobs the wall time mostly measures the others), wall time beside it.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <ctime>

#include "analysis/turn_map.h"
#include "scenario/scenario.h"

namespace {

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

// Process CPU time, s.
double getCpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct Times {
  double cpu, wall;  ///< s
};

// CPU and wall time of fn().
template <class Fn>
Times measure(Fn fn) {
  const double c0 = getCpuSeconds();
  const auto t0 = std::chrono::steady_clock::now();
  fn();
  return {getCpuSeconds() - c0, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

motostab::analysis::SweepOptions makeSpeeds() {
  motostab::analysis::SweepOptions opt;
  opt.start = 10, opt.stop = 50, opt.step = 1;
  return opt;
}

Times timeUpright(const motostab::vehicle::VehicleModel& model) {
  return measure([&] {
    for (int k = 0; k < 10; ++k) {
      auto r = motostab::analysis::runSweep(model, makeSpeeds());
      benchmark::DoNotOptimize(r.criticalSpeeds.data());
    }
  });
}

Times timeMap(const motostab::vehicle::VehicleModel& model) {
  motostab::analysis::TurnMapOptions opt;
  opt.sweep = makeSpeeds();
  for (int k = 0; k < 10; ++k) opt.rolls.push_back(k * 5 * M_PI / 180);
  return measure([&] {
    auto r = motostab::analysis::runTurnMap(model, opt);
    benchmark::DoNotOptimize(r.sweeps.data());
  });
}

void BM_EnduroTurnMap41x10(benchmark::State& st) {
  const motostab::vehicle::VehicleModel model(motostab::scenario::loadScenario(kEnduro));
  std::vector<double> ratios, wallRatios, uprightMs, mapMs;
  for (auto _ : st) {
    const Times a = timeUpright(model), b = timeMap(model);
    uprightMs.push_back(a.cpu * 1e3), mapMs.push_back(b.cpu * 1e3);
    ratios.push_back(b.cpu / a.cpu), wallRatios.push_back(b.wall / a.wall);
  }
  st.counters["ratio"] = median(ratios);
  st.counters["wall_ratio"] = median(wallRatios);
  st.counters["upright_10_sweeps_cpu_ms"] = median(uprightMs);
  st.counters["map_cpu_ms"] = median(mapMs);
}

}  // namespace

BENCHMARK(BM_EnduroTurnMap41x10)->Iterations(5)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
