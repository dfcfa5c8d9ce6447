// motostab uncertainty: parameter uncertainties -> distributions of critical speeds and modes, on
// one process (threads) or MPI ranks (docs/uncertainty.md, docs/distributed.md).
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <mutex>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "apps/option_checks.h"
#include "io/input_error.h"
#include "io/output_folder.h"
#include "io/result_error.h"
#include "scenario/scenario_source.h"
#include "uncertainty/distributed.h"
#include "output/scenario_output.h"
#include "output/uncertainty_output.h"

namespace motostab::cli {

using io::InputError;
using io::OutputFolder;
using output::makeUncertaintyReport;
using output::writeUncertaintyOutputs;
using scenario::Scenario;
using scenario::ScenarioSource;
using scenario::ParameterOverrides;
using uncertainty::DistributedSession;
using uncertainty::UncertaintyOptions;
using uncertainty::UncertaintySetup;
using uncertainty::UncertaintySummary;
using uncertainty::gatherResults;
using uncertainty::getModeValueCount;
using uncertainty::getRankTasks;
using uncertainty::getTaskCount;
using uncertainty::prepareUncertainty;
using uncertainty::runTasks;
using uncertainty::summarizeUncertainty;

namespace {

struct UncertaintyArgs {
  std::string scenario, samples = "1000", seed = "1", method = "mc", speeds, out;
  std::vector<std::string> overrides;
  int threads = 1;
  bool strict = false;
};

// An unsigned integer option, all digits, in [minimum, maximum]; InputError naming the option otherwise.
uint64_t parseCount(const std::string& option, const std::string& text, uint64_t minimum, uint64_t maximum) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || *end != '\0' || errno == ERANGE)
    throw InputError({option, 0, 0, text}, "expected a non-negative integer");
  if (v < minimum) throw InputError({option, 0, 0, text}, "must be at least " + std::to_string(minimum));
  if (v > maximum) throw InputError({option, 0, 0, text}, "must be at most " + std::to_string(maximum));
  return v;
}

// A progress bar on stderr, redrawn when the percentage changes; silent unless stderr is a terminal.
class ProgressBar {
 public:
  ProgressBar(size_t total, bool enabled) : total_(total), enabled_(enabled && isatty(STDERR_FILENO)) {}
  void update(size_t done) {
    if (!enabled_) return;
    std::lock_guard<std::mutex> guard(lock_);
    const int percent = static_cast<int>(100 * done / std::max<size_t>(1, total_));
    if (percent == shown_) return;
    shown_ = percent;
    std::fprintf(stderr, "\r[%-40s] %3d%% %zu/%zu sweeps", std::string(static_cast<size_t>(percent * 40 / 100), '#').c_str(),
                 percent, done, total_);
    if (done >= total_) std::fprintf(stderr, "\n");
  }

 private:
  size_t total_;
  bool enabled_;
  std::mutex lock_;
  int shown_ = -1;
};

UncertaintyOptions makeOptions(const UncertaintyArgs& a, const Scenario& scenario) {
  UncertaintyOptions o;
  o.method = parseSamplingMethod(a.method, {"--method", 0, 0, a.method});
  o.samples = parseCount("--samples", a.samples, 1, kMaxSamples);
  o.seed = parseCount("--seed", a.seed, 0, UINT64_MAX);
  o.start = scenario.speeds.start, o.stop = scenario.speeds.stop, o.step = scenario.speeds.step;
  if (!a.speeds.empty()) parseSpeedRange(a.speeds, o.start, o.stop, o.step);
  return o;
}

// The study keeps every task's results (mode values at every speed) in memory: refused above
// kMaxResultBytes, naming the options that set it, rather than running out of memory hours later.
void checkResultSize(const UncertaintyArgs& a, const UncertaintySetup& setup) {
  constexpr double kMaxResultBytes = 4.0 * (1ull << 30);
  const double bytes = static_cast<double>(getTaskCount(setup)) *
                       static_cast<double>(getModeValueCount(setup) + setup.params.size() + 16) * sizeof(double);
  if (bytes > kMaxResultBytes)
    throw InputError({"--samples", 0, 0, a.samples},
                     std::to_string(getTaskCount(setup)) + " sweeps of " + std::to_string(getModeValueCount(setup) / 2) +
                         " mode values would keep " + std::to_string(static_cast<long>(bytes / (1 << 20))) +
                         " MiB of results (at most 4096): lower --samples or coarsen --speeds");
}

void runUncertainty(const UncertaintyArgs& a) {
  DistributedSession session;
  const ParameterOverrides changes(a.overrides);  // the --set text, parsed once
  const auto source = ScenarioSource::open(a.scenario);  // the file read once, for the command and every sample
  Scenario scenario = source->load(changes);
  reportScenarioWarnings(scenario, a.strict, session.getRank() == 0);
  const UncertaintySetup setup = prepareUncertainty(source, changes, makeOptions(a, scenario));
  checkResultSize(a, setup);
  const std::string out = getOutputFolder(a.out, scenario.name, "uncertainty");
  std::unique_ptr<OutputFolder> folder;  // rank 0 writes; inputs are all checked by now
  if (session.getRank() == 0) folder = std::make_unique<OutputFolder>(out);
  const size_t count = getTaskCount(setup);
  const auto mine = getRankTasks(count, session.getRank(), session.getSize());
  ProgressBar bar(mine.size(), session.getRank() == 0);
  const auto local = runTasks(setup, mine, a.threads, [&](size_t done) { bar.update(done); });
  const auto all = gatherResults(session, local, count, setup.params.size(), getModeValueCount(setup));
  if (session.getRank() != 0) return;
  const UncertaintySummary summary = summarizeUncertainty(setup, all);
  if (summary.succeeded == 0) {  // valid input, no result: no sample to summarise
    const auto failed = std::find_if(all.rbegin(), all.rend(), [](const auto& r) { return !r.reason.empty(); });
    throw io::ResultError("every one of the " + std::to_string(summary.samples) + " samples failed" +
                          (failed == all.rend() ? std::string() : " (the last: " + failed->reason + ")"));
  }
  writeUncertaintyOutputs(folder->getPath(), scenario.name, setup, summary, all);
  output::writeScenarioJson(folder->getPath(), scenario);
  folder->commit();
  std::cout << makeUncertaintyReport(scenario.name, setup, summary) << "\nWrote " << out
            << "/{summary.json, samples.csv, mode_quantiles.csv, sensitivity.csv, report.md, fan_*, histogram_*, "
               "sensitivity_* (.gp/.png/.svg)}"
            << (session.isDistributed() ? " from " + std::to_string(session.getSize()) + " MPI ranks" : "") << "\n";
}

}  // namespace

void registerUncertaintyCommands(CLI::App& app) {
  auto a = std::make_shared<UncertaintyArgs>();
  CLI::App* u = app.add_subcommand("uncertainty", "Critical-speed distributions and sensitivities from the scenario's uncertainty section (mc or sobol; threads; MPI)");
  u->add_option("scenario", a->scenario, "Scenario YAML file with an uncertainty section")->required()->check(CLI::ExistingFile);
  u->add_option("--samples", a->samples, "mc: samples; sobol: base rows N (N (P + 2) sweeps); default 1000, at most 100000");
  u->add_option("--seed", a->seed, "Random seed, a non-negative integer (default 1); sample i depends only on (seed, i)");
  u->add_option("--method", a->method, "mc (Monte Carlo, regression sensitivities) or sobol (Saltelli design, first-order Sobol indices)");
  u->add_option("--speeds", a->speeds, "START:STOP:STEP in m/s (default: the scenario's speeds_mps)")
      ->check(makeSpeedRangeCheck());
  u->add_option("--threads", a->threads, "Worker threads per process (results identical for any number)")->check(makeThreadsCheck());
  addOutOption(*u, a->out, "the scenario's name");
  u->add_option("--set", a->overrides, "Override a scenario value, e.g. --set geometry.trail_m=0.1");
  addStrictOption(u, a->strict);
  u->callback([a]() { runUncertainty(*a); });
}

}  // namespace motostab::cli
