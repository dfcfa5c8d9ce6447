#pragma once
// Shared by the sweep benchmarks: the 401-speed sweep (0-40 m/s at 0.1 m/s, serial) timed in wall
// seconds, and the median of a run's ratios.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "analysis/sweep.h"

namespace motostab::bench {

using analysis::SweepOptions;
using analysis::runSweep;
using vehicle::VehicleModel;


inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// Wall time (s) of the 401-speed sweep of `model`; `states` gets the size of its A. `mirror`: the
/// sweep's one-evaluation mirrored lateral columns (SweepOptions::mirrorLateralColumns) allowed.
inline double timeSweep401(const VehicleModel& model, size_t& states, bool mirror = true) {
  SweepOptions opt;
  opt.start = 0, opt.stop = 40, opt.step = 0.1;
  opt.mirrorLateralColumns = mirror;
  const auto t0 = std::chrono::steady_clock::now();
  auto r = runSweep(model, opt);
  benchmark::DoNotOptimize(r.criticalSpeeds.data());
  states = r.models.back().A.rows();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace motostab::bench
