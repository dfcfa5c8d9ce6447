#include "uncertainty/uncertainty_study.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "core/parallel.h"
#include "analysis/sweep.h"
#include "scenario/parameter_paths.h"
#include "io/csv.h"
#include "uncertainty/sampling.h"
#include "vehicle/vehicle_model.h"

namespace motostab::uncertainty {

using analysis::SweepOptions;
using analysis::SweepResult;
using analysis::makeSpeedGrid;
using analysis::runSweep;
using core::runParallel;
using io::InputError;
using io::formatNumber;
using scenario::ParameterOverrides;
using scenario::ParameterUncertainty;
using scenario::Scenario;
using scenario::ScenarioSource;
using scenario::getScalarParameter;
using vehicle::VehicleModel;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The scenario changes of parameter values x (full precision), after the user's.
ParameterOverrides makeOverrides(const UncertaintySetup& s, const std::vector<double>& x) {
  ParameterOverrides o = s.overrides;
  for (size_t j = 0; j < x.size(); ++j) o.set(s.params[j].path, x[j]);
  return o;
}

// Why drawn values x were refused, in the user's terms: the uncertainty entry whose draw the loader
// refused (its line, sigma and the value drawn), and where and why; else the error as it is.
std::string describeRefusedDraw(const UncertaintySetup& s, const std::vector<double>& x, const InputError& e) {
  const std::string& key = e.getLocation().key;
  for (size_t j = 0; j < s.params.size(); ++j) {
    const std::string& p = s.params[j].path;
    if (!(key == p || key.rfind(p + ".", 0) == 0 || key.rfind(p + "[", 0) == 0)) continue;
    std::string reason = e.getReason();
    reason = reason.substr(0, reason.find(" (value from --set " + p + "="));  // the draw is no --set of the user's
    return s.params[j].where.describe() + ": a value drawn with sigma " + io::formatNumber(s.params[j].sigma, 6) + ", " +
           io::formatNumber(x[j], 6) + ", is refused at " + key + ": " + reason;
  }
  return e.what();
}

// A model of the scenario with values x; nullptr (and `why`) if the loader or the model rejects them.
std::unique_ptr<VehicleModel> buildModel(const UncertaintySetup& s, const std::vector<double>& x, std::string& why) {
  try {
    return std::make_unique<VehicleModel>(s.source->load(makeOverrides(s, x)));
  } catch (const InputError& e) {
    why = describeRefusedDraw(s, x, e);
    return nullptr;
  }
}

// Draw `stream` with unphysical draws replaced; the model of the accepted draw, or nullptr when
// maxAttempts draws were all rejected (`why` then holds the last reason).
std::unique_ptr<VehicleModel> drawPhysical(const UncertaintySetup& s, uint64_t stream, std::vector<double>& x,
                                           int& redraws, std::string& why) {
  for (int a = 0; a < s.options.maxAttempts; ++a) {
    x = drawParameters(s.options.seed, stream, static_cast<uint64_t>(a), s.params, s.nominal);
    if (auto m = buildModel(s, x, why)) return m;
    ++redraws;
  }
  why = "unphysical in all " + std::to_string(s.options.maxAttempts) + " draws; last: " + why;
  return nullptr;
}

// The values of task `task` and its model (nullptr with `why` if none is physical).
std::unique_ptr<VehicleModel> makeTaskModel(const UncertaintySetup& s, const UncertaintyTask& task, TaskResult& r,
                                            std::string& why) {
  switch (task.kind) {
    case TaskKind::Nominal:
    case TaskKind::Plus:
    case TaskKind::Minus: {
      r.parameters = s.nominal;
      if (task.kind != TaskKind::Nominal) {
        const double h = s.options.derivativeStep * s.params[task.param].sigma;
        r.parameters[task.param] += task.kind == TaskKind::Plus ? h : -h;
      }
      return buildModel(s, r.parameters, why);
    }
    case TaskKind::Sample:
      return drawPhysical(s, task.row, r.parameters, r.redraws, why);
    case TaskKind::SobolA:
      return drawPhysical(s, 2 * task.row, r.parameters, r.redraws, why);
    case TaskKind::SobolB:
      return drawPhysical(s, 2 * task.row + 1, r.parameters, r.redraws, why);
    case TaskKind::SobolAB: {
      std::vector<double> b;
      int ignored = 0;
      if (!drawPhysical(s, 2 * task.row, r.parameters, ignored, why) ||
          !drawPhysical(s, 2 * task.row + 1, b, ignored, why))
        return nullptr;
      r.parameters[task.param] = b[task.param];
      auto m = buildModel(s, r.parameters, why);
      if (!m) why = "unphysical combination of rows A and B: " + why;
      return m;
    }
  }
  return nullptr;
}

// First crossings, the crossing list and the fan modes' values from a sweep.
void extractSweep(const SweepResult& sweep, TaskResult& r) {
  r.firstCrossing.fill(kNaN);
  for (const auto& c : sweep.criticalSpeeds) {
    for (size_t m = 0; m < kUncertainModes.size(); ++m)
      if (c.mode == kUncertainModes[m] && !(c.speed >= r.firstCrossing[m])) r.firstCrossing[m] = c.speed;
    r.crossings += (r.crossings.empty() ? "" : ";") + std::string(toString(c.mode)) + "@" + formatNumber(c.speed) +
                   (c.stabilising ? "-" : "+");
  }
  const size_t n = sweep.speeds.size();
  r.modeValues.assign(2 * kFanModes.size() * n, kNaN);
  for (size_t m = 0; m < kFanModes.size(); ++m)
    for (const auto& b : sweep.branches) {
      for (size_t k = 0; k < n; ++k) {
        if (b.labels[k] != kFanModes[m]) continue;
        const auto l = b.eigenvalue[k];
        double& re = r.modeValues[2 * (m * n + k)];
        if (l.imag() < 0 || l.real() <= re) continue;  // keep the least stable member with imag >= 0
        re = l.real();
        r.modeValues[2 * (m * n + k) + 1] = l.imag() / (2 * M_PI);
      }
    }
}

}  // namespace

UncertaintySetup prepareUncertainty(const std::string& file, const ParameterOverrides& overrides,
                                    const UncertaintyOptions& options) {
  return prepareUncertainty(ScenarioSource::open(file), overrides, options);
}

UncertaintySetup prepareUncertainty(std::shared_ptr<const ScenarioSource> source, const ParameterOverrides& overrides,
                                    const UncertaintyOptions& options) {
  UncertaintySetup s;
  const std::string& file = source->getFile();
  s.scenarioFile = file;
  s.source = std::move(source);
  s.overrides = overrides;
  s.options = options;
  const Scenario scenario = s.source->load(overrides);
  const VehicleModel model(scenario);  // the nominal scenario must build (plugins checked)
  if (scenario.uncertainty.empty())
    throw InputError({file, 0, 0, "uncertainty"}, "the scenario has no uncertainty section (or it is empty)");
  const YAML::Node tree = s.source->makeTree(overrides);
  s.params = scenario.uncertainty;
  for (const auto& p : s.params) {
    s.nominal.push_back(getScalarParameter(tree, p.path));
    if (p.distribution == ParameterUncertainty::Distribution::Lognormal && !(s.nominal.back() > 0))
      throw InputError(p.where, "a lognormal parameter needs a positive nominal value");
  }
  return s;
}

size_t getTaskCount(const UncertaintySetup& s) {
  const size_t p = s.params.size(), n = s.options.samples;
  return 1 + 2 * p + (s.options.method == SamplingMethod::Sobol ? n * (p + 2) : n);
}

UncertaintyTask getTask(const UncertaintySetup& s, size_t t) {
  const size_t p = s.params.size();
  if (t == 0) return {TaskKind::Nominal, 0, -1};
  if (t <= 2 * p) return {(t - 1) % 2 == 0 ? TaskKind::Plus : TaskKind::Minus, 0, static_cast<int>((t - 1) / 2)};
  const size_t i = t - 1 - 2 * p;
  if (s.options.method == SamplingMethod::MonteCarlo) return {TaskKind::Sample, i, -1};
  const size_t row = i / (p + 2), k = i % (p + 2);
  if (k == 0) return {TaskKind::SobolA, row, -1};
  if (k == 1) return {TaskKind::SobolB, row, -1};
  return {TaskKind::SobolAB, row, static_cast<int>(k - 2)};
}

size_t getModeValueCount(const UncertaintySetup& s) {
  return 2 * kFanModes.size() * makeSpeedGrid(s.options.start, s.options.stop, s.options.step).size();
}

TaskResult runTask(const UncertaintySetup& s, size_t t) {
  TaskResult r;
  r.firstCrossing.fill(kNaN);
  std::string why;
  try {
    const auto model = makeTaskModel(s, getTask(s, t), r, why);
    if (!model) {
      r.reason = why;
      return r;
    }
    SweepOptions opt;
    opt.start = s.options.start, opt.stop = s.options.stop, opt.step = s.options.step;
    opt.threads = 1;  // serial sweeps are reproducible to the bit
    extractSweep(runSweep(*model, opt), r);
    r.ok = true;
  } catch (const std::exception& e) {
    r.reason = e.what();
  }
  return r;
}

std::vector<TaskResult> runTasks(const UncertaintySetup& s, const std::vector<size_t>& indices, int threads,
                                 const std::function<void(size_t)>& progress) {
  std::vector<TaskResult> out(indices.size());
  std::atomic<size_t> done{0};
  runParallel(indices.size(), threads, [&](size_t i) {
    out[i] = runTask(s, indices[i]);
    const size_t d = ++done;
    if (progress) progress(d);
  });
  return out;
}

}  // namespace motostab::uncertainty
