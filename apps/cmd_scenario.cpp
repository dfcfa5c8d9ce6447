// motostab check | import.
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "io/atomic_file.h"
#include "io/input_error.h"
#include "output/scenario_output.h"
#include "scenario/bicycle_parameters.h"
#include "vehicle/vehicle_model.h"

namespace motostab::cli {

using io::writeFileAtomically;
using output::formatVehicleTable;
using scenario::InertiaRepair;
using scenario::Scenario;
using scenario::calcStaticPivotMoment;
using scenario::calcSuspensionLever;
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
      std::cout << "  swingarm              compliance " << s.swingarm.compliance << ", pivot "
                << (s.swingarm.hasSuspension ? "sprung" : "rigid in-plane") << "\n";
      if (s.swingarm.hasSuspension) {
        const double l = calcSuspensionLever(s);
        std::cout << "  rear suspension       " << s.swingarm.suspension.stiffness << " N m/rad, "
                  << s.swingarm.suspension.damping << " N m s/rad about the pivot (at the wheel "
                  << s.swingarm.suspension.stiffness / (l * l) << " N/m, " << s.swingarm.suspension.damping / (l * l)
                  << " N s/m; lever " << l << " m); static pivot moment " << calcStaticPivotMoment(s) << " N m\n";
      }
    }
    model.describeExtensions(std::cout);
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
