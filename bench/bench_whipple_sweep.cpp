// Speed figures: one Whipple sweep over 0-10 m/s in 0.01 m/s steps (1001 speeds), and the
// cost of one realize to Acceleration after a q, u or z change.
#include <benchmark/benchmark.h>

#include "analysis/sweep.h"
#include "bench/realize_loop.h"
#include "scenario/scenario.h"

namespace {

const std::string kWhipple = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml";

void BM_WhippleSweep1001(benchmark::State& st) {
  const motostab::vehicle::VehicleModel model(motostab::scenario::loadScenario(kWhipple));
  motostab::analysis::SweepOptions opt;
  opt.start = 0, opt.stop = 10, opt.step = 0.01;
  for (auto _ : st) {
    auto r = motostab::analysis::runSweep(model, opt);
    benchmark::DoNotOptimize(r.criticalSpeeds.data());
  }
}
BENCHMARK(BM_WhippleSweep1001)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_TrimAndLinearizeOneSpeed(benchmark::State& st) {
  const motostab::vehicle::VehicleModel model(motostab::scenario::loadScenario(kWhipple));
  const motostab::analysis::TrimResult t = motostab::analysis::calcTrim(model, 5.0);
  for (auto _ : st) {
    const motostab::analysis::TrimResult t2 = motostab::analysis::calcTrim(model, 5.0, {}, &t);
    auto lin = motostab::analysis::linearize(model, t2);
    benchmark::DoNotOptimize(lin.A.data());
  }
}
BENCHMARK(BM_TrimAndLinearizeOneSpeed)->Unit(benchmark::kMicrosecond);

void BM_RealizeAccelerationAfterQChange(benchmark::State& st) {
  const motostab::vehicle::VehicleModel model(motostab::scenario::loadScenario(kWhipple));
  motostab::bench::runRealizeLoop(st, model, motostab::analysis::calcTrim(model, 5.0).state, motostab::analysis::Slot::Q, model.getIndices().roll);
}
BENCHMARK(BM_RealizeAccelerationAfterQChange)->Unit(benchmark::kMicrosecond);

void BM_RealizeAccelerationAfterUChange(benchmark::State& st) {
  const motostab::vehicle::VehicleModel model(motostab::scenario::loadScenario(kWhipple));
  motostab::bench::runRealizeLoop(st, model, motostab::analysis::calcTrim(model, 5.0).state, motostab::analysis::Slot::U, model.getIndices().roll);
}
BENCHMARK(BM_RealizeAccelerationAfterUChange)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
