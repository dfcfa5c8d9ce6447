#pragma once
// What each state of a vehicle model is: its role (roll, steer, tyre lag, ...), whether it is a
// coordinate, a rate or an auxiliary state, and the wheel it belongs to. Plugins report the roles of
// the states they add (plugin_api.h); the vehicle model (vehicle/vehicle_model.h) gives every state
// one, and the analysis classifies modes from roles, never from names (names are for files and people).
#include <string>

#include "Simbody.h"

namespace motostab::plugins {

/// The physical role of a state. Coordinates and their rates share a role.
enum class StateRole {
  Yaw,              ///< heading of the rear frame
  Roll,             ///< roll of the rear frame
  Pitch,            ///< pitch of the rear frame
  Height,           ///< height of the rear wheel centre (bounce)
  Lateral,          ///< lateral position (velocity) of the rear wheel centre
  Forward,          ///< forward position (velocity) of the rear wheel centre
  Steer,            ///< steer angle of the front frame
  WheelSpin,        ///< spin angle of a wheel (WheelSide says which)
  Suspension,       ///< rear suspension angle about the swingarm pivot
  SwingarmBending,  ///< swingarm compliance (seed sec. 4)
  SwingarmTorsion,
  SwingarmTwist,
  ForkBending,      ///< lateral fork compliance
  ForkTorsion,
  RiderLean,        ///< the rider's upper body leaning relative to the rear frame
  Compliance,       ///< another structural compliance coordinate (e.g. of a third-party plugin)
  TyreLag,          ///< a tyre's relaxation state (lagged slip or force; WheelSide says which tyre)
  Controller,       ///< a controller's internal state (e.g. a delay)
  Other,            ///< anything else
};
constexpr int kNumStateRoles = static_cast<int>(StateRole::Other) + 1;

/// Whether a state is a generalized coordinate, its rate, or an auxiliary (first-order) state.
enum class StateKind { Coordinate, Rate, Auxiliary };

/// The wheel a state belongs to.
enum class WheelSide { None, Rear, Front };

/// The role's name in files ("roll", "tyre_lag", ...).
const char* toString(StateRole role);
const char* toString(WheelSide side);

/// True for the structural compliance roles (swingarm, fork, rider lean, other compliance).
constexpr bool isComplianceRole(StateRole r) {
  return r == StateRole::SwingarmBending || r == StateRole::SwingarmTorsion || r == StateRole::SwingarmTwist ||
         r == StateRole::ForkBending || r == StateRole::ForkTorsion || r == StateRole::RiderLean ||
         r == StateRole::Compliance;
}

/// An auxiliary (z) state a plugin or model extension allocates: its name and what it is.
struct AuxiliaryState {
  std::string name;
  StateRole role = StateRole::Other;
  WheelSide wheel = WheelSide::None;
};

/// A one-DOF mobilizer a plugin or model extension adds (a compliance, the rider's lean), with the
/// name and role of its coordinate.
struct NamedMobilizer {
  std::string name;
  StateRole role = StateRole::Compliance;
  SimTK::MobilizedBody mobilizer;
};

}  // namespace motostab::plugins
