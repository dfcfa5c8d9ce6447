// Magic Formula speed goal: the 401-speed enduro sweep (0-40 m/s at 0.1 m/s, serial) with
// `magic_formula` tyres against the same sweep with the enduro's `relaxation_linear` tyres.
// BM_EnduroMagicFormulaSweep401/T/M: T = 0, the motorcycle Magic Formula tyres of
// scenarios/supersport-mf.yaml (relaxation lengths, radial laws and crown radii set to the enduro's);
// T = 1, the MF 6.1 sample .tir file (tests/data) on both wheels; T = 2, that file without its forces
// at zero slip (every shift, the kappa-induced side force, residual torque, Fx arm, Mx and My scaled to
// 0: a mirror-symmetric straight run). M = 1: both sweeps may use the mirrored lateral columns
// (SweepOptions::mirrorLateralColumns, used only where checkMirrorSymmetry passes); M = 0: neither
// does (equal work per column). Sweeps alternate, so both see the same machine state: counter ratio =
// median over pairs of MF / linear wall time (goal <= 1.3).
// BM_TyreEvaluation/T: one steady-state evaluation of the law (T = 0 motorcycle front, 1 MF 6.1
// sample) at drawn slips, ns per call.
#include <benchmark/benchmark.h>
#include <yaml-cpp/yaml.h>

#include "bench/sweep_timing.h"
#include "analysis/linearize.h"
#include "core/portable_random.h"
#include "scenario/scenario.h"
#include "io/yaml_map.h"
#include "tyres/coefficient_source.h"
#include "tyres/magic_formula.h"
#include "tyres/tir_file.h"

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
    std::vector<std::string> out{"contact=" + contact, "contact.front.coefficients.CROWN_RADIUS=0.045",
                                 "contact.rear.coefficients.CROWN_RADIUS=0.070"};
    out.insert(out.end(), kEnduroTyreSettings.begin(), kEnduroTyreSettings.end());
    return out;
  } else {
    // Arg 2: the same file with its forces at zero slip scaled away (a symmetric straight run).
    const std::string scaling =
        which == 2 ? ", scaling: {LHX: 0, LVX: 0, LHY: 0, LVY: 0, LVYKA: 0, LRES: 0, LS: 0, LMX: 0, LMY: 0}" : "";
    contact = "{model: magic_formula, front: {tir: " + kSampleTir + scaling + "}, rear: {tir: " + kSampleTir + scaling + "}}";
  }
  std::vector<std::string> out{"contact=" + contact};
  out.insert(out.end(), kEnduroTyreSettings.begin(), kEnduroTyreSettings.end());
  return out;
}

using motostab::bench::median;
using motostab::bench::timeSweep401;

void BM_EnduroMagicFormulaSweep401(benchmark::State& st) {
  const motostab::vehicle::VehicleModel linear(motostab::scenario::loadScenario(kEnduro));
  const motostab::vehicle::VehicleModel mf(motostab::scenario::loadScenario(kEnduro, makeOverrides(static_cast<int>(st.range(0)))));
  const bool mirror = st.range(1) != 0;
  std::vector<double> ratios, linearMs, mfMs;
  size_t nLinear = 0, nMf = 0;
  for (auto _ : st) {
    const double a = timeSweep401(linear, nLinear, mirror), b = timeSweep401(mf, nMf, mirror);
    linearMs.push_back(a * 1e3), mfMs.push_back(b * 1e3), ratios.push_back(b / a);
  }
  st.counters["ratio"] = median(ratios);
  st.counters["linear_ms"] = median(linearMs);
  st.counters["mf_ms"] = median(mfMs);
  st.counters["n_linear"] = static_cast<double>(nLinear);
  st.counters["n_mf"] = static_cast<double>(nMf);
  // Why a sweep costs what it costs (one untimed sweep each): Newton iterations and trim Jacobians
  // summed over the speeds, and the column groups of A at 20 m/s (each group is one or two evaluations).
  for (const auto& [name, model] : {std::pair<const char*, const motostab::vehicle::VehicleModel*>{"linear", &linear}, {"mf", &mf}}) {
    motostab::analysis::SweepOptions opt;
    opt.start = 0, opt.stop = 40, opt.step = 0.1;
    opt.mirrorLateralColumns = mirror;
    const auto r = motostab::analysis::runSweep(*model, opt);
    double iterations = 0, jacobians = 0;
    for (const auto& t : r.trims) iterations += t.iterations, jacobians += t.jacobianEvaluations;
    const auto grouping = motostab::analysis::calcColumnGrouping({&r.models[199], &r.models[200]});
    st.counters[std::string("trim_iter_") + name] = iterations;
    st.counters[std::string("trim_jac_") + name] = jacobians;
    st.counters[std::string("groups_") + name] = static_cast<double>(grouping.groups.size());
  }
}
BENCHMARK(BM_EnduroMagicFormulaSweep401)
    ->ArgsProduct({{0, 1, 2}, {1, 0}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5)
    ->UseRealTime();

void BM_TyreEvaluation(benchmark::State& st) {
  std::unique_ptr<motostab::tyres::TyreForceLaw> law;
  double Fz = 3000;
  if (st.range(0) == 0) {
    YAML::Node front = YAML::LoadFile(kSupersportMf)["contact"]["front"]["coefficients"];
    motostab::io::YamlMap m(front, kSupersportMf, "contact.front.coefficients");
    law = motostab::tyres::makeTyreForceLaw(motostab::tyres::MagicFormulaVariant::Motorcycle, *motostab::tyres::makeYamlSource(m, nullptr));
    Fz = 1100;
  } else {
    const motostab::tyres::TirFile file = motostab::tyres::TirFile::load(kSampleTir);
    const auto variant = file.getFitType() == 62 ? motostab::tyres::MagicFormulaVariant::MF62 : motostab::tyres::MagicFormulaVariant::MF61;
    law = motostab::tyres::makeTyreForceLaw(variant, *motostab::tyres::makeTirSource(file, nullptr));
  }
  motostab::core::PortableRandom rng(5);
  std::vector<motostab::tyres::TyreSlip> slips(256);
  for (auto& s : slips) s = {Fz * rng.drawUniform(0.5, 1.5), rng.drawUniform(-0.02, 0.02), rng.drawUniform(-0.05, 0.05),
                            rng.drawUniform(-0.1, 0.1), 20};
  size_t i = 0;
  for (auto _ : st) benchmark::DoNotOptimize(law->calcForces(slips[i++ & 255]));
}
BENCHMARK(BM_TyreEvaluation)->DenseRange(0, 1)->Unit(benchmark::kNanosecond);

}  // namespace

BENCHMARK_MAIN();
