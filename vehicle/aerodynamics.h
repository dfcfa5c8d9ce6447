#pragma once
// Aerodynamic drag on the rear frame (seed sec. 4 trim: drive torque balances drag).
#include "plugins/plugin_api.h"
#include "scenario/scenario.h"

namespace motostab::vehicle {

/// Adds F = -1/2 rho CdA |v| v, v the ground velocity of the centre of pressure p_RC (rear-frame
/// body coordinates, m), applied at that point (N).
void addAerodynamicDrag(plugins::BuildContext& context, const SimTK::MobilizedBody& rearFrame, const scenario::AerodynamicsSpec& spec,
                        const SimTK::Vec3& p_RC);

}  // namespace motostab::vehicle
