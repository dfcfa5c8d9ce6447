// study, uncertainty and diagnose: the calls of `motostab study`, `uncertainty` (one process) and
// `diagnose`, without their files; the reports they write as text.
#include <cmath>
#include <optional>

#include "apps/option_checks.h"
#include "diagnosis/diagnosis.h"
#include "output/diagnosis_output.h"
#include "output/study_output.h"
#include "output/uncertainty_output.h"
#include "python/bind_scenario.h"
#include "studies/study_findings.h"
#include "uncertainty/uncertainty_summary.h"

namespace motostab::python {

namespace {

using SpeedTuple = std::optional<std::array<double, 3>>;

// The speed grid of a study: the scenario's unless `speeds` is given (checked).
std::array<double, 3> getSpeedGrid(const ScenarioHandle& s, const SpeedTuple& speeds) {
  const auto& d = s.scenario->speeds;
  if (!speeds) return {d.start, d.stop, d.step};
  cli::checkSpeedRange((*speeds)[0], (*speeds)[1], (*speeds)[2], argumentLocation("speeds"));
  return *speeds;
}

// A Python progress callback (stage, done, total) callable from worker threads; its first exception
// is kept and raised after the call.
class Progress {
 public:
  explicit Progress(py::object callback) : callback_(std::move(callback)) {}
  std::function<void(const std::string&, int, int)> makeFunction() {
    if (callback_.is_none()) return {};
    return [this](const std::string& stage, int done, int total) {
      py::gil_scoped_acquire acquire;
      if (error_) return;
      try {
        callback_(stage, done, total);
      } catch (py::error_already_set& e) {
        error_ = std::make_unique<py::error_already_set>(std::move(e));
      }
    };
  }
  void raiseIfFailed() {
    if (error_) throw *error_;
  }

 private:
  py::object callback_;
  std::unique_ptr<py::error_already_set> error_;
};

// Each variant's sweep, named as the study's files name it (SCENARIO-VARIANT).
py::list convertVariants(std::vector<studies::StudyVariant>& variants, const std::string& name) {
  py::list out;
  for (auto& v : variants) out.append(py::make_tuple(v.name, convertSweep(std::move(v.sweep), name + "-" + v.name)));
  return out;
}

py::dict study(const ScenarioHandle& s, const SpeedTuple& speeds, const std::vector<std::string>& compare,
               double stiffnessScale, std::optional<double> dampingScale, const std::vector<double>& shapeSpeeds,
               int threads, double rollDeg) {
  studies::StudyOptions opt;
  const auto grid = getSpeedGrid(s, speeds);
  opt.sweep.start = grid[0], opt.sweep.stop = grid[1], opt.sweep.step = grid[2];
  opt.variants = compare;
  cli::checkNumber(stiffnessScale, cli::kScaleFactor, argumentLocation("stiffness_scale"));
  if (dampingScale) cli::checkNumber(*dampingScale, cli::kDampingFactor, argumentLocation("damping_scale"));
  opt.stiffnessScale = stiffnessScale;
  opt.dampingScale = dampingScale ? *dampingScale : std::sqrt(stiffnessScale);
  opt.shapeSpeeds = shapeSpeeds;
  opt.overrides = s.changes;
  cli::checkThreads(threads, argumentLocation("threads"));
  opt.threads = threads;
  cli::checkRoll(rollDeg, argumentLocation("roll_deg"));
  if (rollDeg != 0) opt.sweep.trim.roll = rollDeg * M_PI / 180;
  cli::checkStudyOptions(opt, argumentLocation("shape_speeds"), argumentLocation(speeds ? "speeds" : "speeds_mps"));
  struct Out {
    studies::StudyResult result;
    std::string report;
  };
  Out out = callQuietly([&] {
    studies::StudyResult result = studies::runStudy(*s.source, opt);
    std::string report = output::makeStudyReport(result, studies::calcStudyFindings(result), opt);
    return Out{std::move(result), std::move(report)};
  });
  py::list shapes;
  for (const auto& shape : out.result.weaveShapes) {
    py::list components;
    for (const auto& c : shape.components) components.append(py::make_tuple(c.name, c.amplitude, c.phaseDeg));
    shapes.append(py::make_tuple(shape.speed, shape.eigenvalue, components));
  }
  py::dict d;
  d["scenario"] = out.result.scenario;
  d["nominal"] = convertVariants(out.result.nominal, out.result.scenario);
  d["halved"] = convertVariants(out.result.halved, out.result.scenario);
  d["weave_shapes"] = shapes;
  d["report"] = out.report;
  return d;
}

py::dict uncertainty(const ScenarioHandle& s, long long samples, long long seed, const std::string& method,
                     const SpeedTuple& speeds, int threads) {
  uncertainty::UncertaintyOptions o;
  o.method = cli::parseSamplingMethod(method, argumentLocation("method"));
  if (samples < 1) throw io::InputError(argumentLocation("samples"), "must be at least 1");
  if (seed < 0) throw io::InputError(argumentLocation("seed"), "expected a non-negative integer");
  o.samples = static_cast<size_t>(samples);
  o.seed = static_cast<uint64_t>(seed);
  const auto grid = getSpeedGrid(s, speeds);
  o.start = grid[0], o.stop = grid[1], o.step = grid[2];
  cli::checkThreads(threads, argumentLocation("threads"));
  struct Out {
    uncertainty::UncertaintySetup setup;
    std::vector<uncertainty::TaskResult> tasks;
    nlohmann::json summary;
    std::string report;
  };
  Out out = callQuietly([&] {
    Out r;
    r.setup = uncertainty::prepareUncertainty(s.source, s.changes, o);
    std::vector<size_t> all(uncertainty::getTaskCount(r.setup));
    for (size_t t = 0; t < all.size(); ++t) all[t] = t;
    r.tasks = uncertainty::runTasks(r.setup, all, threads);
    const auto summary = uncertainty::summarizeUncertainty(r.setup, r.tasks);
    r.summary = output::makeUncertaintyJson(s.scenario->name, r.setup, summary);
    r.report = output::makeUncertaintyReport(s.scenario->name, r.setup, summary);
    return r;
  });
  const size_t n = out.tasks.size(), p = out.setup.params.size(), m = uncertainty::kUncertainModes.size();
  std::vector<double> parameters(n * p, NAN), crossings(n * m, NAN);
  std::vector<bool> ok(n);
  py::list paths, modes, reasons;
  for (const auto& param : out.setup.params) paths.append(param.path);
  for (const analysis::ModeLabel mode : uncertainty::kUncertainModes) modes.append(analysis::toString(mode));
  for (size_t t = 0; t < n; ++t) {
    const auto& task = out.tasks[t];
    for (size_t j = 0; j < task.parameters.size() && j < p; ++j) parameters[t * p + j] = task.parameters[j];
    for (size_t j = 0; j < m; ++j) crossings[t * m + j] = task.firstCrossing[j];
    ok[t] = task.ok;
    reasons.append(task.reason);
  }
  py::dict d;
  d["summary"] = toPython(out.summary);
  d["report"] = out.report;
  d["parameter_paths"] = paths;
  d["modes"] = modes;
  d["parameters"] = makeArray2(std::move(parameters), n, p);
  d["first_crossings"] = makeArray2(std::move(crossings), n, m);
  py::array_t<bool> succeeded(static_cast<py::ssize_t>(n));
  for (size_t t = 0; t < n; ++t) succeeded.mutable_at(t) = ok[t];
  d["succeeded"] = succeeded;
  d["reasons"] = reasons;
  return d;
}

py::dict diagnose(const ScenarioHandle& s, const std::string& measurements, const std::optional<std::vector<std::string>>& candidates,
                  int maxCauses, int folds, int threads, bool robustness, py::object progress) {
  diagnosis::DiagnosisOptions opt;
  if (candidates) opt.candidates = *candidates;
  cli::checkNumber(maxCauses, cli::kMaxCauses, argumentLocation("max_causes"));
  if (folds != 0) cli::checkNumber(folds, cli::kFolds, argumentLocation("folds"));
  cli::checkThreads(threads, argumentLocation("threads"));
  opt.maxCauses = maxCauses, opt.folds = folds, opt.threads = threads;
  opt.overrides = s.changes;
  opt.robustness = robustness;
  Progress report(std::move(progress));
  opt.progress = report.makeFunction();
  struct Out {
    nlohmann::json summary;
    std::string report;
    std::vector<std::string> causes, extended;
    std::vector<double> observed, sigma, before, after, speed, time;
    std::vector<std::string> component;
  };
  Out out = callQuietly([&] {
    const diagnosis::MeasuredData data = diagnosis::loadMeasuredData(measurements);
    diagnosis::DiagnosisResult r;
    try {
      r = diagnosis::runDiagnosis(s.source, data, opt);
    } catch (const io::InputError& e) {  // a candidate name or glob that matches none: the keyword's name
      if (e.getLocation().file != "--candidates") throw;
      throw io::InputError(argumentLocation("candidates"), "'" + e.getLocation().key + "' " + e.getReason());
    }
    Out o{output::makeDiagnosisJson(r), output::makeDiagnosisReport(r), {}, r.extendedOverrides,
          r.observed, r.sigma, r.predictedBefore, r.predictedAfter, r.observationSpeed, r.observationTime,
          r.observationComponent};
    for (const auto& c : r.causes) o.causes.push_back(c.fit.name);
    return o;
  });
  report.raiseIfFailed();
  py::dict d;
  d["summary"] = toPython(out.summary);
  d["report"] = out.report;
  d["causes"] = out.causes;
  d["extended_overrides"] = out.extended;
  d["observed"] = makeArray(std::move(out.observed));
  d["sigma"] = makeArray(std::move(out.sigma));
  d["predicted_before"] = makeArray(std::move(out.before));
  d["predicted_after"] = makeArray(std::move(out.after));
  d["speed_mps"] = makeArray(std::move(out.speed));
  d["time_s"] = makeArray(std::move(out.time));
  d["component"] = out.component;
  return d;
}

}  // namespace

void bindStudies(py::module_& m) {
  m.def("study", &study, py::arg("scenario"), py::arg("speeds"), py::arg("compare"), py::arg("stiffness_scale"),
        py::arg("damping_scale"), py::arg("shape_speeds"), py::arg("threads"), py::arg("roll_deg"));
  m.def("uncertainty", &uncertainty, py::arg("scenario"), py::arg("samples"), py::arg("seed"), py::arg("method"),
        py::arg("speeds"), py::arg("threads"));
  m.def("diagnose", &diagnose, py::arg("scenario"), py::arg("measurements"), py::arg("candidates"), py::arg("max_causes"),
        py::arg("folds"), py::arg("threads"), py::arg("robustness"), py::arg("progress"));
}

}  // namespace motostab::python
