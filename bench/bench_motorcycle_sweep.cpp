// Issue 3 speed figures: the enduro `twist` model over 0-40 m/s at 0.1 m/s (401 speeds), serial and
// on two threads, with the (2n+1)-realize yardstick timed before each sweep (counters: n states,
// realize_us, yardstick_ms = 401 (2n+1) realizes, ratio = median of sweep / yardstick), and the
// two-thread speed-up from 15 alternated pairs.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>

#include "analysis/sweep.h"
#include "bench/realize_loop.h"
#include "scenario/scenario.h"

namespace {

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void BM_EnduroTwistSweep401(benchmark::State& st) {
  const motostab::VehicleModel model(motostab::loadScenario(kEnduro, {"swingarm.compliance=twist"}));
  motostab::SweepOptions opt;
  opt.start = 0, opt.stop = 40, opt.step = 0.1;
  opt.threads = static_cast<int>(st.range(0));
  const SimTK::State trimmed = motostab::calcTrim(model, 20.0).state;
  size_t states = 0;
  std::vector<double> realize, ratio;
  for (auto _ : st) {
    // The yardstick, (2n+1) realizations to Acceleration per speed, timed just before each
    // sweep (the VM's speed drifts): ratio = sweep / yardstick, median over the iterations.
    st.PauseTiming();
    realize.push_back(motostab::bench::calcRealizeSeconds(model, trimmed, 3000));
    st.ResumeTiming();
    const auto t0 = std::chrono::steady_clock::now();
    auto r = motostab::runSweep(model, opt);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    states = r.models.back().A.rows();
    ratio.push_back(seconds / (401 * (2 * states + 1) * realize.back()));
    benchmark::DoNotOptimize(r.criticalSpeeds.data());
  }
  st.counters["n"] = static_cast<double>(states);
  st.counters["realize_us"] = median(realize) * 1e6;
  st.counters["yardstick_ms"] = 401 * (2 * states + 1) * median(realize) * 1e3;
  st.counters["ratio"] = median(ratio);
}
BENCHMARK(BM_EnduroTwistSweep401)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(5)->UseRealTime();

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
