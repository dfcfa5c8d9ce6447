// Speed figures: uncertainty studies (motostab uncertainty). Each study runs on 2 threads
// (a 2-core machine); counters give the CPU time and the ratio of wall time to the sum of the
// serial sweeps' yardstick (one nominal sweep timed just before, times the sweeps, divided by 2).
// The MPI case times `mpirun -n 1` and `-n 2` of the motostab binary, alternated, and reports the
// speed-up as the median ratio.
#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "analysis/sweep.h"
#include "uncertainty/uncertainty_summary.h"
#include "vehicle/vehicle_model.h"

namespace {

using Clock = std::chrono::steady_clock;
const std::string kDir = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/";

// A bundled scenario with an uncertainty section, in a temporary file.
std::string writeScenario(const std::string& bundled, const std::string& section) {
  const auto file = std::filesystem::temp_directory_path() / ("motostab-bench-uq-" + bundled);
  std::ifstream in(kDir + bundled);
  std::ofstream out(file);
  out << in.rdbuf() << "\n" << section;
  return file.string();
}

const char* kWhippleSection =
    "uncertainty:\n  geometry.trail_m: 0.002\n  geometry.wheelbase_m: 0.005\n  rear_frame.mass_kg: 2\n"
    "  rear_frame.com_m[2]: 0.01\n  front_frame.inertia_kgm2.xz: 0.001\n";
const char* kEnduroSection =
    "uncertainty:\n  swingarm.twist.stiffness_Nm_per_rad: 5000\n  swingarm.twist.damping_Nms_per_rad: 0.2\n"
    "  geometry.normal_trail_m: 0.003\n  rear_frame.com_m[2]: 0.01\n";

double calcCpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

void runStudy(benchmark::State& st, const std::string& file, const std::vector<std::string>& overrides, size_t samples,
              double start, double stop, double step) {
  motostab::uncertainty::UncertaintyOptions o;
  o.samples = samples, o.start = start, o.stop = stop, o.step = step;
  const auto setup = motostab::uncertainty::prepareUncertainty(file, overrides, o);
  std::vector<size_t> all(motostab::uncertainty::getTaskCount(setup));
  for (size_t t = 0; t < all.size(); ++t) all[t] = t;
  for (auto _ : st) {
    st.PauseTiming();
    const auto t0 = Clock::now();  // yardstick: one serial nominal sweep
    motostab::uncertainty::runTask(setup, 0);
    const double yard = std::chrono::duration<double>(Clock::now() - t0).count() * all.size() / 2;
    const double cpu0 = calcCpuSeconds();
    st.ResumeTiming();
    const auto w0 = Clock::now();
    auto r = motostab::uncertainty::runTasks(setup, all, 2);
    const double wall = std::chrono::duration<double>(Clock::now() - w0).count();
    benchmark::DoNotOptimize(r.data());
    st.counters["cpu_s"] = calcCpuSeconds() - cpu0;
    st.counters["ratio"] = wall / yard;
    st.counters["sweeps"] = static_cast<double>(all.size());
  }
}

void BM_Whipple1000Samples(benchmark::State& st) {
  runStudy(st, writeScenario("whipple-benchmark.yaml", kWhippleSection), {}, 1000, 0, 10, 0.25);
}
BENCHMARK(BM_Whipple1000Samples)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

void BM_EnduroTwist200Samples(benchmark::State& st) {
  runStudy(st, writeScenario("enduro.yaml", kEnduroSection), {"swingarm.compliance=twist"}, 200, 0, 40, 1);
}
BENCHMARK(BM_EnduroTwist200Samples)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// CPU time (user + system) of finished child processes so far, s.
double calcChildCpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Wall time of one `mpirun -n K motostab uncertainty` of the enduro study, s; `cpu` gets its CPU time.
double timeMpi(int ranks, const std::string& file, double& cpu) {
  const std::string root = geteuid() == 0 ? " --allow-run-as-root" : "";
  const std::string cmd = "OMPI_MCA_btl=self,vader mpirun" + root + " --oversubscribe -n " + std::to_string(ranks) + " " +
                          MOTOSTAB_BINARY + " uncertainty " + file +
                          " --set swingarm.compliance=twist --samples 200 --speeds 0:40:1 --out " +
                          (std::filesystem::temp_directory_path() / "motostab-bench-uq-mpi").string() + " > /dev/null 2>&1";
  const auto t0 = Clock::now();
  const double c0 = calcChildCpuSeconds();
  if (std::system(cmd.c_str()) != 0) return -1;
  cpu = calcChildCpuSeconds() - c0;
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

void BM_EnduroMpiSpeedup(benchmark::State& st) {
  const std::string file = writeScenario("enduro.yaml", kEnduroSection);
  for (auto _ : st) {
    std::vector<double> ratio;
    for (int pair = 0; pair < 3; ++pair) {
      double cpuOne = 0, cpuTwo = 0;
      const double one = timeMpi(1, file, cpuOne), two = timeMpi(2, file, cpuTwo);
      if (one < 0 || two < 0) {
        st.SkipWithError("mpirun failed (is OpenMPI installed?)");
        return;
      }
      ratio.push_back(one / two);
      st.counters["one_rank_s"] = one;
      st.counters["two_ranks_s"] = two;
      // CPU time of both runs: equal work means an idle machine's speed-up is near 2 t_1 / (t_2 + t_0).
      st.counters["one_rank_cpu_s"] = cpuOne;
      st.counters["two_ranks_cpu_s"] = cpuTwo;
    }
    std::sort(ratio.begin(), ratio.end());
    st.counters["speedup"] = ratio[1];
  }
}
BENCHMARK(BM_EnduroMpiSpeedup)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
