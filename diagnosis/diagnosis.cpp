#include "diagnosis/diagnosis.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "diagnosis/controller_groups.h"
#include "diagnosis/findings.h"
#include "diagnosis/fit_problem.h"
#include "diagnosis/model_fit.h"
#include "diagnosis/profile_likelihood.h"
#include "diagnosis/residual_summary.h"
#include "diagnosis/robustness.h"
#include "diagnosis/steer_rate_amplitude.h"
#include "diagnosis/stepwise_search.h"
#include "io/yaml_map.h"
#include "plugins/builtin.h"
#include "scenario/scenario.h"
#include "scenario/scenario_source.h"

namespace motostab::diagnosis {

using io::InputError;
using io::applyOverride;
using io::loadYamlFile;
using scenario::ParameterOverrides;
using scenario::ScenarioSource;

namespace {

std::vector<const Candidate*> probeCandidates(const ScenarioSource& source, const DiagnosisOptions& opt,
                                              const std::vector<Candidate>& all, std::vector<std::string>& unavailable) {
  std::vector<const Candidate*> out;
  for (const auto& c : all) {
    ParameterOverrides ov = opt.overrides;
    const ModelSpec m = makeModel({}, &c);
    ov.append(m.makeOverrides(m.getStart()));
    try {
      scenario::Scenario s = source.load(ov);
      plugins::makeBuiltinRegistry().readScenarioSections(s);  // the extension sections it adds, read as a build would
      out.push_back(&c);
    } catch (const InputError& e) {
      unavailable.push_back(c.name + ": " + e.getReason() + " (" + e.getLocation().key + ")");
    }
  }
  return out;
}

std::vector<std::pair<std::string, double>> getUncertainty(const scenario::Scenario& s) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& u : s.uncertainty) out.push_back({u.path, u.sigma});
  return out;
}

// The candidates of the scenario the options select; parameters the data set per controller setting
// are not one value and go to `unavailable`.
std::vector<Candidate> selectCandidates(const ScenarioSource& source, const MeasuredData& data, const Predictor& nominal,
                                        const DiagnosisOptions& opt, std::vector<std::string>& unavailable) {
  const scenario::Scenario s = source.load(opt.overrides);
  const auto sections = plugins::listSectionFields(plugins::makeScenarioRegistry(s));
  std::vector<Candidate> listed = listCandidates(source.makeTree(opt.overrides), getUncertainty(s), &unavailable,
                                                 findSteerRateAmplitude(data, nominal), sections);
  for (const std::string& path : getControllerPaths(data))
    for (auto it = listed.begin(); it != listed.end();)
      if (it->name == "parameter:" + path) {
        unavailable.push_back(it->name + ": the measured data set it per controller setting");
        it = listed.erase(it);
      } else {
        ++it;
      }
  const std::vector<std::string> findingPaths = getFindingPaths(data.findings);
  const auto setsFindingPath = [&](const Candidate& c) {
    std::vector<std::string> paths;
    for (const auto& item : c.fixedOverrides.getItems()) paths.push_back(item.path);
    for (const auto& p : c.parameters) paths.push_back(p.path);
    for (const auto& p : paths)
      if (std::find(findingPaths.begin(), findingPaths.end(), p) != findingPaths.end()) return p;
    return std::string();
  };
  for (auto it = listed.begin(); it != listed.end();)
    if (const std::string p = setsFindingPath(*it); !p.empty()) {
      unavailable.push_back(it->name + ": it sets " + p + ", which a finding's variant or change sets");
      it = listed.erase(it);
    } else {
      ++it;
    }
  try {
    return filterCandidates(listed, opt.candidates);
  } catch (const InputError& e) {  // say why a known candidate is missing
    std::string why;
    for (const auto& u : unavailable) why += "; " + u;
    throw e.withReasonAdded(why);
  }
}

// The base and extended models refitted, cross-validated with the extended model's noise (one metric
// for the gain), the causes' intervals profiled.
void fitFinalModels(const FitProblem& problem, const SearchState& state, DiagnosisResult& result, int threads) {
  const ModelSpec none, extended = makeModel(state.causes, nullptr);
  result.extended = fitFull(problem, extended, state.xCauses, "extended", &state.noise);
  result.baseline = fitFull(problem, none, Eigen::VectorXd(), "baseline", &result.extended.noise);
  result.baseline.rms = calcRms(problem, none, result.baseline.x, result.extended.noise);  // one metric
  result.extended.rms = calcRms(problem, extended, result.extended.x, result.extended.noise);
  crossValidate(problem, none, result.extended.noise, result.baseline);
  crossValidate(problem, extended, result.extended.noise, result.extended, threads);
  if (!result.extended.foldFailures.empty())  // the gain compares the two over the same folds
    result.baseline.cvRms = calcCvRmsOver(problem, result.baseline, result.extended.foldFailed);
  calcProfiles(withNoise(problem, result.extended.noise), extended, result.extended);
  for (size_t c = 0, i = 0; c < result.causes.size(); ++c)
    for (auto& e : result.causes[c].fit.parameters) {
      const std::string name = e.name;
      e = result.extended.allParameters[i++];
      e.name = name;  // a pair's qualified name
    }
  for (const auto& o : extended.makeOverrides(result.extended.x).format()) result.extendedOverrides.push_back(o);
}

// Exact predictions before and after, per component summaries and per observation tables, all with the
// extended model's noise.
void tabulate(const FitProblem& fitted, const ModelSpec& extended, DiagnosisResult& result) {
  const FitProblem problem = withNoise(fitted, result.extended.noise);
  result.before = problem.predict(ModelSpec(), Eigen::VectorXd(), true);
  result.after = problem.predict(extended, result.extended.x, true);
  result.residualsBefore = summariseResiduals(problem, result.before);
  result.residualsAfter = summariseResiduals(problem, result.after);
  for (size_t k = 0; k < result.residualsAfter.size(); ++k) {
    result.residualsAfter[k].vafBefore = result.residualsBefore[k].vafAfter;
    result.residualsBefore[k].vafBefore = result.residualsBefore[k].vafAfter;
  }
  for (size_t c = 0; c < problem.components.size(); ++c)
    result.noise.push_back({problem.components[c], problem.componentSigma[c], !problem.componentKnown[c],
                            problem.componentAr[c].phi, problem.componentSigma[c] * problem.componentAr[c].calcMarginalFactor()});
  result.whitenedBefore = calcWhitenedResiduals(problem, result.before);
  result.whitenedAfter = calcWhitenedResiduals(problem, result.after);
  for (const auto& o : problem.observations) {
    result.sigma.push_back(problem.getMarginalSigma(o));
    result.observed.push_back(o.value);
    result.observationComponent.push_back(problem.components[o.component]);
    result.predictedBefore.push_back(problem.getPredicted(result.before, o));
    result.predictedAfter.push_back(problem.getPredicted(result.after, o));
    result.observationSpeed.push_back(o.speed);
    result.observationTime.push_back(o.run >= 0 ? problem.getData().responses[o.run].time[o.sample] : std::nan(""));
    result.observationRow.push_back(o.row);
    result.observationPart.push_back(o.part);
    result.observationRun.push_back(o.run);
    result.observationSignal.push_back(o.signal);
  }
  result.numObservations = static_cast<int>(problem.observations.size());
  result.numFolds = problem.numFolds;
}

}  // namespace

YAML::Node makeScenarioTree(const std::string& scenarioFile, const std::vector<std::string>& overrides) {
  YAML::Node root = loadYamlFile(scenarioFile).getNode();
  for (const auto& o : overrides) applyOverride(root, o);
  return root;
}

bool DiagnosisResult::isFragile() const {
  for (const auto& r : robustness)
    if (r.isFragile()) return true;
  return false;
}

DiagnosisResult runDiagnosis(const std::string& scenarioFile, const MeasuredData& data, const DiagnosisOptions& options) {
  return runDiagnosis(ScenarioSource::open(scenarioFile), data, options);  // read once for every prediction
}

DiagnosisResult runDiagnosis(std::shared_ptr<const ScenarioSource> source, const MeasuredData& data,
                             const DiagnosisOptions& options) {
  DiagnosisOptions opt = options;  // every predictor below (reruns too) shares one store of chains
  if (!opt.reuseLinearModels) opt.sweepCache = nullptr;
  else if (!opt.sweepCache) opt.sweepCache = std::make_shared<SweepCache>();
  if (opt.progress) opt.progress("reference sweep", 0, 1);
  checkFindingChanges(*source, opt.overrides, data.findings);
  const Predictor predictor(source, opt.overrides, data, opt.sweepCache);
  const FitProblem problem(predictor, data, opt.folds);
  std::vector<std::string> unavailable;
  const std::vector<Candidate> all = selectCandidates(*source, data, predictor, opt, unavailable);
  const std::vector<const Candidate*> pool = probeCandidates(*source, opt, all, unavailable);
  SearchState state;
  state.pool = pool;
  DiagnosisResult result;
  runStepwiseSearch(problem, state, opt, result, true);
  result.scenarioFile = source->getFile();
  result.data = &data;
  result.unavailable = unavailable;
  result.extendedOverrides = opt.overrides.format();
  fitFinalModels(problem, state, result, opt.threads);
  tabulate(problem, makeModel(state.causes, nullptr), result);
  if (opt.robustness) result.robustness = runRobustness(source, data, opt, pool, result.causes);
  return result;
}

}  // namespace motostab::diagnosis
