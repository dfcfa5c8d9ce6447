// motostab check | import.
#include <iomanip>
#include <iostream>

#include "apps/commands.h"
#include "io/atomic_file.h"
#include "scenario/bicycle_parameters.h"
#include "vehicle/vehicle_model.h"

namespace motostab::cli {
namespace {

// The issue-10 model extensions present, one line each (docs/scenario-format.md).
void printExtensions(const Scenario& s) {
  if (s.hasSteerDamper)
    std::cout << "  steer damper          " << s.steerDamper.damping << " N m s/rad, Coulomb " << s.steerDamper.coulomb
              << " N m (smoothing " << s.steerDamper.coulombSmoothing << " rad/s; linearised "
              << s.steerDamper.damping + s.steerDamper.coulomb / s.steerDamper.coulombSmoothing << " N m s/rad)\n";
  if (s.hasForkCompliance) {
    const ForkComplianceSpec& f = s.forkCompliance;
    std::cout << "  fork compliance       bending " << f.stiffness << " N m/rad, " << f.damping << " N m s/rad, axis "
              << f.axisDistance << " m up the steer axis, carrier " << f.carrier.mass << " kg";
    if (f.hasTorsion) std::cout << "; torsion " << f.torsionStiffness << " N m/rad, " << f.torsionDamping << " N m s/rad";
    std::cout << "\n";
  }
  if (s.hasRiderLean)
    std::cout << "  rider lean            upper body " << s.riderLean.body.mass << " kg, hinge at " << s.riderLean.hingeHeight
              << " m, " << s.riderLean.stiffness << " N m/rad, " << s.riderLean.damping << " N m s/rad\n";
}

}  // namespace

void registerScenarioCommands(CLI::App& app) {
  auto check = std::make_shared<std::pair<std::string, std::vector<std::string>>>();
  CLI::App* c = app.add_subcommand("check", "Validate a scenario and print derived quantities");
  c->add_option("scenario", check->first, "Scenario YAML file")->required()->check(CLI::ExistingFile);
  c->add_option("--set", check->second, "Override a scenario value");
  c->callback([check]() {
    const Scenario s = loadScenario(check->first, check->second);
    const VehicleModel model(s);  // also validates the plugins
    const MassSummary ms = calcMassSummary(s);
    const auto loads = calcStaticWheelLoads(s);
    std::cout << std::fixed << std::setprecision(4) << "Scenario " << s.name << " is valid.\n"
              << "  total mass            " << ms.mass << " kg\n"
              << "  centre of mass        x " << ms.com[0] << " m, y " << ms.com[1] << " m, z " << ms.com[2]
              << " m (from the rear contact, z up)\n"
              << "  normal trail          " << calcNormalTrail(s.geometry) << " m\n"
              << "  static wheel loads    rear " << loads[0] << " N, front " << loads[1] << " N\n"
              << "  contact model         " << s.contact.model << "\n"
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
    printExtensions(s);
  });

  struct ImportArgs {
    std::string file, format, out, name;
  };
  auto imp = std::make_shared<ImportArgs>();
  CLI::App* i = app.add_subcommand("import", "Convert a parameter file into a scenario");
  i->add_option("file", imp->file, "Parameter file")->required()->check(CLI::ExistingFile);
  i->add_option("--format", imp->format, "Input format")->required()->check(CLI::IsMember({"bicycleparameters"}));
  i->add_option("--out", imp->out, "Scenario YAML to write")->required();
  i->add_option("--name", imp->name, "Scenario name (default: the output file stem)");
  i->callback([imp]() {
    const std::string name = imp->name.empty() ? std::filesystem::path(imp->out).stem().string() : imp->name;
    writeFileAtomically(imp->out, convertBicycleParametersToScenario(imp->file, name));
    loadScenario(imp->out);  // what we write must load
    std::cout << "Wrote " << imp->out << "\n";
  });
}

}  // namespace motostab::cli
