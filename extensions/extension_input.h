#pragma once
// Reading helpers shared by the model-extension plugins of this folder.
#include <string>

#include "io/field.h"
#include "io/yaml_map.h"
#include "scenario/body_spec.h"

namespace motostab::extensions {

/// A torsional spring and damper: k (N m/rad) and c (N m s/rad).
struct SpringDamper {
  double stiffness = 0;
  double damping = 0;
};

/// The fields of a torsional spring and damper: stiffness_Nm_per_rad > 0, damping_Nms_per_rad >= 0
/// (path empty: sections take them into their own).
const io::SectionFields& getSpringDamperFields();

/// `{stiffness_Nm_per_rad > 0, damping_Nms_per_rad >= 0}` from `m` (the caller finishes it).
SpringDamper readSpringDamper(io::YamlMap& m);

/// Fails at `key` of `m` unless `whole` without `part` (scenario::calcBodyRemainder) is a valid body:
/// positive mass and a physical inertia. `wholeName` names `whole` in the message (e.g. "rear_frame").
void checkRemainder(const io::YamlMap& m, const std::string& key, const scenario::BodySpec& whole,
                    const scenario::BodySpec& part, const std::string& wholeName);

}  // namespace motostab::extensions
