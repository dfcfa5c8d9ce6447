#pragma once
// Shared benchmark body: perturb one q or u entry and realize to Acceleration, repeatedly.
#include <benchmark/benchmark.h>

#include <chrono>

#include "analysis/state_function.h"

namespace motostab::bench {

using analysis::Slot;
using analysis::StateEntry;
using analysis::StateFunction;
using vehicle::VehicleModel;


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

/// Mean wall time of one realization to Acceleration after a roll perturbation, s (`count` repeats).
inline double calcRealizeSeconds(const VehicleModel& model, SimTK::State s, int count) {
  const StateFunction fn(model);
  const StateEntry roll{Slot::Q, model.getIndices().roll};
  const double base = fn.get(s, roll);
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < count; ++i) {
    fn.set(s, roll, base + (i % 2 ? 1e-6 : -1e-6));
    model.getSystem().realize(s, SimTK::Stage::Acceleration);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / count;
}

}  // namespace motostab::bench
