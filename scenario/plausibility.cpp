#include "scenario/plausibility.h"

#include <cmath>

#include "io/number.h"
#include "io/yaml_map.h"
#include "scenario/whole_vehicle.h"

namespace motostab::scenario {

using Check = ScenarioWarning::Check;

namespace {

// The location of the key at `path` (its deepest existing part) in `tree`.
io::InputLocation locateKey(const YAML::Node& tree, const std::string& file, const std::string& path) {
  io::InputLocation where{file, 0, 0, path};
  YAML::Node node = tree;
  for (const io::KeyPathSegment& seg : io::parseKeyPath(path)) {
    if (!node.IsMap()) break;
    bool found = false;
    for (const auto& kv : node) {
      if (!kv.first.IsScalar() || kv.first.Scalar() != seg.key) continue;
      const YAML::Mark m = kv.first.Mark();
      if (m.line >= 0) where.line = m.line + 1, where.column = m.column + 1;
      node.reset(kv.second);  // rebind (operator= would overwrite the tree)
      found = true;
      break;
    }
    if (!found) break;
  }
  return where;
}

std::string format(double v) { return io::formatNumber(v, 6); }

class Checker {
 public:
  Checker(const YAML::Node& tree, const std::string& file) : tree_(tree), file_(file) {}
  void warn(Check check, const std::string& path, const std::string& message) {
    out_.push_back({check, locateKey(tree_, file_, path), message});
  }
  // Warns when `what` (its `value` in `unit`) lies outside [low, high].
  void range(Check check, const std::string& path, const std::string& what, double value, double low, double high,
             const std::string& unit, const std::string& hint) {
    if (value >= low && value <= high) return;
    warn(check, path, what + " " + format(value) + " " + unit + " lies outside the plausible " + format(low) + " to " +
                          format(high) + " " + unit + ": " + hint);
  }
  const YAML::Node& getTree() const { return tree_; }
  std::vector<ScenarioWarning> take() { return std::move(out_); }

 private:
  const YAML::Node& tree_;
  const std::string& file_;
  std::vector<ScenarioWarning> out_;
};

void checkGeometry(const Scenario& s, Checker& c) {
  const GeometrySpec& g = s.geometry;
  c.range(Check::SteerAxisTilt, "geometry.steer_axis_tilt_deg", "steer-axis tilt", g.steerAxisTilt * 180 / M_PI, 5, 45, "deg",
          "the caster angle from vertical (motorcycles about 20-30 deg, bicycles 15-25): radians given as degrees, or the "
          "head angle (90 deg - caster) given?");
  c.range(Check::Wheelbase, "geometry.wheelbase_m", "wheelbase", g.wheelbase, 0.5, 3, "m", "millimetres given as metres?");
  const std::string trailKey = io::findKeyPath(c.getTree(), "geometry.normal_trail_m") ? "geometry.normal_trail_m" : "geometry.trail_m";
  c.range(Check::Trail, trailKey, "trail", g.trail, -0.1, 0.5, "m", "millimetres given as metres, or the fork offset given?");
  c.range(Check::ForkOffset, trailKey, "fork offset r_F sin(tilt) - normal trail", calcForkOffset(s), -0.1, 0.2, "m",
          "check the trail, the steer-axis tilt and the front radius together");
}

// The whole vehicle: mass, CoM between the contact points and above the ground, pitch the largest
// moment (a vehicle is long and tall but narrow), radii of gyration of a vehicle's size.
void checkWholeVehicle(const Scenario& s, Checker& c) {
  const BodySpec t = calcVehicleTotal(s);
  const std::string key = s.hasTotal ? "total" : "rear_frame";
  c.range(Check::TotalMass, key + ".mass_kg", "the whole vehicle's mass", t.mass, 5, 1000, "kg", "grams given as kilograms?");
  if (!(t.com[0] > 0 && t.com[0] < s.geometry.wheelbase))
    c.warn(Check::CentreOfMass, key + ".com_m",
           "the vehicle's centre of mass (x " + format(t.com[0]) + " m) lies outside the wheelbase (0 to " +
               format(s.geometry.wheelbase) + " m): a static wheel load is negative (x measured from the front contact, or "
               "in millimetres?)");
  if (!(t.com[2] > 0))
    c.warn(Check::CentreOfMass, key + ".com_m",
           "the vehicle's centre of mass (z " + format(t.com[2]) + " m) is not above the ground (z measured downwards?)");
  const InertiaSpec& I = t.inertia;
  if (I.yy < std::max(I.xx, I.zz))
    c.warn(Check::InertiaOrder, key + ".inertia_kgm2",
           "the whole vehicle's pitch moment yy (" + format(I.yy) + " kg m^2) is below its roll xx (" + format(I.xx) +
               ") or yaw zz (" + format(I.zz) + "): a long, narrow vehicle has pitch the largest; roll, pitch and yaw swapped?");
  const double kMax = std::sqrt(std::max({I.xx, I.yy, I.zz}) / t.mass);
  c.range(Check::RadiusOfGyration, key + ".inertia_kgm2", "the whole vehicle's largest radius of gyration sqrt(I/m)", kMax, 0.05, 1.5, "m",
          "inertia in kg cm^2 or g m^2 given as kg m^2?");
}

void checkWheel(const Scenario& s, const WheelSpec& w, const std::string& name, Checker& c) {
  c.range(Check::WheelRadius, name + ".radius_m", "wheel radius", w.radius, 0.1, 0.6, "m", "millimetres given as metres, or a diameter?");
  if (w.axialInertia > w.mass * w.radius * w.radius)
    c.warn(Check::WheelInertia, name + ".spin_inertia_kgm2",
           "spin inertia " + format(w.axialInertia) + " kg m^2 exceeds mass x radius^2 (" +
               format(w.mass * w.radius * w.radius) + "): even a wheel with all its mass at the rim has less");
  if (w.axialInertia < w.diametralInertia)
    c.warn(Check::WheelInertia, name + ".spin_inertia_kgm2",
           "spin inertia " + format(w.axialInertia) + " kg m^2 is below the diametral " + format(w.diametralInertia) +
               ": a wheel spins about its largest moment; spin and diametral swapped?");
  bool assumed = false;
  for (const AssumedValue& a : s.assumed) assumed = assumed || a.key.rfind(name + ".", 0) == 0;
  if (assumed && (w.radius < 0.25 || w.radius > 0.36))
    c.warn(Check::DefaultWheel, name + ".radius_m",
           "the default wheel mass and inertias (assumed: not given) are a 17-inch motorcycle wheel's, but this wheel's "
           "radius is " + format(w.radius) + " m: give its mass_kg, spin_inertia_kgm2 and diametral_inertia_kgm2");
}

// The linear tyre's coefficients against the convention of tyres/relaxation_linear.h (the seed's
// Table 6 signs), where the scenario gives them.
void checkLinearTyres(const Scenario& s, Checker& c) {
  const YAML::Node contact = io::findKeyPath(c.getTree(), "contact");
  if (s.contact.model != "relaxation_linear" || !contact.IsMap()) return;
  for (const char* end : {"front", "rear"}) {
    const YAML::Node t = contact[end];
    if (!t || !t.IsMap()) continue;
    const std::string at = std::string("contact.") + end + ".";
    auto value = [&](const char* key, double& v) {
      if (!t[key] || !t[key].IsScalar()) return false;
      try {
        v = t[key].as<double>();
      } catch (const YAML::Exception&) {
        return false;  // the plugin reports it
      }
      return std::isfinite(v);
    };
    double v = 0;
    if (value("cornering_stiffness_per_rad", v))
      c.range(Check::CorneringStiffness, at + "cornering_stiffness_per_rad", "cornering stiffness per unit load", v, 2, 40, "/rad",
              "per degree given as per radian, or not divided by the load?");
    if (value("camber_stiffness_per_rad", v) && v < 0)
      c.warn(Check::TyreSign, at + "camber_stiffness_per_rad",
             "negative (" + format(v) + "): a leaning tyre pushes towards the lean (positive, tyres/relaxation_linear.h)");
    if (value("self_aligning_stiffness_m_per_rad", v) && v > 0)
      c.warn(Check::TyreSign, at + "self_aligning_stiffness_m_per_rad",
             "positive (" + format(v) + "): the self-aligning moment turns the wheel towards its velocity (negative, "
             "tyres/relaxation_linear.h)");
    if (value("twisting_stiffness_m_per_rad", v) && v < 0)
      c.warn(Check::TyreSign, at + "twisting_stiffness_m_per_rad",
             "negative (" + format(v) + "): the twisting moment turns the wheel towards the lean (positive, "
             "tyres/relaxation_linear.h)");
    if (value("relaxation_length_m", v) && v > 1)
      c.warn(Check::RelaxationLength, at + "relaxation_length_m",
             format(v) + " m is longer than any measured tyre's (0.05-0.5 m): millimetres given as metres?");
    // A carcass stiffness gives sigma = Fz k_alpha / k_y at rest (tyres/relaxation_linear.h).
    double ky = 0, kAlpha = 0;
    if (value("lateral_carcass_stiffness_N_per_m", ky) && ky > 0 && value("cornering_stiffness_per_rad", kAlpha)) {
      const double sigma = calcStaticWheelLoads(s)[end == std::string("front") ? 1 : 0] * kAlpha / ky;
      if (sigma > 1)
        c.warn(Check::RelaxationLength, at + "lateral_carcass_stiffness_N_per_m",
               format(ky) + " N/m gives a relaxation length of " + format(sigma) +
                   " m at the static load, longer than any measured tyre's (0.05-0.5 m): N/mm given as N/m?");
    }
  }
}

}  // namespace

std::vector<ScenarioWarning> checkPlausibility(const Scenario& s, const YAML::Node& tree, const std::string& file) {
  Checker c(tree, file);
  checkGeometry(s, c);
  checkWholeVehicle(s, c);
  checkWheel(s, s.rearWheel, "rear_wheel", c);
  checkWheel(s, s.frontWheel, "front_wheel", c);
  if (s.gravity > 0)
    c.range(Check::Gravity, "gravity_mps2", "gravity", s.gravity, 9.7, 9.9, "m/s^2", "feet per second squared, or g given as 1?");
  checkLinearTyres(s, c);
  return c.take();
}

const char* getCheckName(Check check) {
  switch (check) {
    case Check::SteerAxisTilt: return "steer_axis_tilt";
    case Check::Wheelbase: return "wheelbase";
    case Check::Trail: return "trail";
    case Check::ForkOffset: return "fork_offset";
    case Check::CentreOfMass: return "centre_of_mass";
    case Check::TotalMass: return "total_mass";
    case Check::InertiaOrder: return "inertia_order";
    case Check::RadiusOfGyration: return "radius_of_gyration";
    case Check::WheelRadius: return "wheel_radius";
    case Check::WheelInertia: return "wheel_inertia";
    case Check::DefaultWheel: return "default_wheel";
    case Check::Gravity: return "gravity";
    case Check::TyreSign: return "tyre_sign";
    case Check::CorneringStiffness: return "cornering_stiffness";
    case Check::RelaxationLength: return "relaxation_length";
    case Check::PluginInput: return "plugin_input";
  }
  return "unknown";
}

std::string formatWarning(const ScenarioWarning& w) { return w.where.describe() + ": " + w.message; }

}  // namespace motostab::scenario
