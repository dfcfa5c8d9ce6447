#include "diagnosis/robustness.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "diagnosis/fit_problem.h"
#include "diagnosis/stepwise_search.h"

namespace motostab::diagnosis {

using scenario::ScenarioSource;

std::vector<DataVariant> makeRobustnessVariants(const MeasuredData& data) {
  std::vector<DataVariant> out;
  for (const std::string& file : data.eigenvalueFiles) {
    DataVariant v{"eigenvalues: " + std::filesystem::path(file).filename().string(), data};
    v.data.eigenvalues.clear();
    for (const auto& e : data.eigenvalues)
      if (e.where.file != file) v.data.eigenvalues.push_back(e);
    auto& files = v.data.eigenvalueFiles;
    files.erase(std::remove(files.begin(), files.end(), file), files.end());
    if (!v.data.eigenvalues.empty() || !v.data.responses.empty() || !v.data.findings.empty()) out.push_back(std::move(v));
  }
  for (size_t r = 0; r < data.responses.size(); ++r) {
    DataVariant v{"response run " + std::to_string(r + 1) + ": " + std::filesystem::path(data.responses[r].file).filename().string(), data};
    v.data.responses.erase(v.data.responses.begin() + static_cast<long>(r));
    if (!v.data.eigenvalues.empty() || !v.data.responses.empty() || !v.data.findings.empty()) out.push_back(std::move(v));
  }
  DataVariant mid{"speed ranges -> mid speeds", data};
  bool any = false;
  for (auto& e : mid.data.eigenvalues)
    if (e.hasRange) e.speed = 0.5 * (e.speedMin + e.speedMax), e.speedMin = e.speedMax = e.speed, e.hasRange = false, any = true;
  if (any) out.push_back(std::move(mid));
  return out;
}

}  // namespace motostab::diagnosis

namespace motostab::diagnosis {
namespace {

constexpr double kZ95 = 1.959963984540054;

// The full data's 95 % interval of an estimate: its profile interval, else estimate +/- 1.96 stderr.
std::pair<double, double> getInterval(const ParameterEstimate& e) {
  if (e.hasProfile) return {e.profileLow, e.profileHigh};
  return {e.value - kZ95 * e.stderr_, e.value + kZ95 * e.stderr_};
}

bool valuesConsistent(const FitSummary& full, const FitSummary& variant) {
  for (const auto& a : full.parameters)
    for (const auto& b : variant.parameters) {
      if (a.name != b.name) continue;
      const auto [lo, hi] = getInterval(a);
      const auto [vlo, vhi] = getInterval(b);
      if (vhi < lo || vlo > hi) return false;
    }
  return true;
}

}  // namespace

RobustnessVerdict judgeRobustness(const std::vector<Cause>& full, const RobustnessRun& run) {
  if (!run.error.empty()) return RobustnessVerdict::Failed;
  if (full.empty()) return run.causes.empty() ? RobustnessVerdict::Same : RobustnessVerdict::OtherCause;
  if (run.causes.empty()) return RobustnessVerdict::LostPower;
  const Cause& first = full[0];
  if (run.causes[0] == first.fit.name)
    return valuesConsistent(first.fit, run.fits.at(0)) ? RobustnessVerdict::Same : RobustnessVerdict::ValueDiffers;
  for (const auto& i : first.indistinguishable)
    if (i.name == run.causes[0]) return RobustnessVerdict::Indistinguishable;
  return RobustnessVerdict::OtherCause;
}

const char* getVerdictName(RobustnessVerdict v) {
  switch (v) {
    case RobustnessVerdict::Same: return "same";
    case RobustnessVerdict::LostPower: return "lost power";
    case RobustnessVerdict::Indistinguishable: return "indistinguishable";
    case RobustnessVerdict::OtherCause: return "other cause";
    case RobustnessVerdict::ValueDiffers: return "value differs";
    case RobustnessVerdict::Failed: return "failed";
  }
  return "";
}

std::vector<RobustnessRun> runRobustness(const std::shared_ptr<const ScenarioSource>& source, const MeasuredData& data,
                                         const DiagnosisOptions& opt, const std::vector<const Candidate*>& pool,
                                         const std::vector<Cause>& causes) {
  std::vector<RobustnessRun> out;
  const std::vector<DataVariant> variants = makeRobustnessVariants(data);
  DiagnosisOptions quiet = opt;
  quiet.progress = nullptr;
  // As many steps as named on all the data (one when none was): a rerun asks whether those causes
  // survive, not what a further step would add.
  quiet.maxCauses = std::max(1, static_cast<int>(causes.size()));
  for (size_t k = 0; k < variants.size(); ++k) {
    if (opt.progress) opt.progress("robustness reruns", static_cast<int>(k), static_cast<int>(variants.size()));
    RobustnessRun run;
    run.leftOut = variants[k].leftOut;
    try {
      const Predictor predictor(source, opt.overrides, variants[k].data, opt.sweepCache);
      const FitProblem problem(predictor, variants[k].data, opt.folds);
      SearchState state;
      state.pool = pool;
      DiagnosisResult r;
      runStepwiseSearch(problem, state, quiet, r, false);
      for (const auto& c : r.causes) run.causes.push_back(c.fit.name), run.fits.push_back(c.fit);
    } catch (const std::exception& e) {
      run.error = e.what();
    }
    run.verdict = judgeRobustness(causes, run);
    out.push_back(run);
  }
  if (opt.progress) opt.progress("robustness reruns", static_cast<int>(variants.size()), static_cast<int>(variants.size()));
  return out;
}

}  // namespace motostab::diagnosis
