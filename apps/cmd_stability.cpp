// motostab sweep | linearize | study: scenario -> model -> trim -> linearise -> modes -> outputs.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "apps/option_checks.h"
#include "analysis/turn_map.h"
#include "io/input_error.h"
#include "io/output_folder.h"
#include "io/result_error.h"
#include "output/linear_models_mat.h"
#include "output/map_output.h"
#include "output/scenario_output.h"
#include "diagnosis/measured_data.h"
#include "io/csv.h"
#include "output/study_output.h"
#include "output/study_verdicts_output.h"
#include "output/sweep_output.h"
#include "scenario/scenario_source.h"

namespace motostab::cli {

using analysis::LinearModel;
using analysis::SweepOptions;
using analysis::SweepResult;
using analysis::TrimOptions;
using analysis::TrimResult;
using analysis::TurnMapOptions;
using analysis::TurnMapResult;
using analysis::calcModeContents;
using analysis::calcTrim;
using analysis::linearize;
using analysis::runSweep;
using analysis::runTurnMap;
using io::InputError;
using io::OutputFolder;
using io::ResultError;
using output::formatSweepTable;
using output::formatTurnMapTable;
using output::makeStudyReport;
using output::writeLinearModel;
using output::writeLinearModelsMat;
using output::writeScenarioJson;
using output::writeStudyOutputs;
using output::writeSweepOutputs;
using output::writeTurnMapOutputs;
using scenario::Scenario;
using scenario::ScenarioSource;
using scenario::ParameterOverrides;
using studies::StudyOptions;
using studies::StudyResult;
using studies::runStudy;
using vehicle::VehicleModel;


namespace {

// After the outputs are written: exit 3 (io::ResultError) when points of the grid did not trim, so that
// a script sees the map or sweep is partial (docs/commands.md, exit codes).
void reportPartial(size_t failed, size_t total, const std::string& what, const std::string& out) {
  if (failed == 0) return;
  throw ResultError(std::to_string(failed) + " of " + std::to_string(total) + " " + what +
                    " did not trim; the others are in " + out + " (the failed ones listed in its summary)");
}

// Where the speeds of a turn come from: --speeds, or the scenario's speeds_mps.
io::InputLocation getSpeedsLocation(bool fromOption) {
  return {"command line", 0, 0, fromOption ? "--speeds" : "speeds_mps (the scenario's; override with --speeds)"};
}

// motostab sweep: eigenvalues over speed, or a speed x roll map of steady turns.
void registerSweepCommand(CLI::App& app) {
  struct SweepArgs {
    std::string scenario, speeds, out, roll;
    std::vector<std::string> overrides;
    int threads = 1;
    bool strict = false;
  };
  auto sweepArgs = std::make_shared<SweepArgs>();
  CLI::App* sweep = app.add_subcommand("sweep", "Linear stability sweep over speed: eigenvalues, modes, critical speeds, plots");
  sweep->add_option("scenario", sweepArgs->scenario, "Scenario YAML file")->required()->check(CLI::ExistingFile);
  sweep->add_option("--speeds", sweepArgs->speeds, "START:STOP:STEP in m/s (default: the scenario's speeds_mps)")
      ->check(makeSpeedRangeCheck());
  addOutOption(*sweep, sweepArgs->out, "the scenario's name");
  sweep->add_option("--set", sweepArgs->overrides, "Override a scenario value, e.g. --set geometry.trail_m=0.1");
  sweep->add_option("--roll-deg", sweepArgs->roll,
                    "Steady turns at this roll angle (deg, > 0 right), or a speed x roll map over A:B:STEP")
      ->check(makeRollAnglesCheck());
  sweep->add_option("--threads", sweepArgs->threads,
                    "Worker threads (2: about 1.8x faster; results then agree with one thread to the trim "
                    "tolerance, not to the bit)")
      ->check(makeThreadsCheck());
  addStrictOption(sweep, sweepArgs->strict);
  sweep->callback([sweepArgs]() {
    const Scenario scenario = loadScenarioReporting(sweepArgs->scenario, sweepArgs->overrides, sweepArgs->strict);
    const std::string out = getOutputFolder(sweepArgs->out, scenario.name, "sweep");
    OutputFolder folder(out);  // first: a kill from here on leaves the old outputs whole
    const VehicleModel model(scenario);
    SweepOptions opt;
    opt.start = scenario.speeds.start;
    opt.stop = scenario.speeds.stop;
    opt.step = scenario.speeds.step;
    if (!sweepArgs->speeds.empty()) parseSpeedRange(sweepArgs->speeds, opt.start, opt.stop, opt.step);
    opt.threads = sweepArgs->threads;
    opt.keepFailedSpeeds = true;
    opt.linearize.computeB = true;  // for linear_models.mat (about 3 % of the sweep's time, docs/commands.md)
    writeScenarioJson(folder.getPath(), scenario);
    if (!sweepArgs->roll.empty()) {
      checkTurnSpeeds(opt.start, getSpeedsLocation(!sweepArgs->speeds.empty()));
      const std::vector<double> rolls = parseRollAngles(sweepArgs->roll);
      if (rolls.size() > 1) {
        checkMapPoints(opt.start, opt.stop, opt.step, rolls.size(), getSpeedsLocation(!sweepArgs->speeds.empty()));
        TurnMapOptions mo;
        mo.sweep = opt;
        mo.rolls = rolls;
        const TurnMapResult map = runTurnMap(model, mo);
        writeTurnMapOutputs(folder.getPath(), scenario.name, map);
        std::vector<LinearModel> models;  // every speed of every roll, roll-major
        for (const SweepResult& s : map.sweeps) models.insert(models.end(), s.models.begin(), s.models.end());
        writeLinearModelsMat(folder.getPath() / "linear_models.mat", models);
        folder.commit();
        const size_t grid = analysis::makeSpeedGrid(opt.start, opt.stop, opt.step).size();
        std::cout << "Scenario " << scenario.name << ": " << rolls.size() << " roll angles x " << grid << " speeds\n"
                  << formatTurnMapTable(map) << "Wrote " << out
                  << "/{map.csv, map_summary.json, linear_models.mat, scenario.json, damping_map, root_loci, "
                     "real_part_vs_speed (.gp/.png/.svg), roll_*/}\n";
        reportPartial(map.countFailedPoints() + map.failedRolls.size() * grid, rolls.size() * grid, "points of the map", out);
        return;
      }
      opt.trim.roll = rolls.front();
    }
    const SweepResult result = runSweep(model, opt);
    writeSweepOutputs(folder.getPath(), scenario.name, result);
    writeLinearModelsMat(folder.getPath() / "linear_models.mat", result.models);
    folder.commit();
    std::cout << "Scenario " << scenario.name << ": " << result.speeds.size() << " speeds\n"
              << formatSweepTable(result) << "Wrote " << out << "/{eigenvalues.csv, summary.json, linear_models.mat, "
              << "scenario.json, root_locus.{png,svg,gp}, real_part_vs_speed.{png,svg,gp}}\n";
    reportPartial(result.failures.size(), result.failures.size() + result.speeds.size(), "speeds", out);
  });
}

// motostab linearize: A, B and the eigenvectors at one speed.
void registerLinearizeCommand(CLI::App& app) {
  struct LinArgs {
    std::string scenario, out;
    double speed = 0, rollDeg = NAN;
    std::vector<std::string> overrides;
    bool strict = false;
  };
  auto linArgs = std::make_shared<LinArgs>();
  CLI::App* lin = app.add_subcommand("linearize", "Trim at one speed and write A, B and the eigenvectors");
  lin->add_option("scenario", linArgs->scenario, "Scenario YAML file")->required()->check(CLI::ExistingFile);
  lin->add_option("--speed", linArgs->speed, "Forward speed, m/s")->required()->check(makeNumberCheck(kSpeedMps));
  addOutOption(*lin, linArgs->out, "the scenario's name");
  lin->add_option("--set", linArgs->overrides, "Override a scenario value");
  lin->add_option("--roll-deg", linArgs->rollDeg,
                  "Linearise about the steady turn at this roll angle (deg, > 0 right); --speed is then the rear "
                  "contact point's speed along its path")
      ->check(makeRollCheck());
  addStrictOption(lin, linArgs->strict);
  lin->callback([linArgs]() {
    const Scenario scenario = loadScenarioReporting(linArgs->scenario, linArgs->overrides, linArgs->strict);
    const std::string out = getOutputFolder(linArgs->out, scenario.name, "linearize");
    OutputFolder folder(out);
    const VehicleModel model(scenario);
    TrimOptions trimOptions;
    if (!std::isnan(linArgs->rollDeg)) {
      checkTurnSpeeds(linArgs->speed, {"command line", 0, 0, "--speed"});
      trimOptions.roll = linArgs->rollDeg * M_PI / 180;
    }
    const TrimResult trim = calcTrim(model, linArgs->speed, trimOptions);
    const LinearModel lm = linearize(model, trim);  // each eigenvalue labelled from its content at this speed
    writeLinearModel(folder.getPath(), lm, calcModeContents(lm));
    writeLinearModelsMat(folder.getPath() / "linear_models.mat", {lm});
    writeScenarioJson(folder.getPath(), scenario);
    folder.commit();
    std::cout << "Trim at " << linArgs->speed << " m/s: residual " << trim.residualNorm << " after " << trim.iterations
              << " iterations; " << lm.states.size() << " states. Wrote " << out
              << "/{A.csv, B.csv, eigenvalues.csv, eigenvectors.csv, linear_model.json, linear_models.mat, scenario.json}\n";
  });
}

// The findings file of `motostab study`: --findings, else for a scenario file DIR/NAME.yaml the bundled
// DIR/../examples/seed-findings/NAME.yaml when it exists (the seed's supersport and enduro); empty: none.
std::string findFindingsFile(const std::string& given, bool none, const std::string& scenarioFile) {
  if (none) return "";
  if (!given.empty()) return given;
  const std::filesystem::path p(scenarioFile);
  const std::filesystem::path bundled = p.parent_path() / ".." / "examples" / "seed-findings" / p.filename();
  std::error_code ec;
  return std::filesystem::is_regular_file(bundled, ec) ? bundled.lexically_normal().string() : "";
}

// motostab study: the seed paper's swingarm study.
void registerStudyCommand(CLI::App& app) {
  struct StudyArgs {
    std::string scenario, speeds, out, findings, candidates;
    std::vector<std::string> overrides;
    std::vector<std::string> variants{"rigid", "bending", "torsion", "twist"};
    bool noFindings = false;
    double stiffnessScale = 0.5, dampingScale = 1.0 / std::sqrt(2.0);
    std::vector<double> shapeSpeeds{10.0, 18.5, 30.0};
    int threads = 2;
    double rollDeg = 0;
    bool strict = false;
  };
  auto st = std::make_shared<StudyArgs>();
  CLI::App* study = app.add_subcommand("study", "Swingarm study of seed sec. 4: rigid/bending/torsion/twist sweeps, Figs. 9-12, report");
  study->add_option("scenario", st->scenario, "Motorcycle scenario with a swingarm section")->required()->check(CLI::ExistingFile);
  study->add_option("--speeds", st->speeds, "START:STOP:STEP in m/s (default: the scenario's speeds_mps)")
      ->check(makeSpeedRangeCheck());
  addOutOption(*study, st->out, "the scenario's name");
  study->add_option("--set", st->overrides, "Override a scenario value for every variant");
  study->add_option("--compare", st->variants, "Compliance variants to compare")->delimiter(',');
  study->add_option("--stiffness-scale", st->stiffnessScale, "Stiffness factor of the second set (seed Fig. 11: 0.5)")
      ->check(makeNumberCheck(kScaleFactor));
  CLI::Option* dampingOption =
      study->add_option("--damping-scale", st->dampingScale,
                        "Damping factor of the second set (default: the square root of the stiffness factor, which keeps "
                        "each damping ratio; seed: 1/sqrt(2))")
          ->check(makeNumberCheck(kDampingFactor));
  study->add_option("--shape-speeds", st->shapeSpeeds, "Speeds of the weave mode-shape compass plots, m/s")
      ->delimiter(',')
      ->check(makeNumberCheck(kSpeedMps));
  study->add_option("--threads", st->threads, "Variants swept in parallel")->check(makeThreadsCheck());
  study->add_option("--roll-deg", st->rollDeg, "Compare the variants about steady turns at this roll angle (deg)")
      ->check(makeRollCheck());
  study->add_option("--findings", st->findings,
                    "Findings to set against the motorcycle and diagnose (docs/measured-data-format.md; default for "
                    "scenarios/NAME.yaml: examples/seed-findings/NAME.yaml when it exists)")
      ->check(CLI::ExistingFile);
  study->add_flag("--no-findings", st->noFindings, "No verdicts on findings (and no diagnosis)");
  study->add_option("--candidates", st->candidates,
                    "Candidate causes offered for the findings' disagreements (default: steer_damper,rider_arms,"
                    "fork_compliance,tyre_relaxation, those the scenario admits)");
  addStrictOption(study, st->strict);
  study->callback([st, dampingOption]() {
    const ParameterOverrides changes(st->overrides);  // the --set text, parsed once
    const auto source = ScenarioSource::open(st->scenario);  // the file, read once for every variant and verdict
    Scenario scenario = source->load(changes);
    reportScenarioWarnings(scenario, st->strict);
    StudyOptions opt;
    opt.sweep.start = scenario.speeds.start;
    opt.sweep.stop = scenario.speeds.stop;
    opt.sweep.step = scenario.speeds.step;
    if (!st->speeds.empty()) parseSpeedRange(st->speeds, opt.sweep.start, opt.sweep.stop, opt.sweep.step);
    opt.variants = st->variants;
    opt.stiffnessScale = st->stiffnessScale;
    opt.dampingScale = dampingOption->count() > 0 ? st->dampingScale : std::sqrt(st->stiffnessScale);
    opt.shapeSpeeds = st->shapeSpeeds;
    opt.overrides = changes;
    opt.threads = st->threads;
    if (st->rollDeg != 0) opt.sweep.trim.roll = st->rollDeg * M_PI / 180;
    checkStudyOptions(opt, {"--shape-speeds", 0, 0, ""}, getSpeedsLocation(!st->speeds.empty()));
    studies::VerdictOptions vo;
    vo.findingsFile = findFindingsFile(st->findings, st->noFindings, st->scenario);
    if (!st->candidates.empty()) vo.candidates = io::splitFields(st->candidates, ','), vo.candidatesGiven = true;
    vo.threads = st->threads;
    vo.overrides = changes;
    if (!vo.findingsFile.empty()) {  // bad input before any work
      diagnosis::loadMeasuredData(vo.findingsFile);
      std::vector<std::string> unavailable;
      studies::selectStudyCandidates(*source, vo, unavailable);
    }
    const std::string out = getOutputFolder(st->out, scenario.name, "study");
    OutputFolder folder(out);
    const auto t0 = std::chrono::steady_clock::now();
    const StudyResult result = runStudy(*source, opt);
    const double sweepSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const studies::StudyFindings findings = studies::calcStudyFindings(result);
    std::optional<studies::StudyVerdicts> verdicts;
    if (!vo.findingsFile.empty()) verdicts = studies::runStudyVerdicts(source, vo);
    const studies::StudyVerdicts* v = verdicts ? &*verdicts : nullptr;
    writeStudyOutputs(folder.getPath(), result, findings, opt, v, st->scenario);
    writeScenarioJson(folder.getPath(), scenario);
    folder.commit();
    std::cout << makeStudyReport(result, findings, opt) << "\n";
    if (v && st->rollDeg != 0)
      std::cout << "The findings are judged on straight running, as the seed states them; the variants above are "
                   "compared at "
                << io::formatNumber(st->rollDeg, 4) << " deg of roll.\n";
    if (v) std::cout << output::makeVerdictSummary(*v);
    else std::cout << "No findings set against the motorcycle (--findings FILE; docs/commands.md).\n";
    std::cout << "Sweeps " << io::formatNumber(sweepSeconds, 3) << " s"
              << (v ? ", diagnosis of the findings " + io::formatNumber(v->seconds, 3) + " s" : std::string()) << ".\nWrote "
              << out << "/{report.md, study_modes.csv, weave_shapes.csv, fig09..fig12 (.gp/.png/.svg), nominal/, halved/"
              << (v ? ", verdicts.json, extended.yaml" : "") << "}\n";
  });
}

}  // namespace

void registerStabilityCommands(CLI::App& app) {
  registerSweepCommand(app);
  registerLinearizeCommand(app);
  registerStudyCommand(app);
  registerCompareCommands(app);
}

}  // namespace motostab::cli
