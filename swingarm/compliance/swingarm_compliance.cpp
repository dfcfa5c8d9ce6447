#include "swingarm/compliance/swingarm_compliance.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "multibody/pin_joint.h"
#include "multibody/pin_spring_damper.h"

namespace motostab::swingarm {

using io::YamlMap;
using multibody::addPinAtDesignPose;
using plugins::BuildContext;
using plugins::PluginRegistrar;
using plugins::SwingarmAssembly;
using plugins::SwingarmModel;
using plugins::SwingarmModelFactory;
using plugins::SwingarmSite;
using multibody::addPinSpringDamper;


using SimTK::MobilizedBody;
using SimTK::Transform;
using SimTK::Vec3;

ComplianceAxis makeAxisFromArm(const Vec3& p_SH, double arm, double beta, double k, double c) {
  return {p_SH + arm * Vec3(-std::sin(beta), 0, std::cos(beta)), Vec3(std::cos(beta), 0, std::sin(beta)), k, c};
}

namespace {

// One axis as written in the scenario: {arm_m, beta_deg} or {point_m, direction} in S, with
// stiffness and damping scaled by the swingarm's stiffness_scale and damping_scale.
struct AxisSpec {
  bool explicitAxis = false;
  Vec3 point, direction;
  double arm = 0, beta = 0, stiffness = 0, damping = 0;
  ComplianceAxis toAxis(const Vec3& p_SH) const {
    return explicitAxis ? ComplianceAxis{point, direction, stiffness, damping}
                        : makeAxisFromArm(p_SH, arm, beta, stiffness, damping);
  }
};

constexpr const char* kAxisNames[] = {"bending", "torsion", "twist"};

// What the identification writes beside an axis's model (docs/swingarm-identification.md): checked
// (>= 0), not used. Key, unit, what it is.
struct IdentificationValue {
  const char* key;
  const char* unit;
  const char* meaning;
};
constexpr IdentificationValue kIdentificationValues[] = {
    {"arm_m_stderr", "m", "standard error of `arm_m`"},
    {"beta_deg_stderr", "deg", "standard error of `beta_deg`"},
    {"stiffness_Nm_per_rad_stderr", "N m/rad", "standard error of `stiffness_Nm_per_rad`"},
    {"damping_Nms_per_rad_stderr", "N m s/rad", "standard error of `damping_Nms_per_rad`"},
    {"reduced_stiffness_Nm_per_rad", "N m/rad", "stiffness reduced to the twist axis (seed eq. 11-15)"},
    {"reduced_stiffness_Nm_per_rad_stderr", "N m/rad", "its standard error"},
    {"frequency_hz", "Hz", "natural frequency of the rig mode"},
    {"frequency_hz_stderr", "Hz", "its standard error"},
    {"damping_ratio", "", "damping ratio of the rig mode"},
    {"damping_ratio_stderr", "", "its standard error"}};

bool isGeometryKey(const std::string& key) {
  return key == "arm_m" || key == "beta_deg" || key == "point_m" || key == "direction" || key == "arm_m_stderr" ||
         key == "beta_deg_stderr";
}

// The axis geometry: {arm_m, beta_deg} (relative to the hub) or {point_m, direction} (in S). The
// identification's fragment nests it under `axis:` and gives both; arm and beta are used then.
void readAxisGeometry(YamlMap& m, const io::SectionFields& f, AxisSpec& a) {
  if (m.has("arm_m") || m.has("beta_deg")) {
    // The pair goes together: a missing one is the missing-key error (arm first, as it is read first).
    auto readPaired = [&](const char* k) { return m.has(k) ? io::readNumber(m, f.get(k)) : m.getDouble(k); };
    a.arm = readPaired("arm_m");
    a.beta = readPaired("beta_deg") * M_PI / 180;
    for (const char* k : {"point_m", "direction"})
      if (m.has(k)) io::readVector3(m, f.get(k));
  } else {
    const auto p = io::readVector3(m, f.get("point_m"));
    const auto d = io::readVector3(m, f.get("direction"));
    a.explicitAxis = true;
    a.point = Vec3(p[0], p[1], p[2]);
    a.direction = Vec3(d[0], d[1], d[2]);
    if (a.direction.norm() < 1e-9) m.fail("direction", "must not be zero");
    a.direction /= a.direction.norm();
  }
}

// The identification's values present in `m` whose keys pass `keep` (checked, not used).
template <class Keep>
void checkIdentificationValues(YamlMap& m, const io::SectionFields& f, Keep keep) {
  for (const IdentificationValue& v : kIdentificationValues)
    if (keep(std::string(v.key)) && m.has(v.key)) io::readNumber(m, f.get(v.key));
}

AxisSpec readAxis(YamlMap m, const io::SectionFields& f, double kScale, double cScale) {
  AxisSpec a;
  a.stiffness = io::readNumber(m, f.get("stiffness_Nm_per_rad")) * kScale;
  a.damping = io::readNumber(m, f.get("damping_Nms_per_rad")) * cScale;
  if (m.has("axis")) {
    YamlMap axis = m.getMap("axis");
    readAxisGeometry(axis, f, a);
    checkIdentificationValues(axis, f, isGeometryKey);
    axis.finish();
  } else {
    readAxisGeometry(m, f, a);
  }
  checkIdentificationValues(m, f, [&](const std::string& key) { return !m.has("axis") || !isGeometryKey(key); });
  m.finish();
  return a;
}

// Adds a revolute compliance joint about `axis` (in S) with its spring and damper; the child's
// body frame coincides with S at the design pose, whose pose in the parent is X_PS.
MobilizedBody::Pin addComplianceJoint(BuildContext& ctx, MobilizedBody& parent, const Transform& X_PS,
                                      const SimTK::Body& body, const ComplianceAxis& axis) {
  MobilizedBody::Pin pin = addPinAtDesignPose(parent, X_PS, body, axis.point_S, axis.direction_S);
  addPinSpringDamper(ctx.forces, pin, axis.stiffness, axis.damping);
  return pin;
}

Transform hubFrame(const SwingarmSite& site) { return Transform(~site.X_RS.R(), site.p_SH); }

class RigidSwingarm : public SwingarmModel {
 public:
  SwingarmAssembly addSwingarm(BuildContext&, const SwingarmSite& site) override {
    MobilizedBody parent = site.rearFrame;
    MobilizedBody::Weld arm(parent, site.X_RS, site.body, Transform());
    return {arm, hubFrame(site), {}};
  }
};

// The role of a compliance axis by its key: bending, torsion or twist.
plugins::StateRole getRole(const std::string& key) {
  if (key == "bending") return plugins::StateRole::SwingarmBending;
  if (key == "torsion") return plugins::StateRole::SwingarmTorsion;
  if (key == "twist") return plugins::StateRole::SwingarmTwist;
  return plugins::StateRole::Compliance;
}

// One or two compliance DOFs in series, from the rear frame to the hub.
class CompliantSwingarm : public SwingarmModel {
 public:
  CompliantSwingarm(std::vector<std::pair<std::string, AxisSpec>> axes) : axes_(std::move(axes)) {}
  SwingarmAssembly addSwingarm(BuildContext& ctx, const SwingarmSite& site) override {
    SwingarmAssembly out;
    MobilizedBody parent = site.rearFrame;
    Transform X_PS = site.X_RS;
    for (size_t i = 0; i < axes_.size(); ++i) {
      // The first joint carries the swingarm's mass; later ones a massless hub carrier.
      const SimTK::Body body = i == 0 ? SimTK::Body(site.body) : SimTK::Body(SimTK::Body::Massless());
      MobilizedBody::Pin pin = addComplianceJoint(ctx, parent, X_PS, body, axes_[i].second.toAxis(site.p_SH));
      out.coordinates.push_back({"swingarm_" + axes_[i].first, getRole(axes_[i].first), pin});
      parent = pin;
      X_PS = Transform();
    }
    out.hubCarrier = parent;
    out.X_CH = hubFrame(site);
    return out;
  }

 private:
  std::vector<std::pair<std::string, AxisSpec>> axes_;
};

}  // namespace

const io::SectionFields& getSwingarmModelFields() {
  using io::Field;
  using io::Range;
  using io::Shape;
  auto axis = [](const char* name) {
    return Field::of(Shape::Other, name, "", "", std::string(name) + " axis with its stiffness and damping (section `swingarm." +
                                                     name + "`); every axis present is validated, the model uses those it names")
        .optional();
  };
  static const io::SectionFields f{
      "swingarm",
      {axis("bending"), axis("torsion"), axis("twist"),
       Field::number("stiffness_scale", "", Range::Positive, "factor on every axis stiffness, for sensitivity studies (seed Fig. 11: 0.5)")
           .withDefault(1),
       Field::number("damping_scale", "", Range::NonNegative,
                     "factor on every axis damping, for sensitivity studies (seed Fig. 11: 1/sqrt 2)")
           .withDefault(1),
       Field::of(Shape::Other, "axes_from", "", "", "a file written by `motostab identify swingarm` whose axes are used where "
                                                  "the section gives none (path relative to the scenario)")
           .optional(),
       Field::of(Shape::Other, "identification", "", "", "provenance of identified axes, not read").optional()}};
  return f;
}

const io::SectionFields& getSwingarmAxisFields(const std::string& name) {
  using io::Field;
  using io::Range;
  using io::Shape;
  auto make = [](const std::string& axis) {
    io::SectionFields s{
        "swingarm." + axis,
        {Field::number("stiffness_Nm_per_rad", "N m/rad", Range::Positive,
                       "lumped stiffness about the " + axis + " axis (seed sec. 4), times `swingarm.stiffness_scale`"),
         Field::number("damping_Nms_per_rad", "N m s/rad", Range::NonNegative,
                       "lumped damping about the axis, times `swingarm.damping_scale`"),
         Field::number("arm_m", "m", Range::Any, "a, signed distance of the axis from the hub (seed eq. 2-10, Fig. 8); with `beta_deg`")
             .optional(),
         Field::number("beta_deg", "deg", Range::Any,
                       "beta, the axis direction (cos beta, 0, sin beta) in S, through hub + a (-sin beta, 0, cos beta)")
             .optional(),
         Field::of(Shape::Vector3, "point_m", "m", "", "a point of the axis in S, instead of `arm_m` and `beta_deg`").optional(),
         Field::of(Shape::Vector3, "direction", "", "not zero", "the axis direction in S (normalised), with `point_m`").optional(),
         Field::of(Shape::Other, "axis", "", "", "the geometry keys of this table and their standard errors nested, as "
                                                 "`motostab identify swingarm` writes them (`arm_m`, `beta_deg` used when given)")
             .optional()}};
    for (const IdentificationValue& v : kIdentificationValues)
      s.fields.push_back(
          Field::number(v.key, v.unit, Range::NonNegative, std::string(v.meaning) + "; from the identification, checked, not used")
              .optional());
    return s;
  };
  static const std::vector<io::SectionFields> all = [&] {
    std::vector<io::SectionFields> out;
    for (const char* axis : kAxisNames) out.push_back(make(axis));
    return out;
  }();
  for (const io::SectionFields& s : all)
    if (s.path == "swingarm." + name) return s;
  throw std::logic_error("no swingarm compliance axis " + name);
}

namespace {

// Every axis mapping present is validated; the model uses those it names.
SwingarmModelFactory makeFactory(std::vector<std::string> axisNames) {
  return [axisNames](YamlMap& m) -> std::unique_ptr<SwingarmModel> {
    const io::SectionFields& f = getSwingarmModelFields();
    const double kScale = io::readNumber(m, f.get("stiffness_scale")), cScale = io::readNumber(m, f.get("damping_scale"));
    std::vector<std::pair<std::string, AxisSpec>> present;
    for (const char* key : kAxisNames)
      if (m.has(key)) present.push_back({key, readAxis(m.getMap(key), getSwingarmAxisFields(key), kScale, cScale)});
    if (m.has("identification")) m.markUsed("identification");  // provenance only
    // Axes written by `motostab identify swingarm`, used unchanged (path relative to the scenario);
    // read once, when the scenario is loaded (io/input_store.h), and kept for every later build.
    if (m.has("axes_from")) {
      YamlMap fragment = m.loadFileMap("axes_from");
      if (fragment.has("identification")) fragment.markUsed("identification");
      for (const char* key : kAxisNames) {
        const bool inline_ = std::any_of(present.begin(), present.end(), [&](const auto& p) { return p.first == key; });
        if (fragment.has(key) && !inline_) present.push_back({key, readAxis(fragment.getMap(key), getSwingarmAxisFields(key), kScale, cScale)});
        else if (fragment.has(key)) fragment.markUsed(key);
      }
      fragment.finish();
    }
    std::vector<std::pair<std::string, AxisSpec>> axes;
    for (const auto& name : axisNames) {
      auto it = std::find_if(present.begin(), present.end(), [&](const auto& p) { return p.first == name; });
      if (it == present.end()) m.fail("", "compliance '" + name + "' needs a '" + name + "' axis mapping");
      axes.push_back(*it);
    }
    if (axes.empty()) return std::make_unique<RigidSwingarm>();
    return std::make_unique<CompliantSwingarm>(axes);
  };
}

}  // namespace

void registerSwingarmModels(PluginRegistrar& registry) {
  registry.addSectionFields(getSwingarmModelFields());
  for (const char* axis : kAxisNames) registry.addSectionFields(getSwingarmAxisFields(axis));
  registry.addSwingarmModel("rigid", makeFactory({}));
  registry.addSwingarmModel("bending", makeFactory({"bending"}));
  registry.addSwingarmModel("torsion", makeFactory({"torsion"}));
  registry.addSwingarmModel("twist", makeFactory({"twist"}));
  registry.addSwingarmModel("bending+torsion", makeFactory({"bending", "torsion"}));
}

}  // namespace motostab::swingarm
