#pragma once
// Passive rider lean (`rider_lean`): the rider's upper body on a revolute joint about the
// longitudinal axis (design x) through (0, 0, h) in the rear frame, with a torsional spring k and
// damper c: T = -k theta - c theta' (N m) on the upper body, its reaction on the rear frame.
// Coordinate `rider_lean` (rad, right-hand rule about forward x: > 0 moves the head towards -y, i.e.
// leans right relative to the rear frame, the same sense as roll).
// The upper body's mass properties are taken out of the rear frame's (scenario rear_frame includes
// the whole rider), so the upright vehicle's mass, CoM and inertia are unchanged.
// Model: Schwab, Meijaard, Kooijman (2012), "Lateral dynamics of a bicycle with a passive rider
// model: stability and controllability", Vehicle System Dynamics 50(8):1209-1224 (upper body hinged at
// the hip about a longitudinal axis); Sharp & Limebeer (2001) and Cossalter (2006) ch. 6 for motorcycles.
#include <memory>

#include "plugins/plugin_api.h"

namespace motostab::extensions {

/// The section `rider_lean: {hinge_height_m, mass_kg, com_m, inertia_kgm2, stiffness_Nm_per_rad,
/// damping_Nms_per_rad}`.
struct RiderLeanParams {
  double hingeHeight = 0;        ///< h, m above the ground, in the plane of symmetry (> 0)
  scenario::BodySpec body;       ///< upper body: mass (kg), CoM in D (m, y = 0), inertia about its CoM in D
  double stiffness = 0;          ///< k, N m/rad (> 0)
  double damping = 0;            ///< c, N m s/rad (>= 0)
};

/// The section's declared fields.
const io::SectionFields& getRiderLeanFields();

/// Reads and checks the section: the rear frame of `vehicle` without the upper body must remain a
/// valid body (the caller finishes `m`).
RiderLeanParams readRiderLean(io::YamlMap& m, const plugins::VehicleLayout& vehicle);

/// The extension with these parameters (typed constructor).
std::unique_ptr<plugins::ExtensionModel> makeRiderLean(const RiderLeanParams& params);

/// Registers `rider_lean`.
void registerRiderLean(plugins::PluginRegistrar& registry);

}  // namespace motostab::extensions
