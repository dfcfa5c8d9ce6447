// motostab diagnose: measured data -> what the model gets wrong, its cause, the extended model, the gain.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "apps/option_checks.h"
#include "diagnosis/diagnosis.h"
#include "output/diagnosis_output.h"
#include "output/scenario_output.h"
#include "io/csv.h"
#include "io/output_folder.h"
#include "io/result_error.h"
#include "scenario/scenario.h"
#include "scenario/scenario_source.h"

namespace motostab::cli {

using diagnosis::DiagnosisOptions;
using diagnosis::DiagnosisResult;
using diagnosis::MeasuredData;
using diagnosis::loadMeasuredData;
using diagnosis::runDiagnosis;
using io::InputError;
using io::OutputFolder;
using io::splitFields;
using output::makeDiagnosisReport;
using output::writeDiagnosisOutputs;
using scenario::Scenario;
using scenario::ScenarioSource;
using scenario::ParameterOverrides;

namespace {

// A one-line progress bar on stderr (only when stderr is a terminal).
void showProgress(const std::string& stage, int done, int total) {
  const int width = 30, filled = total > 0 ? width * done / total : 0;
  std::fprintf(stderr, "\r%-34s [%s%s] %d/%d", stage.c_str(), std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), done, total);
  std::fflush(stderr);
}

}  // namespace

void registerDiagnoseCommands(CLI::App& app) {
  struct Args {
    std::string scenario, measurements, out, candidates;
    int maxCauses = 3, folds = 0, threads = 1;
    bool noRobustness = false, strict = false;
    std::vector<std::string> overrides;
  };
  auto a = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("diagnose", "What the model gets wrong against measured data, its cause, the extended model and the gain");
  cmd->add_option("scenario", a->scenario, "Scenario YAML file")->required()->check(CLI::ExistingFile);
  cmd->add_option("measurements", a->measurements, "Measured-data YAML file (docs/measured-data-format.md)")->required();
  cmd->add_option("--candidates", a->candidates, "Comma list of candidate names or globs (default: all)");
  cmd->add_option("--max-causes", a->maxCauses, "Causes named at most (forward stepwise)")->check(CLI::Range(kMaxCauses.low, kMaxCauses.high));
  cmd->add_option("--folds", a->folds, "Cross-validation folds (default 5, or one per run)")->check(CLI::Range(kFolds.low, kFolds.high));
  cmd->add_option("--threads", a->threads, "Candidates fitted in parallel")->check(makeThreadsCheck());
  cmd->add_flag("--no-robustness", a->noRobustness,
                "Skip the reruns with each data source left out and speed ranges at mid speeds");
  addOutOption(*cmd, a->out, "the scenario's name");
  cmd->add_option("--set", a->overrides, "Override a scenario value, e.g. --set geometry.trail_m=0.1");
  addStrictOption(cmd, a->strict);
  cmd->callback([a]() {
    const ParameterOverrides changes(a->overrides);  // the --set text, parsed once
    const auto source = ScenarioSource::open(a->scenario);  // the file read once, for the command and every prediction
    Scenario scenario = source->load(changes);
    reportScenarioWarnings(scenario, a->strict);
    const MeasuredData data = loadMeasuredData(a->measurements);
    DiagnosisOptions opt;
    if (!a->candidates.empty()) opt.candidates = splitFields(a->candidates, ',');
    opt.maxCauses = a->maxCauses;
    opt.folds = a->folds;
    opt.threads = a->threads;
    opt.overrides = changes;
    opt.robustness = !a->noRobustness;
    const bool terminal = isatty(fileno(stderr));
    if (terminal) opt.progress = showProgress;
    const std::string out = getOutputFolder(a->out, scenario.name, "diagnose");
    OutputFolder folder(out);  // inputs read; from here an error or a kill leaves the old outputs whole
    const DiagnosisResult result = runDiagnosis(source, data, opt);
    const auto& fits = result.candidates;  // a failed fit has no score (diagnosis/model_fit.h, fitOrFail)
    if (!fits.empty() && std::none_of(fits.begin(), fits.end(), [](const auto& f) { return std::isfinite(f.bic); }))
      throw io::ResultError("every one of the " + std::to_string(fits.size()) + " candidates failed to fit (the first: " +
                            (fits.front().failed.empty() ? std::string("no reason") : fits.front().failed.front()) + ")");
    if (terminal) std::fprintf(stderr, "\n");
    writeDiagnosisOutputs(folder.getPath(), result);
    output::writeScenarioJson(folder.getPath(), scenario);
    folder.commit();
    std::cout << makeDiagnosisReport(result) << "\nWrote " << out
              << "/{diagnosis.json, report.md, residuals.csv, extended.yaml, plots}\n";
  });
}

}  // namespace motostab::cli
