#include "extensions/extension_input.h"

namespace motostab::extensions {

using scenario::BodySpec;

SpringDamper readSpringDamper(io::YamlMap& m) {
  SpringDamper out;
  out.stiffness = m.getPositive("stiffness_Nm_per_rad");
  out.damping = m.getNonNegative("damping_Nms_per_rad");
  return out;
}

void checkRemainder(const io::YamlMap& m, const std::string& key, const BodySpec& whole, const BodySpec& part,
                    const std::string& wholeName) {
  const BodySpec r = scenario::calcBodyRemainder(whole, part);
  if (!(r.mass > 0)) m.fail(key, "the moving part's mass must be below " + wholeName + ".mass_kg");
  const std::string why = scenario::checkInertia(r.inertia);
  if (!why.empty()) m.fail(key, wholeName + " without the moving part: " + why);
}

}  // namespace motostab::extensions
