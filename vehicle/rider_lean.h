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
#include "plugins/plugin_api.h"
#include "scenario/scenario.h"

namespace motostab::vehicle {

/// Adds the upper body to `rearFrame`, whose body origin is at p_DR (design frame, m). Returns its
/// one-DOF mobilizer (q = 0 upright), coordinate `rider_lean` with role RiderLean.
plugins::NamedMobilizer addRiderLean(plugins::BuildContext& context, SimTK::MobilizedBody& rearFrame, const SimTK::Vec3& p_DR,
                                       const scenario::RiderLeanSpec& spec);

}  // namespace motostab::vehicle
