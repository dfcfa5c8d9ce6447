#pragma once
// Rigid-body mass properties in the design frame D (scenario.h: origin at the rear contact point of
// the upright vehicle at rest, x forward, y left, z up), and the parallel-axis arithmetic on them.
// The scenario reader and the model-extension plugins (plugins/plugin_api.h) share these types.
#include <array>
#include <string>
#include <vector>

namespace motostab::scenario {

using Vec3d = std::array<double, 3>;

/// Inertia tensor components about the centre of mass, in the design frame, kg m^2.
/// Off-diagonal entries are tensor components (I_xz = -sum m x z), as in Meijaard et al. 2007.
struct InertiaSpec {
  double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
};

/// A rigid body: mass (kg), centre of mass in D (m), inertia about the CoM in D.
struct BodySpec {
  double mass = 0;
  Vec3d com{0, 0, 0};
  InertiaSpec inertia;
};

/// A body with a name, as reports list them (`rear_frame`, `fork_carrier`, ...).
struct NamedBody {
  std::string name;
  BodySpec body;
};

/// Checks an inertia tensor: symmetric positive definite and principal moments satisfying the
/// triangle inequality. Returns an empty string if valid, else the reason.
std::string checkInertia(const InertiaSpec& inertia);

/// The mass properties of `whole` without `part` (all in D): mass, CoM and inertia about the new CoM.
/// Parallel-axis theorem about the design origin; the caller checks the result (mass > 0, checkInertia).
BodySpec calcBodyRemainder(const BodySpec& whole, const BodySpec& part);

/// Parallel-axis composition: the total mass, the common CoM, the inertia about it (D axes).
/// Needs a positive total mass.
BodySpec composeBodies(const std::vector<BodySpec>& parts);

}  // namespace motostab::scenario
