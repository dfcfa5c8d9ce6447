#pragma once
// Lateral fork compliance (`fork_compliance`), after Sharp & Alstead (1980) "The influence
// of structural flexibilities on the straight-running stability of motorcycles" (VSD 9(6)), Spierings
// (1981) "The effects of lateral front fork flexibility on the vibrational modes of straight-running
// single-track vehicles" (VSD 10(1)) and Cossalter, Lot, Massaro (2007) "The influence of frame
// compliance and rider mobility on the scooter stability" (VSD 45(4)).
// The hub carrier C (lower fork legs, axle, brake) turns relative to the front frame H about the
// bending axis n_b = (cos lambda, 0, sin lambda) (perpendicular to the steer axis, in the plane of
// symmetry), through the steer-axis point P at distance d above the steer axis's ground point:
//   p_P = (w + c, 0, 0) + d (-sin lambda, 0, cos lambda)          (design frame, m)
// coordinate `fork_bending` (rad; > 0 by the right-hand rule about n_b moves the contact point to +y),
// moment T_b = -k_b theta_b - c_b theta_b'. Optional torsion in series: a massless link between C and
// the wheel turning about the steer-axis direction through P, coordinate `fork_torsion`
// (rad, same sense as steer), T_t = -k_t theta_t - c_t theta_t'.
// The carrier's mass properties are taken out of the front frame's, so the totals are unchanged;
// steer torque still acts between front frame and rear frame.
#include <memory>
#include <vector>

#include "extensions/extension_input.h"
#include "plugins/plugin_api.h"

namespace motostab::extensions {

/// Default carrier fraction of the front frame's mass (estimate: lower fork legs, axle and brake
/// caliper are about a third of a motorcycle's front frame; see docs/scenario-format.md).
constexpr double kDefaultForkCarrierFraction = 0.3;

/// The section `fork_compliance: {stiffness_Nm_per_rad, damping_Nms_per_rad, axis_distance_along_steer_m?,
/// carrier_mass_fraction? | carrier: {mass_kg, com_m, inertia_kgm2}?, torsion: {stiffness_Nm_per_rad,
/// damping_Nms_per_rad}?}`.
struct ForkComplianceParams {
  SpringDamper bending;          ///< k_b (N m/rad, > 0), c_b (N m s/rad, >= 0)
  double axisDistance = 0;       ///< d, m along the steer axis from its ground point (default: the crown)
  scenario::BodySpec carrier;    ///< moving part's mass properties in D (default: a fraction of the front frame)
  double carrierFraction = 0;    ///< the fraction used for the default carrier (0 when given explicitly)
  bool hasTorsion = false;
  SpringDamper torsion;          ///< k_t (N m/rad, > 0), c_t (N m s/rad, >= 0)
};

/// The section's declared fields: `fork_compliance`, its `carrier` body and its `torsion` (in this order).
const std::vector<io::SectionFields>& getForkComplianceFields();

/// Reads and checks the section; the front frame of `vehicle` without the carrier must remain a valid
/// body (the caller finishes `m`).
ForkComplianceParams readForkCompliance(io::YamlMap& m, const plugins::VehicleLayout& vehicle);

/// Default bending axis point: the steer-axis point at the height of the front tyre's top (2 r_F), an
/// estimate of the fork crown (lower triple clamp), m along the steer axis: 2 r_F / cos(lambda).
double calcDefaultForkAxisDistance(const plugins::VehicleLayout& vehicle);

/// The default hub carrier: the front frame scaled by `fraction` (that fraction of its mass at its
/// CoM, that fraction of its inertia), so that the rest, the front frame scaled by 1 - fraction, is a
/// valid body for every valid front frame.
scenario::BodySpec calcDefaultForkCarrier(const plugins::VehicleLayout& vehicle, double fraction);

/// The bending hinge point P in the design frame (m) and the unit bending axis n_b.
SimTK::Vec3 calcForkHingePoint(const ForkComplianceParams& params, const plugins::VehicleLayout& vehicle);
SimTK::Vec3 calcForkBendingAxis(const plugins::VehicleLayout& vehicle);

/// The extension with these parameters on `vehicle` (typed constructor).
std::unique_ptr<plugins::ExtensionModel> makeForkCompliance(const ForkComplianceParams& params,
                                                            const plugins::VehicleLayout& vehicle);

/// Registers `fork_compliance`.
void registerForkCompliance(plugins::PluginRegistrar& registry);

}  // namespace motostab::extensions
