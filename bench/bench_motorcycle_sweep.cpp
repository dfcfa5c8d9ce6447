// Issue 3 speed figures: the enduro `twist` model over 0-40 m/s at 0.1 m/s (401 speeds), serial and
// on two threads, and one realize to Acceleration for the (2n+1)-realize cost ratio (counters: n states,
// realize_us, yardstick_ms = 401 (2n+1) realizes; ratio = Time / yardstick_ms), and the two-thread speed-up
// from 15 alternated pairs.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>

#include "analysis/sweep.h"
#include "bench/realize_loop.h"
#include "scenario/scenario.h"

namespace {

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

void BM_EnduroTwistSweep401(benchmark::State& st) {
  const motostab::VehicleModel model(motostab::loadScenario(kEnduro, {"swingarm.compliance=twist"}));
  motostab::SweepOptions opt;
  opt.start = 0, opt.stop = 40, opt.step = 0.1;
  opt.threads = static_cast<int>(st.range(0));
  size_t states = 0;
  for (auto _ : st) {
    auto r = motostab::runSweep(model, opt);
    states = r.models.back().A.rows();
    benchmark::DoNotOptimize(r.criticalSpeeds.data());
  }
  // The yardstick: (2n+1) realizations to Acceleration per speed, timed here on this machine.
  const double realize = motostab::bench::calcRealizeSeconds(model, motostab::calcTrim(model, 20.0).state, 20000);
  st.counters["n"] = static_cast<double>(states);
  st.counters["realize_us"] = realize * 1e6;
  st.counters["yardstick_ms"] = 401 * (2 * states + 1) * realize * 1e3;
}
BENCHMARK(BM_EnduroTwistSweep401)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

// Serial and two-thread sweeps alternated, so that both see the same machine state (the build VM's
// speed drifts by up to 2x): counter speedup = median over pairs of serial / parallel wall time.
void BM_EnduroTwistSweepSpeedup(benchmark::State& st) {
  const motostab::VehicleModel model(motostab::loadScenario(kEnduro, {"swingarm.compliance=twist"}));
  motostab::SweepOptions opt;
  opt.start = 0, opt.stop = 40, opt.step = 0.1;
  auto timeSweep = [&](int threads) {
    opt.threads = threads;
    const auto t0 = std::chrono::steady_clock::now();
    auto r = motostab::runSweep(model, opt);
    benchmark::DoNotOptimize(r.criticalSpeeds.data());
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  std::vector<double> ratios, serial;
  for (auto _ : st) {
    serial.push_back(timeSweep(1));
    ratios.push_back(serial.back() / timeSweep(2));
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  st.counters["speedup"] = median(ratios);
  st.counters["serial_ms"] = median(serial) * 1e3;
}
BENCHMARK(BM_EnduroTwistSweepSpeedup)->Unit(benchmark::kMillisecond)->Iterations(15)->UseRealTime();

void BM_EnduroTwistRealize(benchmark::State& st) {
  const motostab::VehicleModel model(motostab::loadScenario(kEnduro, {"swingarm.compliance=twist"}));
  motostab::bench::runRealizeLoop(st, model, motostab::calcTrim(model, 20.0).state, motostab::Slot::Q, model.getIndices().roll);
}
BENCHMARK(BM_EnduroTwistRealize)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
