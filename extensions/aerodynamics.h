#pragma once
// Aerodynamic drag (`aerodynamics`) on the rear frame: F = -1/2 rho CdA |v| v at the centre of
// pressure, v its ground velocity (seed sec. 4: in the trim the drive torque balances the drag).
#include <memory>

#include "plugins/plugin_api.h"

namespace motostab::extensions {

/// The section `aerodynamics: {drag_area_m2, air_density_kgpm3, centre_of_pressure_m}`.
struct AerodynamicsParams {
  double dragArea = 0;      ///< Cd A, m^2 (>= 0)
  double airDensity = 1.2;  ///< rho, kg/m^3 (> 0)
  scenario::Vec3d centreOfPressure{0, 0, 0};  ///< in D, m
};

/// The section's declared fields.
const io::SectionFields& getAerodynamicsFields();

/// Reads and checks the section (the caller finishes `m`).
AerodynamicsParams readAerodynamics(io::YamlMap& m);

/// The extension with these parameters (typed constructor).
std::unique_ptr<plugins::ExtensionModel> makeAerodynamics(const AerodynamicsParams& params);

/// Registers `aerodynamics`.
void registerAerodynamics(plugins::PluginRegistrar& registry);

}  // namespace motostab::extensions
