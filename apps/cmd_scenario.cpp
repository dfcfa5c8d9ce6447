// motostab check | fields | import.
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "io/atomic_file.h"
#include "io/input_error.h"
#include "output/scenario_output.h"
#include "plugins/builtin.h"
#include "scenario/bicycle_parameters.h"
#include "vehicle/vehicle_model.h"

namespace motostab::cli {

using io::writeFileAtomically;
using output::formatVehicleTable;
using scenario::InertiaRepair;
using scenario::Scenario;
using scenario::loadScenario;
using scenario::writeBicycleParametersScenario;
using vehicle::VehicleModel;

namespace {

void printInertiaRepairs(const std::vector<InertiaRepair>& repairs) {
  for (const auto& r : repairs)
    std::cout << "repaired " << r.key << ": " << r.explanation << "; " << (r.after < r.before ? "lowered" : "raised")
              << " from " << r.before << " to " << r.after << " kg m^2 (" << std::showpos << r.after - r.before
              << std::noshowpos << "). The linearised Whipple model does not use the frames' "
              << "I_yy (pitch), so the eigenvalues are those of the file's values.\n";
}

}  // namespace

void registerScenarioCommands(CLI::App& app) {
  struct CheckArgs {
    std::string scenario;
    std::vector<std::string> overrides;
    bool strict = false;
  };
  auto check = std::make_shared<CheckArgs>();
  CLI::App* c = app.add_subcommand("check", "Validate a scenario; print the whole vehicle (Table 6 form), its bodies and warnings");
  c->add_option("scenario", check->scenario, "Scenario YAML file")->required()->check(CLI::ExistingFile);
  c->add_option("--set", check->overrides, "Override a scenario value");
  addStrictOption(c, check->strict);
  c->callback([check]() {
    const Scenario s = loadScenarioReporting(check->scenario, check->overrides, check->strict);
    const VehicleModel model(s);  // also validates the plugins
    std::cout << "Scenario " << s.name << " is valid" << (s.warnings.empty() ? "" : " (plausibility warnings above)")
              << ".\n" << formatVehicleTable(s) << std::fixed << std::setprecision(4)
              << "Model\n  contact model         " << s.contact.model << "\n"
              << "  degrees of freedom    " << model.getNumQ() << " coordinates, " << model.getNumZ() << " auxiliary states\n";
    if (s.hasSwingarm) {
      const bool sprung = std::any_of(model.getQStates().begin(), model.getQStates().end(),
                                      [](const auto& q) { return q.role == plugins::StateRole::Suspension; });
      std::cout << "  swingarm              compliance " << s.swingarm.compliance << ", pivot "
                << (sprung ? "sprung" : "rigid in-plane") << "\n";
    }
    model.describeExtensions(std::cout);
  });

  struct FieldsArgs {
    std::vector<std::string> sections, libraries;
  };
  auto fa = std::make_shared<FieldsArgs>();
  CLI::App* f = app.add_subcommand("fields", "List the declared fields of scenario sections: key, unit, range, default, meaning");
  f->add_option("section", fa->sections, "Sections to list, as key paths (geometry, rider_lean, swingarm.suspension; \"\" the top level); default all");
  f->add_option("--plugin", fa->libraries, "A plugin library (as a scenario's `plugins:` lists it) whose sections to list too; repeatable");
  f->callback([fa]() {
    plugins::PluginRegistry registry = plugins::makeBuiltinRegistry();
    for (const std::string& library : fa->libraries) registry.loadLibrary(library, {"--plugin", 0, 0, library});
    const std::vector<io::SectionFields> all = plugins::listSectionFields(registry);
    const std::vector<std::string>& sections = fa->sections;
    for (const std::string& name : sections)
      if (std::none_of(all.begin(), all.end(), [&](const io::SectionFields& s) { return s.path == name; })) {
        std::vector<std::string> paths;  // each path once ("" is the top level)
        for (const io::SectionFields& s : all)
          if (std::find(paths.begin(), paths.end(), s.path) == paths.end()) paths.push_back(s.path);
        std::string known;
        for (const std::string& p : paths) known += (known.empty() ? "" : ", ") + (p.empty() ? std::string("\"\"") : p);
        throw io::InputError({"command line", 0, 0, name}, "no such section (known: " + known + ")");
      }
    for (const io::SectionFields& s : all)
      if (sections.empty() || std::find(sections.begin(), sections.end(), s.path) != sections.end())
        std::cout << io::formatSectionHeading(s) << "\n\n" << io::formatFieldTable(s) << "\n";
  });

  struct ImportArgs {
    std::string file, format, out, name;
    bool repairInertia = false;
  };
  auto imp = std::make_shared<ImportArgs>();
  CLI::App* i = app.add_subcommand("import", "Convert a parameter file into a scenario");
  i->add_option("file", imp->file, "Parameter file")->required()->check(CLI::ExistingFile);
  i->add_option("--format", imp->format, "Input format")->required()->check(CLI::IsMember({"bicycleparameters"}));
  i->add_option("--out", imp->out, "Scenario YAML to write")->required();
  i->add_option("--name", imp->name, "Scenario name (default: the output file stem)");
  i->add_flag("--repair-inertia", imp->repairInertia,
              "Move a frame's I_yy onto the triangle-inequality bound (unused by the linear Whipple model)");
  i->callback([imp]() {
    const std::filesystem::path out(imp->out);
    if (!out.has_filename() || out.filename() == "." || out.filename() == "..")
      throw io::InputError({"command line", 0, 0, "--out"}, "'" + imp->out + "' names no file: give the scenario file to write, e.g. bike.yaml");
    const std::string name = imp->name.empty() ? std::filesystem::path(imp->out).stem().string() : imp->name;
    std::vector<InertiaRepair> repairs;  // written only once it loads; errors at the parameter file's lines
    writeBicycleParametersScenario(imp->file, name, imp->out, {imp->repairInertia}, &repairs);
    printInertiaRepairs(repairs);
    std::cout << "Wrote " << imp->out << "\n";
  });
}

}  // namespace motostab::cli
