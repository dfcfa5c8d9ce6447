// Magic Formula speed goal: the 401-speed enduro sweep (0-40 m/s at 0.1 m/s, serial) with
// `magic_formula` tyres against the same sweep with the enduro's `relaxation_linear` tyres. Arg 0: the
// motorcycle Magic Formula tyres of scenarios/supersport-mf.yaml (relaxation lengths and radial laws set
// to the enduro's); arg 1: the MF 6.1 sample .tir file (tests/data) on both wheels; arg 2: that file
// without its forces at zero slip (shifts, residual torque, Mx, My scaled to 0). Sweeps alternate, so
// both see the same machine state: counter ratio = median over pairs of MF / linear wall time (goal
// <= 1.3).
#include <benchmark/benchmark.h>
#include <yaml-cpp/yaml.h>

#include "bench/sweep_timing.h"
#include "scenario/scenario.h"

namespace {

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";
const std::string kSupersportMf = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/supersport-mf.yaml";
const std::string kSampleTir =
    std::string(MOTOSTAB_SOURCE_DIR) + "/tests/data/reference/MF61-sample-tir/sample_MF61_ExternData.tir";

// The enduro's own relaxation lengths and radial laws, for either tyre model.
const std::vector<std::string> kEnduroTyreSettings = {
    "contact.front.relaxation_length_m=0.089",      "contact.rear.relaxation_length_m=0.179",
    "contact.front.radial_stiffness_N_per_m=100000", "contact.rear.radial_stiffness_N_per_m=120000",
    "contact.front.radial_damping_Ns_per_m=200",     "contact.rear.radial_damping_Ns_per_m=200"};

std::vector<std::string> makeOverrides(int which) {
  std::string contact;
  if (which == 0) {
    YAML::Emitter e;
    e.SetMapFormat(YAML::Flow);
    e.SetSeqFormat(YAML::Flow);
    e << YAML::LoadFile(kSupersportMf)["contact"];
    contact = e.c_str();
  } else {
    // Arg 2: the same file with its forces at zero slip scaled away (a symmetric straight run).
    const std::string scaling =
        which == 2 ? ", scaling: {LHX: 0, LVX: 0, LHY: 0, LVY: 0, LRES: 0, LMX: 0, LMY: 0}" : "";
    contact = "{model: magic_formula, front: {tir: " + kSampleTir + scaling + "}, rear: {tir: " + kSampleTir + scaling + "}}";
  }
  std::vector<std::string> out{"contact=" + contact};
  out.insert(out.end(), kEnduroTyreSettings.begin(), kEnduroTyreSettings.end());
  return out;
}

using motostab::bench::median;
using motostab::bench::timeSweep401;

void BM_EnduroMagicFormulaSweep401(benchmark::State& st) {
  const motostab::VehicleModel linear(motostab::loadScenario(kEnduro));
  const motostab::VehicleModel mf(motostab::loadScenario(kEnduro, makeOverrides(static_cast<int>(st.range(0)))));
  std::vector<double> ratios, linearMs, mfMs;
  size_t nLinear = 0, nMf = 0;
  for (auto _ : st) {
    const double a = timeSweep401(linear, nLinear), b = timeSweep401(mf, nMf);
    linearMs.push_back(a * 1e3), mfMs.push_back(b * 1e3), ratios.push_back(b / a);
  }
  st.counters["ratio"] = median(ratios);
  st.counters["linear_ms"] = median(linearMs);
  st.counters["mf_ms"] = median(mfMs);
  st.counters["n_linear"] = static_cast<double>(nLinear);
  st.counters["n_mf"] = static_cast<double>(nMf);
}
BENCHMARK(BM_EnduroMagicFormulaSweep401)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(5)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
