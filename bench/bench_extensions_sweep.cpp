// Speed figures: the 401-speed enduro sweep (0-40 m/s at 0.1 m/s, serial) with all four model
// extensions present (steer_damper with friction, fork_compliance with torsion, rider_lean, and the
// relaxation_linear tyres read through the `bicycle` preset with every enduro value given beside it,
// so the tyres are the enduro's) against the same sweep without them. Sweeps alternate, so both see
// the same machine state: counter ratio = median over pairs of extended / plain wall time (goal <= 1.3).
#include <benchmark/benchmark.h>

#include "bench/sweep_timing.h"
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

using motostab::bench::median;
using motostab::bench::timeSweep401;

// Arg 0: all four extensions; arg k = 1..4: extension k alone (kExtensions[k - 1]).
void BM_EnduroExtensionsSweep401(benchmark::State& st) {
  const motostab::vehicle::VehicleModel plain(motostab::scenario::loadScenario(kEnduro));
  const int which = static_cast<int>(st.range(0));
  const std::vector<std::string> overrides =
      which == 0 ? kExtensions : std::vector<std::string>{kExtensions[static_cast<size_t>(which - 1)]};
  const motostab::vehicle::VehicleModel extended(motostab::scenario::loadScenario(kEnduro, overrides));
  std::vector<double> ratios, plainMs, extendedMs;
  size_t nPlain = 0, nExtended = 0;
  for (auto _ : st) {
    const double a = timeSweep401(plain, nPlain), b = timeSweep401(extended, nExtended);
    plainMs.push_back(a * 1e3), extendedMs.push_back(b * 1e3), ratios.push_back(b / a);
  }
  st.counters["ratio"] = median(ratios);
  st.counters["plain_ms"] = median(plainMs);
  st.counters["extended_ms"] = median(extendedMs);
  st.counters["n_plain"] = static_cast<double>(nPlain);
  st.counters["n_extended"] = static_cast<double>(nExtended);
}
BENCHMARK(BM_EnduroExtensionsSweep401)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(9)->UseRealTime();
BENCHMARK(BM_EnduroExtensionsSweep401)->DenseRange(1, 4)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
