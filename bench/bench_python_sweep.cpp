// Python against C++: the enduro `twist` model over 0-40 m/s at 0.1 m/s (401 speeds, serial), called as
// motostab.sweep(scenario, speeds=(0, 40, 0.1)) from an embedded Python interpreter that imports the
// built module (build/python), against the same sweep in C++ (the model built from the same scenario,
// then analysis::runSweep, as `motostab sweep` does). Both run in each iteration, alternated, so that
// they see the same machine. Counters: cpp_ms and python_ms (medians), ratio = median of python / C++
// per iteration, overhead_ms = median of python - C++ (argument checks, GIL release, the results turned
// into NumPy arrays and Python objects), model_ms (building the model, in both). The same from the
// thread's CPU time (both run serially on this thread): cpu_ratio and cpu_overhead_ms, which a machine
// shared with other work disturbs far less than the wall-clock figures.
#include <benchmark/benchmark.h>
#include <pybind11/embed.h>

#include <time.h>

#include <chrono>

#include "analysis/sweep.h"
#include "bench/sweep_timing.h"
#include "scenario/scenario.h"

namespace {

namespace py = pybind11;
using Clock = std::chrono::steady_clock;

const std::string kEnduro = std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/enduro.yaml";

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// CPU seconds of the calling thread.
double getThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void BM_EnduroTwistSweep401PythonVsCpp(benchmark::State& st) {
  py::scoped_interpreter interpreter;  // once per process (NumPy cannot be initialised twice)
  py::module_::import("sys").attr("path").attr("insert")(0, MOTOSTAB_PYTHON_PATH);
  const py::module_ motostab = py::module_::import("motostab");
  const py::object pyScenario =
      motostab.attr("Scenario").attr("load")(kEnduro).attr("with_")(py::dict(py::arg("swingarm.compliance") = "twist"));
  const py::object pySweep = motostab.attr("sweep");
  const py::tuple speeds = py::make_tuple(0.0, 40.0, 0.1);
  const motostab::scenario::Scenario scenario = motostab::scenario::loadScenario(kEnduro, {"swingarm.compliance=twist"});
  motostab::analysis::SweepOptions opt;
  opt.start = 0, opt.stop = 40, opt.step = 0.1;
  opt.linearize.computeB = true;  // the sweep `motostab sweep` and motostab.sweep both run
  std::vector<double> cpp, python, ratio, overhead, model, cpuRatio, cpuOverhead;
  for (auto _ : st) {
    auto t0 = Clock::now();
    double c0 = getThreadCpuSeconds();
    {
      const motostab::vehicle::VehicleModel m(scenario);
      model.push_back(secondsSince(t0));
      const auto r = motostab::analysis::runSweep(m, opt);
      benchmark::DoNotOptimize(r.criticalSpeeds.data());
    }
    cpp.push_back(secondsSince(t0));
    const double cppCpu = getThreadCpuSeconds() - c0;
    t0 = Clock::now();
    c0 = getThreadCpuSeconds();
    const py::object result = pySweep(pyScenario, py::arg("speeds") = speeds);
    python.push_back(secondsSince(t0));
    const double pythonCpu = getThreadCpuSeconds() - c0;
    benchmark::DoNotOptimize(result.ptr());
    cpuRatio.push_back(pythonCpu / cppCpu);
    cpuOverhead.push_back(pythonCpu - cppCpu);
    ratio.push_back(python.back() / cpp.back());
    overhead.push_back(python.back() - cpp.back());
  }
  using motostab::bench::median;
  st.counters["cpp_ms"] = median(cpp) * 1e3;
  st.counters["python_ms"] = median(python) * 1e3;
  st.counters["ratio"] = median(ratio);
  st.counters["overhead_ms"] = median(overhead) * 1e3;
  st.counters["model_ms"] = median(model) * 1e3;
  st.counters["cpu_ratio"] = median(cpuRatio);
  st.counters["cpu_overhead_ms"] = median(cpuOverhead) * 1e3;
}
BENCHMARK(BM_EnduroTwistSweep401PythonVsCpp)->Unit(benchmark::kMillisecond)->Iterations(15)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
