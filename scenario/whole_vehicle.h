#pragma once
// The whole vehicle as engineers tabulate it (total mass, centre of gravity, roll, pitch and yaw
// inertias and the product about the CoG, as in the seed's Table 6), and the split of such a total
// into the scenario's bodies: with `total:` the rear frame (with the rider) is the total minus every
// other body, exactly (parallel-axis theorem). All in the design frame D (scenario.h), SI units.
#include <array>
#include <string>
#include <vector>

#include "scenario/scenario.h"

namespace motostab::scenario {

/// A wheel as a body in D: its mass at its hub `hub_D` (m), inertia diag(diametral, spin, diametral).
BodySpec makeWheelBody(const WheelSpec& wheel, const Vec3d& hub_D);

/// The swingarm's mass properties mapped from its frame S to D: c_D = P + R c_S, I_D = R I_S R^T
/// (R: the axes of S in D, calcSwingarmFrame). Needs hasSwingarm.
BodySpec calcSwingarmBodyInD(const Scenario& scenario);

/// The bodies beside the scenario's rear frame (which holds the whole rider): `front_frame` (with
/// a fork's hub carrier), `rear_wheel`, `front_wheel` and `swingarm` when there is one, in D.
std::vector<NamedBody> listOtherBodies(const Scenario& scenario);

/// The whole vehicle with rider: the rear frame and listOtherBodies composed.
BodySpec calcVehicleTotal(const Scenario& scenario);

/// The rear frame (with rider) that makes the whole vehicle equal `total`: `total` minus the composed
/// listOtherBodies (calcBodyRemainder). Not checked: the caller tests mass > 0 and checkInertia.
BodySpec calcRearFrameFromTotal(const Scenario& scenario, const BodySpec& total);

/// The vehicle in the form of the seed's Table 6 and of most published data sets.
struct VehicleTable {
  BodySpec total;                    ///< mass kg; CoG in D m; inertia about the CoG: roll xx, pitch yy, yaw zz, product xz
  std::array<double, 2> wheelLoads;  ///< static vertical loads {rear, front}, N
  double wheelbase = 0;              ///< m
  double steerAxisTiltDeg = 0;       ///< caster angle, deg
  double trail = 0;                  ///< m
  double normalTrail = 0;            ///< m
  double forkOffset = 0;             ///< m (calcForkOffset)
};
VehicleTable calcVehicleTable(const Scenario& scenario);

/// Defaults for what a split needs and a whole-vehicle data set seldom gives: a sport motorcycle's
/// front assembly and 17-inch wheels with tyres, the values of the bundled super-sport documented in
/// docs/motorcycle-parameters.md (front frame 14 kg; front wheel 11.9 kg, spin 0.60, diametral
/// 0.32 kg m^2; rear wheel 13.3 kg, 0.65, 0.41 kg m^2; sources and ranges there).
struct WheelDefaults {
  double mass = 0;              ///< kg
  double axialInertia = 0;      ///< kg m^2
  double diametralInertia = 0;  ///< kg m^2
};
WheelDefaults getDefaultWheel(bool front);

/// The default front frame (fork, clamps, handlebar, brakes; no wheel): 14 kg, CoM at the height of
/// the front tyre's top (2 r_F) and 0.02 m ahead of the steer axis, principal moments 0.35 (along the
/// steer axis), 0.75 (lateral) and 0.85 kg m^2 (normal to both), turned into D by the steer-axis tilt.
BodySpec makeDefaultFrontFrame(const GeometrySpec& geometry, double frontRadius);

/// Source text of the defaults, for AssumedValue::source.
extern const char* const kWholeVehicleDefaultSource;

}  // namespace motostab::scenario
