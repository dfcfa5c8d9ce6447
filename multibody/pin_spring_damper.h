#pragma once
// A linear torsional spring and viscous damper on a one-DOF mobilizer, as one force element.
#include "Simbody.h"

namespace motostab::multibody {

/// Adds tau = -stiffness (q - freeAngle) - damping u on mobilizer `pin`'s first coordinate
/// (stiffness N m/rad or N/m, damping N m s/rad or N s/m, freeAngle rad or m), with potential
/// energy stiffness (q - freeAngle)^2 / 2. One Force::Custom instead of Simbody's
/// MobilityLinearSpring + MobilityLinearDamper pair: the spring's "depends only on positions" flag
/// makes GeneralForceSubsystem cache and re-add every force array on each realization, about 15%
/// of a sweep's time on a vehicle with three such joints (bench/bench_extensions_sweep.cpp).
void addPinSpringDamper(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& pin, double stiffness,
                        double damping, double freeAngle = 0);

}  // namespace motostab::multibody
