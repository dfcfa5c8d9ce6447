// Speed figures: the enduro `twist` model over 0-40 m/s at 0.1 m/s (401 speeds), serial and
// on two threads, with the (2n+1)-realize yardstick timed before each sweep (counters: n states,
// realize_us, yardstick_ms = 401 (2n+1) realizes, ratio = median of sweep / yardstick), and the
// two-thread speed-up from 15 alternated pairs against the machine's own two-thread yardstick.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <thread>

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
  const motostab::vehicle::VehicleModel model(motostab::scenario::loadScenario(kEnduro, {"swingarm.compliance=twist"}));
  motostab::analysis::SweepOptions opt;
  opt.start = 0, opt.stop = 40, opt.step = 0.1;
  opt.threads = static_cast<int>(st.range(0));
  const SimTK::State trimmed = motostab::analysis::calcTrim(model, 20.0).state;
  size_t states = 0;
  std::vector<double> realize, ratio;
  for (auto _ : st) {
    // The yardstick, (2n+1) realizations to Acceleration per speed, timed just before each
    // sweep (the VM's speed drifts): ratio = sweep / yardstick, median over the iterations.
    st.PauseTiming();
    realize.push_back(motostab::bench::calcRealizeSeconds(model, trimmed, 3000));
    st.ResumeTiming();
    const auto t0 = std::chrono::steady_clock::now();
    auto r = motostab::analysis::runSweep(model, opt);
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
// The machine's own yardstick, in the same iterations: two independent serial sweeps (one model
// each, nothing shared) on two threads of this process against the same two one after the other
// (counter machine_speedup, median of the ratios); fraction = median of speedup / machine_speedup.
void BM_EnduroTwistSweepSpeedup(benchmark::State& st) {
  const motostab::vehicle::VehicleModel model(motostab::scenario::loadScenario(kEnduro, {"swingarm.compliance=twist"}));
  const std::unique_ptr<motostab::vehicle::VehicleModel> replica = model.makeReplica();
  auto sweep = [](const motostab::vehicle::VehicleModel& m, int threads) {
    motostab::analysis::SweepOptions opt;
    opt.start = 0, opt.stop = 40, opt.step = 0.1;
    opt.threads = threads;
    auto r = motostab::analysis::runSweep(m, opt);
    benchmark::DoNotOptimize(r.criticalSpeeds.data());
  };
  auto seconds = [](const std::function<void()>& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  std::vector<double> ratios, serial, machine, fraction;
  for (auto _ : st) {
    serial.push_back(seconds([&] { sweep(model, 1); }));
    ratios.push_back(serial.back() / seconds([&] { sweep(model, 2); }));
    const double together = seconds([&] {
      std::thread other([&] { sweep(*replica, 1); });
      sweep(model, 1);
      other.join();
    });
    const double oneAfterOther = seconds([&] { sweep(model, 1), sweep(*replica, 1); });
    machine.push_back(oneAfterOther / together);
    fraction.push_back(ratios.back() / machine.back());
  }
  st.counters["speedup"] = median(ratios);
  st.counters["serial_ms"] = median(serial) * 1e3;
  st.counters["machine_speedup"] = median(machine);
  st.counters["fraction"] = median(fraction);
}
BENCHMARK(BM_EnduroTwistSweepSpeedup)->Unit(benchmark::kMillisecond)->Iterations(15)->UseRealTime();

// The input matrix B in a sweep (SweepOptions::linearize.computeB, off by default; the sweep command
// turns it on for linear_models.mat): sweeps with and without it alternated on the enduro `twist` model
// (401 speeds, one thread), so that both see the same machine state. Counters: ratio = median over
// pairs of (with B) / (without B) wall time, without_ms and with_ms their medians.
void BM_EnduroTwistSweepInputMatrix(benchmark::State& st) {
  const motostab::vehicle::VehicleModel model(motostab::scenario::loadScenario(kEnduro, {"swingarm.compliance=twist"}));
  auto seconds = [&](bool computeB) {
    motostab::analysis::SweepOptions opt;
    opt.start = 0, opt.stop = 40, opt.step = 0.1;
    opt.linearize.computeB = computeB;
    const auto t0 = std::chrono::steady_clock::now();
    auto r = motostab::analysis::runSweep(model, opt);
    benchmark::DoNotOptimize(r.criticalSpeeds.data());
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  std::vector<double> without, with, ratio;
  for (auto _ : st) {
    without.push_back(seconds(false));
    with.push_back(seconds(true));
    ratio.push_back(with.back() / without.back());
  }
  st.counters["ratio"] = median(ratio);
  st.counters["without_ms"] = median(without) * 1e3;
  st.counters["with_ms"] = median(with) * 1e3;
}
BENCHMARK(BM_EnduroTwistSweepInputMatrix)->Unit(benchmark::kMillisecond)->Iterations(5)->UseRealTime();

void BM_EnduroTwistRealize(benchmark::State& st) {
  const motostab::vehicle::VehicleModel model(motostab::scenario::loadScenario(kEnduro, {"swingarm.compliance=twist"}));
  motostab::bench::runRealizeLoop(st, model, motostab::analysis::calcTrim(model, 20.0).state, motostab::analysis::Slot::Q, model.getIndices().roll);
}
BENCHMARK(BM_EnduroTwistRealize)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
