// motostab compare: several scenarios swept over the same speeds, side by side.
#include <iostream>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "io/input_error.h"
#include "io/output_folder.h"
#include "output/compare_output.h"

namespace motostab::cli {

using analysis::SweepOptions;
using analysis::runSweep;
using io::InputError;
using io::OutputFolder;
using output::ComparedSweep;
using output::formatCompareTable;
using output::makeCompareLabels;
using output::writeCompareOutputs;
using scenario::Scenario;
using vehicle::VehicleModel;

void registerCompareCommands(CLI::App& app) {
  struct CompareArgs {
    std::vector<std::string> scenarios, overrides;
    std::string speeds, out;
    int threads = 1;
    bool strict = false;
  };
  auto a = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "Several scenarios swept over the same speeds: overlaid root loci and real parts, critical speeds "
                 "and their differences against the first");
  cmd->add_option("scenarios", a->scenarios, "Scenario YAML files, two or more (the first is the reference)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--speeds", a->speeds, "START:STOP:STEP in m/s (default: the first scenario's speeds_mps)")
      ->check(makeSpeedRangeCheck());
  addOutOption(*cmd, a->out, "NAME1-vs-NAME2...");
  cmd->add_option("--set", a->overrides, "Override a value in every scenario, e.g. --set aerodynamics.drag_area_m2=0");
  cmd->add_option("--threads", a->threads, "Worker threads of each sweep")->check(makeThreadsCheck());
  addStrictOption(cmd, a->strict);
  cmd->callback([a]() {
    if (a->scenarios.size() < 2)
      throw InputError({"command line", 0, 0, "scenarios"}, "compare needs two or more scenario files");
    std::vector<ComparedSweep> sweeps;
    std::vector<std::string> names;
    for (const std::string& file : a->scenarios) {
      sweeps.push_back({"", loadScenarioReporting(file, a->overrides, a->strict), {}});
      names.push_back(sweeps.back().scenario.name);
    }
    const std::vector<std::string> labels = makeCompareLabels(names);
    std::string joined;
    for (size_t i = 0; i < sweeps.size(); ++i) {
      sweeps[i].label = labels[i];
      joined += (i ? "-vs-" : "") + labels[i];
    }
    const std::string out = getOutputFolder(a->out, joined, "compare");
    SweepOptions opt;
    const Scenario& first = sweeps.front().scenario;
    opt.start = first.speeds.start, opt.stop = first.speeds.stop, opt.step = first.speeds.step;
    if (!a->speeds.empty()) parseSpeedRange(a->speeds, opt.start, opt.stop, opt.step);
    opt.threads = a->threads;
    OutputFolder folder(out);  // inputs read; from here an error or a kill leaves the old outputs whole
    for (ComparedSweep& c : sweeps) {
      const VehicleModel model(c.scenario);
      c.sweep = runSweep(model, opt);
    }
    writeCompareOutputs(folder.getPath(), sweeps);
    folder.commit();
    std::cout << sweeps.size() << " scenarios over " << sweeps.front().sweep.speeds.size() << " speeds\n"
              << formatCompareTable(sweeps) << "Wrote " << out
              << "/{summary.json, critical_speeds.csv, root_locus, real_part_vs_speed (.gp/.png/.svg), LABEL/}\n";
  });
}

}  // namespace motostab::cli
