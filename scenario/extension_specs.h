#pragma once
// Readers of the optional model-extension sections of a scenario: `steer_damper`,
// `fork_compliance`, `rider_lean`, `steer_controller`. Each section is strict (unknown keys, wrong types, negative
// stiffnesses are InputErrors at file:line:col); absent sections leave the model as it was.
#include "scenario/scenario.h"
#include "io/yaml_map.h"

namespace motostab::scenario {

/// Reads every extension section present in the scenario root `root` into `scenario` (whose
/// frames, wheels and geometry are already read).
void readExtensions(io::YamlMap& root, Scenario& scenario);

/// Reads `mass_kg`, `com_m` and `inertia_kgm2` (checked) from `m` (scenario.cpp); the caller finishes the map.
BodySpec readBodyKeys(io::YamlMap& m);

/// `steer_damper: {damping_Nms_per_rad, coulomb_Nm?, coulomb_smoothing_rad_per_s?}`.
SteerDamperSpec readSteerDamper(io::YamlMap m);

/// `steer_controller: {roll_angle_Nm_per_rad?, roll_rate_Nms_per_rad?, steer_angle_Nm_per_rad?,
/// steer_rate_Nms_per_rad?, gain_factor?, schedule: {below_mps: v0} | {table: [[v, f], ...]}?, delay_s?,
/// torque_limit_Nm?}` (vehicle/steer_controller.h). The table needs at least two rows with strictly
/// increasing speeds; a negative delay or one between 0 and kMinSteerDelay, a non-positive limit or gain
/// factor are errors.
SteerControllerSpec readSteerController(io::YamlMap m);

/// The scalar keys of `steer_controller` (gains, gain_factor, delay_s, torque_limit_Nm), for readers
/// that set them per measurement (diagnosis/measured_data.h).
const std::vector<std::string>& getSteerControllerScalarKeys();

/// `fork_compliance: {stiffness_Nm_per_rad, damping_Nms_per_rad, axis_distance_along_steer_m?,
/// carrier_mass_fraction? | carrier: {mass_kg, com_m, inertia_kgm2}?, torsion: {stiffness_Nm_per_rad,
/// damping_Nms_per_rad}?}`; the front frame without the carrier must remain a valid body.
ForkComplianceSpec readForkCompliance(io::YamlMap m, const Scenario& scenario);

/// `rider_lean: {hinge_height_m, mass_kg, com_m, inertia_kgm2, stiffness_Nm_per_rad,
/// damping_Nms_per_rad}`; the rear frame without the upper body must remain a valid body.
RiderLeanSpec readRiderLean(io::YamlMap m, const Scenario& scenario);

/// `rider_arms: {inertia_kgm2, stiffness_Nm_per_rad, damping_Nms_per_rad, grip_half_width_m?}`
/// (scenario.h RiderArmsSpec), its grip masses placed on the steer axis at the front frame's
/// centre-of-mass height, `scenario`'s rear frame able to give them up (checked).
RiderArmsSpec readRiderArms(io::YamlMap m, const Scenario& scenario);

/// Default fork bending axis: the steer-axis point at the height of the front tyre's top (2 r_F), an
/// estimate of the fork crown (lower triple clamp), m along the steer axis: 2 r_F / cos(lambda).
double calcDefaultForkAxisDistance(const Scenario& scenario);

/// Default carrier fraction of the front frame's mass (estimate: lower fork legs, axle and brake
/// caliper are about a third of a motorcycle's front frame; see docs/scenario-format.md).
constexpr double kDefaultForkCarrierFraction = 0.3;

}  // namespace motostab::scenario
