#include "swingarm/compliance/swingarm_compliance.h"

#include <algorithm>
#include <filesystem>

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

// The axis geometry: {arm_m, beta_deg} (relative to the hub) or {point_m, direction} (in S). The
// identification's fragment nests it under `axis:` and gives both; arm and beta are used then.
void readAxisGeometry(YamlMap& m, AxisSpec& a) {
  if (m.has("arm_m") || m.has("beta_deg")) {
    a.arm = m.getDouble("arm_m");
    a.beta = m.getDouble("beta_deg") * M_PI / 180;
    for (const char* k : {"point_m", "direction"})
      if (m.has(k)) m.getVec3(k);
  } else {
    const auto p = m.getVec3("point_m");
    const auto d = m.getVec3("direction");
    a.explicitAxis = true;
    a.point = Vec3(p[0], p[1], p[2]);
    a.direction = Vec3(d[0], d[1], d[2]);
    if (a.direction.norm() < 1e-9) m.fail("direction", "must not be zero");
    a.direction /= a.direction.norm();
  }
  for (const char* k : {"arm_m_stderr", "beta_deg_stderr"})
    if (m.has(k)) m.getNonNegative(k);
}

AxisSpec readAxis(YamlMap m, double kScale, double cScale) {
  AxisSpec a;
  a.stiffness = m.getPositive("stiffness_Nm_per_rad") * kScale;
  a.damping = m.getNonNegative("damping_Nms_per_rad") * cScale;
  if (m.has("axis")) {
    YamlMap axis = m.getMap("axis");
    readAxisGeometry(axis, a);
    axis.finish();
  } else {
    readAxisGeometry(m, a);
  }
  // Informational values the identification writes beside the model (docs/swingarm-identification.md).
  for (const char* k : {"stiffness_Nm_per_rad_stderr", "damping_Nms_per_rad_stderr", "reduced_stiffness_Nm_per_rad",
                        "reduced_stiffness_Nm_per_rad_stderr", "frequency_hz", "frequency_hz_stderr", "damping_ratio",
                        "damping_ratio_stderr"})
    if (m.has(k)) m.getNonNegative(k);
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
  const std::string axis =
      " axis: `{arm_m, beta_deg}` (seed eq. 2-10, Fig. 8) or `{point_m, direction}` in S, with `stiffness_Nm_per_rad`, "
      "`damping_Nms_per_rad` and optional `*_stderr`; every axis present is validated, the model uses those it names";
  static const io::SectionFields f{
      "swingarm",
      {Field::of(Shape::Other, "bending", "", "", "bending" + axis).optional(),
       Field::of(Shape::Other, "torsion", "", "", "torsion" + axis).optional(),
       Field::of(Shape::Other, "twist", "", "", "twist" + axis).optional(),
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

namespace {

// Every axis mapping present is validated; the model uses those it names.
SwingarmModelFactory makeFactory(std::vector<std::string> axisNames) {
  return [axisNames](YamlMap& m) -> std::unique_ptr<SwingarmModel> {
    const io::SectionFields& f = getSwingarmModelFields();
    const double kScale = io::readNumber(m, f.get("stiffness_scale")), cScale = io::readNumber(m, f.get("damping_scale"));
    std::vector<std::pair<std::string, AxisSpec>> present;
    for (const char* key : {"bending", "torsion", "twist"})
      if (m.has(key)) present.push_back({key, readAxis(m.getMap(key), kScale, cScale)});
    if (m.has("identification")) m.markUsed("identification");  // provenance only
    // Axes written by `motostab identify swingarm`, used unchanged (path relative to the scenario);
    // read once, when the scenario is loaded (io/input_store.h), and kept for every later build.
    if (m.has("axes_from")) {
      YamlMap fragment = m.loadFileMap("axes_from");
      if (fragment.has("identification")) fragment.markUsed("identification");
      for (const char* key : {"bending", "torsion", "twist"}) {
        const bool inline_ = std::any_of(present.begin(), present.end(), [&](const auto& p) { return p.first == key; });
        if (fragment.has(key) && !inline_) present.push_back({key, readAxis(fragment.getMap(key), kScale, cScale)});
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
  registry.addSwingarmModel("rigid", makeFactory({}));
  registry.addSwingarmModel("bending", makeFactory({"bending"}));
  registry.addSwingarmModel("torsion", makeFactory({"torsion"}));
  registry.addSwingarmModel("twist", makeFactory({"twist"}));
  registry.addSwingarmModel("bending+torsion", makeFactory({"bending", "torsion"}));
}

}  // namespace motostab::swingarm
