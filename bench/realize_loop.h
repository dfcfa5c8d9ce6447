#pragma once
// Shared benchmark body: perturb one q or u entry and realize to Acceleration, repeatedly.
#include <benchmark/benchmark.h>

#include "analysis/state_function.h"

namespace motostab::bench {

inline void runRealizeLoop(benchmark::State& st, const VehicleModel& model, SimTK::State s, Slot slot, int index) {
  const StateFunction fn(model);
  const double base = fn.get(s, {slot, index});
  double d = 1e-6;
  for (auto _ : st) {
    fn.set(s, {slot, index}, base + (d = -d));
    model.getSystem().realize(s, SimTK::Stage::Acceleration);
    benchmark::DoNotOptimize(s.getUDot()[0]);
  }
}

}  // namespace motostab::bench
