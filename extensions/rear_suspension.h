#pragma once
// Rear suspension (`swingarm.suspension`, a section inside `swingarm`): the swingarm turns about the
// pivot's lateral axis (design y) against a rotational spring and damper. A massless link on a pin
// through the pivot carries the swingarm (its compliance in series); its angle q > 0 lifts the hub.
// The spring's free angle is set so that it carries the static pivot moment M_0 at q = 0 (the design
// pose is the loaded equilibrium):
//   T = -k_theta (q - q_0) - c_theta q',   q_0 = -M_0 / k_theta          (N m)
// The scenario gives k and c about the pivot or referred to the wheel: k_theta = k_wheel l^2,
// c_theta = c_wheel l^2, with l the horizontal pivot-to-hub distance (the hub's vertical travel per
// radian; the wheel rate is the vertical force at the contact per vertical hub travel relative to the
// rear frame, SAE J670).
#include <memory>

#include "plugins/plugin_api.h"

namespace motostab::extensions {

/// The section, always about the pivot.
struct RearSuspensionParams {
  double stiffness = 0;          ///< k_theta, N m/rad (> 0)
  double damping = 0;            ///< c_theta, N m s/rad (>= 0)
  double lever = 0;              ///< l, m (> 0): horizontal distance from the pivot to the rear hub
  double staticPivotMoment = 0;  ///< M_0, N m (VehicleLayout::staticPivotMoment)
};

/// Suspension lever l (m) of a vehicle: the pivot's distance ahead of the rear hub (the hub is at x = 0).
double calcSuspensionLever(const plugins::VehicleLayout& vehicle);

/// The section's declared fields.
const io::SectionFields& getRearSuspensionFields();

/// Reads and checks the section: `stiffness_Nm_per_rad` or `wheel_rate_N_per_m`, and
/// `damping_Nms_per_rad` or `damping_Ns_per_m` (exactly one of each pair); the caller finishes `m`.
RearSuspensionParams readRearSuspension(io::YamlMap& m, const plugins::VehicleLayout& vehicle);

/// The extension with these parameters (typed constructor; tests build it without YAML).
std::unique_ptr<plugins::ExtensionModel> makeRearSuspension(const RearSuspensionParams& params);

/// Registers `swingarm.suspension`.
void registerRearSuspension(plugins::PluginRegistrar& registry);

}  // namespace motostab::extensions
