#include "extensions/extension_input.h"

namespace motostab::extensions {

using scenario::BodySpec;

const io::SectionFields& getSpringDamperFields() {
  using io::Field;
  using io::Range;
  static const io::SectionFields f{"", {Field::number("stiffness_Nm_per_rad", "N m/rad", Range::Positive, "k, stiffness"),
                                        Field::number("damping_Nms_per_rad", "N m s/rad", Range::NonNegative, "c, damping")}};
  return f;
}

SpringDamper readSpringDamper(io::YamlMap& m) {
  const io::SectionFields& f = getSpringDamperFields();
  SpringDamper out;
  out.stiffness = io::readNumber(m, f.get("stiffness_Nm_per_rad"));
  out.damping = io::readNumber(m, f.get("damping_Nms_per_rad"));
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
