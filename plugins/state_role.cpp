#include "plugins/state_role.h"

namespace motostab::plugins {

const char* toString(StateRole role) {
  static const char* const kNames[kNumStateRoles] = {
      "yaw",          "roll",         "pitch",          "height",           "lateral",          "forward",
      "steer",        "wheel_spin",   "suspension",     "swingarm_bending", "swingarm_torsion", "swingarm_twist",
      "fork_bending", "fork_torsion", "rider_lean",     "compliance",       "tyre_lag",         "controller",
      "other"};
  return kNames[static_cast<int>(role)];
}

const char* toString(WheelSide side) {
  switch (side) {
    case WheelSide::Rear: return "rear";
    case WheelSide::Front: return "front";
    case WheelSide::None: break;
  }
  return "none";
}

}  // namespace motostab::plugins
