#include "scenario/extension_specs.h"

#include <Eigen/Dense>

#include <cmath>

#include "io/number.h"
#include "scenario/whole_vehicle.h"

namespace motostab::scenario {

using io::YamlMap;
using io::parseFiniteNumber;

namespace {

// Fails at `key` unless the remainder of `whole` without `part` is a valid body.
void checkRemainder(const YamlMap& m, const std::string& key, const BodySpec& whole, const BodySpec& part,
                    const std::string& wholeName) {
  const BodySpec r = calcBodyRemainder(whole, part);
  if (!(r.mass > 0)) m.fail(key, "the moving part's mass must be below " + wholeName + ".mass_kg");
  const std::string why = checkInertia(r.inertia);
  if (!why.empty()) m.fail(key, wholeName + " without the moving part: " + why);
}

// {stiffness_Nm_per_rad > 0, damping_Nms_per_rad >= 0} of one spring-damper.
void readSpringDamper(YamlMap& m, double& stiffness, double& damping) {
  stiffness = m.getPositive("stiffness_Nm_per_rad");
  damping = m.getNonNegative("damping_Nms_per_rad");
}

}  // namespace

double calcDefaultForkAxisDistance(const Scenario& s) {
  return 2 * s.frontWheel.radius / std::cos(s.geometry.steerAxisTilt);
}

SteerDamperSpec readSteerDamper(YamlMap m) {
  SteerDamperSpec d;
  d.damping = m.getNonNegative("damping_Nms_per_rad");
  if (m.has("coulomb_Nm")) d.coulomb = m.getNonNegative("coulomb_Nm");
  if (m.has("coulomb_smoothing_rad_per_s")) d.coulombSmoothing = m.getPositive("coulomb_smoothing_rad_per_s");
  m.finish();
  return d;
}

namespace {

// `schedule: {below_mps: v0}` or `schedule: {table: [[v, f], ...]}` (speeds strictly increasing).
void readSchedule(YamlMap m, SteerControllerSpec& c) {
  if (m.has("below_mps") == m.has("table")) m.fail("", "give exactly one of below_mps and table");
  if (m.has("below_mps")) {
    c.schedule = SteerControllerSpec::Schedule::Below;
    c.scheduleBelow = m.getPositive("below_mps");
  } else {
    c.schedule = SteerControllerSpec::Schedule::Table;
    const YAML::Node t = m.getNode()["table"];
    m.markUsed("table");
    if (!t.IsSequence() || t.size() < 2) m.fail("table", "expected a list of at least two [speed_mps, factor] rows");
    for (size_t i = 0; i < t.size(); ++i) {
      std::array<double, 2> row{0, 0};
      if (!t[i].IsSequence() || t[i].size() != 2) m.failElement("table", i, "expected [speed_mps, factor]");
      for (size_t j = 0; j < 2; ++j) {
        const auto v = t[i][j].IsScalar() ? parseFiniteNumber(t[i][j].Scalar()) : std::nullopt;
        if (!v) m.failElement("table", i, "expected finite numbers [speed_mps, factor]");
        row[j] = *v;
      }
      if (i > 0 && !(row[0] > c.scheduleTable.back()[0]))
        m.failElement("table", i, "speeds must increase strictly (not sorted by speed)");
      c.scheduleTable.push_back(row);
    }
  }
  m.finish();
}

}  // namespace

const std::vector<std::string>& getSteerControllerScalarKeys() {
  static const std::vector<std::string> keys{"roll_angle_Nm_per_rad", "roll_rate_Nms_per_rad", "steer_angle_Nm_per_rad",
                                             "steer_rate_Nms_per_rad", "gain_factor", "delay_s", "torque_limit_Nm"};
  return keys;
}

SteerControllerSpec readSteerController(YamlMap m) {
  SteerControllerSpec c;
  c.rollAngleGain = m.getDouble("roll_angle_Nm_per_rad", 0);
  c.rollRateGain = m.getDouble("roll_rate_Nms_per_rad", 0);
  c.steerAngleGain = m.getDouble("steer_angle_Nm_per_rad", 0);
  c.steerRateGain = m.getDouble("steer_rate_Nms_per_rad", 0);
  c.gainFactor = m.getPositive("gain_factor", 1);
  if (m.has("schedule")) readSchedule(m.getMap("schedule"), c);
  c.delay = m.getZeroOrAtLeast("delay_s", kMinSteerDelay, "s", 0);
  if (m.has("torque_limit_Nm")) c.torqueLimit = m.getPositive("torque_limit_Nm");
  m.finish();
  return c;
}

ForkComplianceSpec readForkCompliance(YamlMap m, const Scenario& s) {
  ForkComplianceSpec f;
  readSpringDamper(m, f.stiffness, f.damping);
  f.axisDistance = m.has("axis_distance_along_steer_m") ? m.getDouble("axis_distance_along_steer_m")
                                                        : calcDefaultForkAxisDistance(s);
  if (m.has("carrier") && m.has("carrier_mass_fraction"))
    m.fail("carrier_mass_fraction", "give only one of carrier and carrier_mass_fraction");
  std::string carrierKey = "carrier_mass_fraction";
  if (m.has("carrier")) {
    YamlMap c = m.getMap("carrier");
    f.carrier = readBodyKeys(c);
    c.finish();
    carrierKey = "carrier";
  } else {
    f.carrierFraction = m.has(carrierKey) ? m.getPositive(carrierKey) : kDefaultForkCarrierFraction;
    if (f.carrierFraction >= 1) m.fail(carrierKey, "must be below 1");
    f.carrier = calcDefaultForkCarrier(s, f.carrierFraction);
  }
  checkRemainder(m, carrierKey, s.frontFrame, f.carrier, "front_frame");
  if (m.has("torsion")) {
    YamlMap t = m.getMap("torsion");
    f.hasTorsion = true;
    readSpringDamper(t, f.torsionStiffness, f.torsionDamping);
    t.finish();
  }
  m.finish();
  return f;
}

RiderLeanSpec readRiderLean(YamlMap m, const Scenario& s) {
  RiderLeanSpec r;
  r.hingeHeight = m.getPositive("hinge_height_m");
  r.body = readBodyKeys(m);
  readSpringDamper(m, r.stiffness, r.damping);
  if (r.body.com[1] != 0) m.fail("com_m", "the upper body's centre of mass must lie in the plane of symmetry (y = 0)");
  checkRemainder(m, "mass_kg", s.rearFrame, r.body, "rear_frame");
  m.finish();
  return r;
}

RiderArmsSpec readRiderArms(YamlMap m, const Scenario& s) {
  RiderArmsSpec a;
  a.inertia = m.getPositive("inertia_kgm2");
  a.stiffness = m.getNonNegative("stiffness_Nm_per_rad");
  a.damping = m.getNonNegative("damping_Nms_per_rad");
  if (m.has("grip_half_width_m")) a.gripHalfWidth = m.getPositive("grip_half_width_m");
  // The steer axis through its ground point (w + c, 0, 0) along n = (-sin lambda, 0, cos lambda); the
  // grips at the point of it nearest the front frame's CoM, +/- d along y (distance d from the axis).
  const double lambda = s.geometry.steerAxisTilt;
  const Eigen::Vector3d p0(s.geometry.wheelbase + s.geometry.trail, 0, 0), n(-std::sin(lambda), 0, std::cos(lambda));
  const Eigen::Vector3d g = p0 + n * n.dot(Eigen::Vector3d(s.frontFrame.com[0], 0, s.frontFrame.com[2]) - p0);
  const double d = a.gripHalfWidth, mass = a.inertia / (d * d);  // two grips of mass/2 each at distance d
  a.body.mass = mass;
  a.body.com = {g(0), 0, g(2)};
  a.body.inertia = {mass * d * d, 0, mass * d * d, 0, 0, 0};  // about any axis in the x-z plane: m d^2
  checkRemainder(m, "inertia_kgm2", s.rearFrame, a.body, "rear_frame");
  m.finish();
  return a;
}

void readExtensions(YamlMap& root, Scenario& s) {
  if (root.has("steer_damper")) {
    s.hasSteerDamper = true;
    s.steerDamper = readSteerDamper(root.getMap("steer_damper"));
  }
  if (root.has("fork_compliance")) {
    s.hasForkCompliance = true;
    s.forkCompliance = readForkCompliance(root.getMap("fork_compliance"), s);
  }
  if (root.has("rider_lean")) {
    s.hasRiderLean = true;
    s.riderLean = readRiderLean(root.getMap("rider_lean"), s);
  }
  if (root.has("steer_controller")) {
    s.hasSteerController = true;
    s.steerController = readSteerController(root.getMap("steer_controller"));
  }
  if (root.has("rider_arms")) {  // last: the grips move from the rear frame (and rider) to the front frame
    s.hasRiderArms = true;
    s.riderArms = readRiderArms(root.getMap("rider_arms"), s);
    s.rearFrame = calcBodyRemainder(s.rearFrame, s.riderArms.body);
    s.frontFrame = composeBodies({s.frontFrame, s.riderArms.body});
  }
}

}  // namespace motostab::scenario
