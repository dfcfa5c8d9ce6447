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
#include <string>
#include <utility>
#include <vector>

#include "plugins/plugin_api.h"
#include "scenario/scenario.h"

namespace motostab::vehicle {

/// The body that carries the front wheel and the compliance mobilizers (roles ForkBending, ForkTorsion).
struct ForkAssembly {
  SimTK::MobilizedBody hubCarrier;  ///< body origin at the front hub, axes parallel to D at the design pose
  std::vector<plugins::NamedMobilizer> coordinates;
};

/// Adds carrier (and torsion link) to `frontFrame`, whose body origin is the front hub at p_DF (D, m).
ForkAssembly addForkCompliance(plugins::BuildContext& context, SimTK::MobilizedBody& frontFrame, const SimTK::Vec3& p_DF,
                               const scenario::Scenario& scenario);

/// The bending hinge point P in the design frame (m) and the unit bending axis n_b.
SimTK::Vec3 calcForkHingePoint(const scenario::Scenario& scenario);
SimTK::Vec3 calcForkBendingAxis(const scenario::Scenario& scenario);

}  // namespace motostab::vehicle
