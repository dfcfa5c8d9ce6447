// Issue 10 speed goal: the 401-speed enduro sweep (0-40 m/s at 0.1 m/s, serial) with all four model
// extensions present (steer_damper with friction, fork_compliance with torsion, rider_lean, and the
// relaxation_linear tyres read through the `bicycle` preset with every enduro value given beside it,
// so the tyres are the enduro's) against the same sweep without them. Sweeps alternate, so both see
// the same machine state: counter ratio = median over pairs of extended / plain wall time (goal <= 1.3).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>

#include "analysis/sweep.h"
#include "scenario/scenario.h"

namespace {

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

const std::vector<std::string> kExtensions = {
    "steer_damper={damping_Nms_per_rad: 5, coulomb_Nm: 0.5}",
    "fork_compliance={stiffness_Nm_per_rad: 40000, damping_Nms_per_rad: 20, "
    "torsion: {stiffness_Nm_per_rad: 60000, damping_Nms_per_rad: 10}}",
    "rider_lean={hinge_height_m: 0.75, mass_kg: 40, com_m: [0.45, 0, 1.05], "
    "inertia_kgm2: {xx: 2.0, yy: 2.1, zz: 0.7, xy: 0, xz: 0, yz: 0}, stiffness_Nm_per_rad: 2000, damping_Nms_per_rad: 60}",
    "contact.preset=bicycle",
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double timeSweep(const motostab::VehicleModel& model, size_t& states) {
  motostab::SweepOptions opt;
  opt.start = 0, opt.stop = 40, opt.step = 0.1;
  const auto t0 = std::chrono::steady_clock::now();
  auto r = motostab::runSweep(model, opt);
  benchmark::DoNotOptimize(r.criticalSpeeds.data());
  states = r.models.back().A.rows();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void BM_EnduroExtensionsSweep401(benchmark::State& st) {
  const motostab::VehicleModel plain(motostab::loadScenario(kEnduro));
  const motostab::VehicleModel extended(motostab::loadScenario(kEnduro, kExtensions));
  std::vector<double> ratios, plainMs, extendedMs;
  size_t nPlain = 0, nExtended = 0;
  for (auto _ : st) {
    const double a = timeSweep(plain, nPlain), b = timeSweep(extended, nExtended);
    plainMs.push_back(a * 1e3), extendedMs.push_back(b * 1e3), ratios.push_back(b / a);
  }
  st.counters["ratio"] = median(ratios);
  st.counters["plain_ms"] = median(plainMs);
  st.counters["extended_ms"] = median(extendedMs);
  st.counters["n_plain"] = static_cast<double>(nPlain);
  st.counters["n_extended"] = static_cast<double>(nExtended);
}
BENCHMARK(BM_EnduroExtensionsSweep401)->Unit(benchmark::kMillisecond)->Iterations(9)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
