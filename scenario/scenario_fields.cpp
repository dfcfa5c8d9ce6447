#include "scenario/scenario_fields.h"

namespace motostab::scenario {

using io::Field;
using io::Quantity;
using io::Range;
using io::SectionFields;
using io::Shape;

namespace {

std::vector<Field> makeBodyFieldList(const std::string& what) {
  return {Field::number("mass_kg", "kg", Range::Positive, "mass of the " + what).measures(Quantity::Mass),
          Field::of(Shape::Vector3, "com_m", "m", "", "centre of mass").measures(Quantity::Length),
          Field::of(Shape::Inertia, "inertia_kgm2", "kg m^2", "positive definite, triangle inequality",
                    "inertia tensor about the centre of mass; all six entries")
              .measures(Quantity::Inertia)};
}

}  // namespace

const SectionFields& getTopLevelFields() {
  auto section = [](const char* key, const std::string& meaning) { return Field::of(Shape::Other, key, "", "", meaning); };
  static const SectionFields f{
      "",
      {section("name", "study name, the default output folder's name"),
       section("description", "free text").optional(),
       Field::number("gravity_mps2", "m/s^2", Range::NonNegative, "gravity, acting along -z"),
       section("speeds_mps", "the default sweep range (section `speeds_mps`); absent: 0 to 10 by 0.1").optional(),
       section("geometry", "wheelbase, trail and steer axis tilt (section `geometry`)"),
       section("total", "the whole vehicle with rider, instead of `rear_frame` (section `total`); the rear frame is derived")
           .optional(),
       section("rear_frame", "rear frame with rigid rider (section `rear_frame`); or `total`").optional(),
       section("front_frame", "front frame (section `front_frame`); beside `total` optional, a motorcycle's assumed")
           .optional(),
       section("rear_wheel", "rear wheel (section `rear_wheel`)"),
       section("front_wheel", "front wheel (section `front_wheel`)"),
       section("contact", "`{model: NAME, ...}`: the contact plugin of that name reads the rest"),
       section("swingarm", "swingarm between rear frame and rear wheel (section `swingarm`); absent: the rear wheel on the rear frame")
           .optional(),
       section("plugins", "shared libraries loaded before the model is built, by path relative to this file (docs/plugins.md)")
           .optional(),
       section("uncertainty", "standard deviations of parameters, keyed by the paths `--set` takes (docs/uncertainty.md)")
           .optional()}};
  return f;
}

const SectionFields& getSpeedRangeFields() {
  static const SectionFields f{"speeds_mps",
                               {Field::number("start", "m/s", Range::NonNegative, "lowest speed"),
                                Field::number("stop", "m/s", Range::NonNegative, "highest speed, at least `start` and at most 150"),
                                Field::number("step", "m/s", Range::Positive, "step; at most 10000 speeds")}};
  return f;
}

const SectionFields& getGeometryFields() {
  static const SectionFields f{
      "geometry",
      {Field::number("wheelbase_m", "m", Range::Positive, "w, distance between the contact points").measures(Quantity::Length),
       Field::number("trail_m", "m", Range::Any,
                     "c, distance of the front contact point behind where the steer axis meets the ground; give exactly "
                     "one of `trail_m` and `normal_trail_m`")
           .optional()
           .keepingSign()
           .measures(Quantity::Length),
       Field::number("normal_trail_m", "m", Range::Any, "trail x cos(steer_axis_tilt), instead of `trail_m`")
           .optional()
           .keepingSign()
           .measures(Quantity::Length),
       Field::number("steer_axis_tilt_deg", "deg", Range::Any,
                     "lambda, steer axis angle from vertical (caster angle), top towards the rear")
           .within("-90 < x < 90")
           .measures(Quantity::Angle)}};
  return f;
}

SectionFields makeBodyFields(const std::string& path, const std::string& what) { return {path, makeBodyFieldList(what)}; }

namespace {

// The whole vehicle: its centre of mass between the contact points (else a wheel load is negative).
SectionFields makeTotalFields() {
  SectionFields s = makeBodyFields("total", "whole vehicle with rider");
  for (Field& f : s.fields)
    if (f.key == "com_m") f = f.within("0 < x < wheelbase_m");
  return s;
}

}  // namespace

SectionFields makeWheelFields(const std::string& path) {
  return {path,
          {Field::number("radius_m", "m", Range::Positive, "outer rolling radius; the wheel centre sits this high at rest")
               .measures(Quantity::Length),
           Field::number("crown_radius_m", "m", Range::Any, "tyre cross-section radius; 0 is a knife edge")
               .within("0 <= x < radius_m")
               .keepingSign()
               .measures(Quantity::Length),
           Field::number("mass_kg", "kg", Range::Positive, "mass (beside `total`: optional, a motorcycle wheel assumed)")
               .measures(Quantity::Mass),
           Field::number("spin_inertia_kgm2", "kg m^2", Range::Positive,
                         "moment of inertia about the axle, at most twice the diametral (beside `total`: optional, as the mass)")
               .measures(Quantity::Inertia),
           Field::number("diametral_inertia_kgm2", "kg m^2", Range::Positive,
                         "moment of inertia about a diameter (beside `total`: optional, as the mass)")
               .measures(Quantity::Inertia)}};
}

const SectionFields& getSwingarmFields() {
  static const SectionFields f = [] {
    SectionFields s{"swingarm", {Field::of(Shape::Vector3, "pivot_m", "m", "ahead of the rear wheel centre", "pivot in D")
                                     .measures(Quantity::Length)}};
    for (const Field& b : makeBodyFieldList("swingarm (in S)")) s.fields.push_back(b);
    s.fields.push_back(Field::of(Shape::Other, "compliance", "", "", "compliance plugin: `rigid`, `bending`, `torsion`, `twist`, `bending+torsion`"));
    s.fields.push_back(Field::of(Shape::Other, "suspension", "", "", "rear suspension at the pivot (model extension `swingarm.suspension`); absent: the pivot is rigid in-plane")
                           .optional());
    return s;
  }();
  return f;
}

const std::vector<SectionFields>& getScenarioFields() {
  static const std::vector<SectionFields> all{getTopLevelFields(),
                                              getSpeedRangeFields(),
                                              getGeometryFields(),
                                              makeTotalFields(),
                                              makeBodyFields("rear_frame", "rear frame with rigid rider"),
                                              makeBodyFields("front_frame", "front frame (fork, handlebar)"),
                                              makeWheelFields("rear_wheel"),
                                              makeWheelFields("front_wheel"),
                                              getSwingarmFields()};
  return all;
}

}  // namespace motostab::scenario
