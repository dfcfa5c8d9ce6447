#pragma once
// Swingarm compliance plugins (seed sec. 4): `rigid`, and one revolute DOF with rotational stiffness
// and damping about an identified axis, `bending`, `torsion`, `twist`, or `bending+torsion` in series.
#include "plugins/plugin_api.h"

namespace motostab::swingarm {

/// A lumped compliance axis in the swingarm frame S with its stiffness and damping.
struct ComplianceAxis {
  SimTK::Vec3 point_S;      ///< a point on the axis, m
  SimTK::Vec3 direction_S;  ///< unit direction
  double stiffness = 0;     ///< N m/rad
  double damping = 0;       ///< N m s/rad
};

/// The axis from the identification outputs (seed eq. 2-10, Fig. 8): it makes angle beta (rad)
/// with the S x axis and passes at signed arm a (m) from the hub: direction (cos b, 0, sin b),
/// through hub + a (-sin b, 0, cos b). beta = 90 deg lies a metres in front of the hub.
ComplianceAxis makeAxisFromArm(const SimTK::Vec3& p_SH, double arm, double beta, double stiffness, double damping);

/// Registers rigid, bending, torsion, twist and bending+torsion.
void registerSwingarmModels(plugins::PluginRegistrar& registry);

/// The `swingarm` keys the compliance models read (the loader reads pivot, body and `compliance`):
/// the axes, the stiffness and damping scales, `axes_from`.
const io::SectionFields& getSwingarmModelFields();

/// The keys of one axis mapping, `name` bending, torsion or twist (section `swingarm.<name>`):
/// stiffness, damping, the geometry ({arm_m, beta_deg} or {point_m, direction}, also nested under
/// `axis`) and the identification's informational values. std::logic_error for another name.
const io::SectionFields& getSwingarmAxisFields(const std::string& name);

}  // namespace motostab::swingarm
