// Aerodynamic drag (extensions/aerodynamics.h, scenario `aerodynamics`): in steady straight running on
// rolling contacts the drive torque carries the drag through the rear contact, T = 1/2 rho CdA v^2 r_R;
// the section's keys are checked where they are given.
#include <gtest/gtest.h>

#include <cmath>

#include "core/portable_random.h"
#include "extension_test_util.h"
#include "extensions/aerodynamics.h"

namespace motostab::extensions {

using core::PortableRandom;
using io::formatNumber;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::Input;
using vehicle::VehicleModel;

namespace {

using namespace motostab::testing;

// The Whipple bicycle's knife-edge wheels roll without slip and the front wheel carries no torque, so
// the rear contact's longitudinal force equals the drag and the rear wheel's torque balance gives
// T = F r_R, wherever the centre of pressure is.
TEST(Aerodynamics, DriveTorqueCarriesTheDragThroughTheRearContact) {
  PortableRandom rng(20261128);
  for (int trial = 0; trial < 3; ++trial) {
    const double cda = rng.drawUniform(0.2, 0.8), rho = rng.drawUniform(1.0, 1.3), v = rng.drawUniform(3, 9);
    const double x = rng.drawUniform(0.2, 0.8), z = rng.drawUniform(0.6, 1.2);
    const Scenario s = loadScenario(kWhipple, {"aerodynamics={drag_area_m2: " + formatNumber(cda) + ", air_density_kgpm3: " +
                                               formatNumber(rho) + ", centre_of_pressure_m: [" + formatNumber(x) + ", 0, " +
                                               formatNumber(z) + "]}"});
    const VehicleModel model(s);
    const analysis::TrimResult trim = analysis::calcTrim(model, v);
    const double expected = 0.5 * rho * cda * v * v * s.rearWheel.radius;
    EXPECT_NEAR(model.getInput(trim.state, Input::DriveTorque) / expected, 1.0, 1e-8) << "v = " << v;
  }
}

TEST(Aerodynamics, ZeroDragAreaReproducesTheBicycle) {
  expectWhippleSpectrumKept(
      loadScenario(kWhipple, {"aerodynamics={drag_area_m2: 0, air_density_kgpm3: 1.2, centre_of_pressure_m: [0.5, 0, 1]}"}),
      1e-12);
}

TEST(Aerodynamics, MalformedInputNamesFileLineColumnAndKey) {
  const std::string cop = "  centre_of_pressure_m: [0.5, 0, 1]\n";
  expectBadInputs(kWhipple, "aerodynamics_bad",
                  {{"aerodynamics:\n" + cop + "  air_density_kgpm3: 1.2\n  drag_area_m2: -0.3\n", 3, "aerodynamics.drag_area_m2"},
                   {"aerodynamics:\n" + cop + "  drag_area_m2: 0.3\n  air_density_kgpm3: 0\n", 3, "aerodynamics.air_density_kgpm3"},
                   {"aerodynamics:\n  drag_area_m2: 0.3\n  air_density_kgpm3: 1.2\n  centre_of_pressure_m: [0.5, 1]\n", 3,
                    "aerodynamics.centre_of_pressure_m"},
                   {"aerodynamics:\n" + cop + "  drag_area_m2: 0.3\n  air_density_kgpm3: 1.2\n  cd: 0.6\n", 3, "aerodynamics.cd"}});
}

}  // namespace
}  // namespace motostab::extensions
