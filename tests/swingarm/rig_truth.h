#pragma once
// Truth of the virtual swingarm, computed independently of the identification code from the rig's
// parameters with seed eq. 5-9 (vector sum of the bending and torsion rotations per newton).
#include <cmath>

#include "swingarm/identification/virtual_rig.h"

struct RigTruth {
  double beta;  ///< deg, static twist axis
  double aTw;   ///< m
  double kLat;  ///< N/m
  double kTw;   ///< Nm/rad
};

inline RigTruth calcRigTruth(const motostab::swingarm::identification::VirtualSwingarm& rig) {
  const double d = M_PI / 180;
  const double ub = rig.armB / rig.kB, ut = rig.armT / rig.kT;  // rotation per newton (eq. 6)
  const double wx = ub * std::cos(rig.betaBDeg * d) + ut * std::cos(rig.betaTDeg * d);
  const double wz = ub * std::sin(rig.betaBDeg * d) + ut * std::sin(rig.betaTDeg * d);
  const double y = rig.armB * ub + rig.armT * ut, theta = std::hypot(wx, wz);  // eq. 5 per newton
  return {std::atan2(wz, wx) / d, y / theta, 1 / y, y / (theta * theta)};
}
