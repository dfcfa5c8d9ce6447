#include "scenario/scenario.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>

#include "scenario/parameter_paths.h"
#include "scenario/plausibility.h"
#include "scenario/scenario_fields.h"
#include "scenario/scenario_source.h"
#include "io/csv.h"
#include "io/number.h"
#include "io/output_folder.h"
#include "scenario/whole_vehicle.h"
#include "io/yaml_map.h"

namespace motostab::scenario {

using io::InputError;
using io::YamlMap;
using io::readNumber;
using io::readVector3;

namespace {

InertiaSpec readInertia(YamlMap m) {
  InertiaSpec I;
  I.xx = m.getDouble("xx");
  I.yy = m.getDouble("yy");
  I.zz = m.getDouble("zz");
  I.xy = m.getDouble("xy");
  I.xz = m.getDouble("xz");
  I.yz = m.getDouble("yz");
  m.finish();
  const std::string why = checkInertia(I);
  if (!why.empty()) m.fail("", why);
  return I;
}

}  // namespace

BodySpec readBodyKeys(YamlMap& m) {
  static const io::SectionFields f = makeBodyFields("", "body");
  BodySpec b;
  b.mass = readNumber(m, f.get("mass_kg"));
  b.com = readVector3(m, f.get("com_m"));
  b.inertia = readInertia(m.getMap(f.get("inertia_kgm2").key));
  return b;
}

namespace {

BodySpec readBody(YamlMap m) {
  const BodySpec b = readBodyKeys(m);
  m.finish();
  return b;
}

std::string formatAssumed(double value, const std::string& unit) { return io::formatNumber(value, 6) + " " + unit; }

// A wheel. With `assumed` (a scenario with `total:`) its mass and inertias may be left out: the
// defaults of getDefaultWheel, each recorded in `assumed`.
WheelSpec readWheel(YamlMap m, bool front, std::vector<AssumedValue>* assumed) {
  const WheelDefaults d = getDefaultWheel(front);
  static const io::SectionFields f = makeWheelFields("");
  auto readOrAssume = [&](const std::string& key, double fallback, const std::string& unit) {
    if (!assumed || m.has(key)) return readNumber(m, f.get(key));
    assumed->push_back({m.getPath() + "." + key, formatAssumed(fallback, unit), kWholeVehicleDefaultSource});
    return fallback;
  };
  WheelSpec w;
  w.radius = readNumber(m, f.get("radius_m"));
  w.crownRadius = m.getNonNegative(f.get("crown_radius_m").key);
  if (w.crownRadius >= w.radius) m.fail("crown_radius_m", "must be smaller than radius_m");
  w.mass = readOrAssume("mass_kg", d.mass, "kg");
  w.axialInertia = readOrAssume("spin_inertia_kgm2", d.axialInertia, "kg m^2");
  w.diametralInertia = readOrAssume("diametral_inertia_kgm2", d.diametralInertia, "kg m^2");
  // A wheel is a body of revolution: principal moments (A, D, D) need A <= 2D.
  if (w.axialInertia > 2 * w.diametralInertia)
    m.fail("spin_inertia_kgm2", "violates the triangle inequality: spin inertia exceeds twice the diametral inertia");
  m.finish();
  return w;
}

// Centre of mass of the swingarm in D, m.
Vec3d calcSwingarmCom(const Scenario& s) {
  const SwingarmFrame f = calcSwingarmFrame(s);
  const Vec3d& c_S = s.swingarm.body.com;
  Vec3d c = f.origin;
  for (int i = 0; i < 3; ++i) c[i] += f.x[i] * c_S[0] + f.y[i] * c_S[1] + f.z[i] * c_S[2];
  return c;
}

// One entry of the uncertainty section: `path: sigma` or `path: {sigma: s, distribution: d}`.
ParameterUncertainty readUncertaintyEntry(YamlMap& m, const std::string& path) {
  using D = ParameterUncertainty::Distribution;
  ParameterUncertainty u;
  u.path = path;
  u.where = m.locate(path);
  if (m.getNode()[path].IsMap()) {
    YamlMap e = m.getMap(path);
    u.sigma = e.getNonNegative("sigma");
    const std::string d = e.getString("distribution", "normal");
    if (d == "uniform") u.distribution = D::Uniform;
    else if (d == "lognormal") u.distribution = D::Lognormal;
    else if (d != "normal") e.fail("distribution", "expected normal, uniform or lognormal (got '" + d + "')");
    e.finish();
  } else {
    u.sigma = m.getNonNegative(path);
  }
  return u;
}

// The `uncertainty:` section: key paths as --set takes them, each naming a number of the scenario
// tree (checked with getScalarParameter), with a standard deviation >= 0 in the key's own unit.
std::vector<ParameterUncertainty> readUncertainty(YamlMap m, const YAML::Node& tree) {
  std::vector<ParameterUncertainty> out;
  for (const auto& kv : m.getNode()) {
    const std::string path = kv.first.as<std::string>();
    if (path == "uncertainty" || path.rfind("uncertainty.", 0) == 0 || path.rfind("uncertainty[", 0) == 0)
      m.fail(path, "an uncertainty cannot refer to the uncertainty section");
    try {
      getScalarParameter(tree, path);
    } catch (const InputError& e) {
      m.fail(path, "not a numeric parameter of the scenario: " + e.getReason());
    }
    out.push_back(readUncertaintyEntry(m, path));
  }
  m.finish();
  return out;
}

}  // namespace

long countSpeeds(double start, double stop, double step, std::string& why) {
  why.clear();
  if (!(std::isfinite(start) && std::isfinite(stop) && std::isfinite(step) && start >= 0 && stop >= start && step > 0))
    why = "expected finite numbers with 0 <= start <= stop and step > 0";
  else if (stop > SpeedRange::kMaxSpeed)
    why = "speeds above " + io::formatNumber(SpeedRange::kMaxSpeed) + " m/s (540 km/h) are beyond any vehicle";
  const double steps = why.empty() ? std::floor((stop - start) / step + 1e-9) : 0;
  if (why.empty() && !(steps + 1 <= SpeedRange::kMaxSpeeds))
    why = "gives " + io::formatNumber(steps + 1, 6) + " speeds; at most " + std::to_string(SpeedRange::kMaxSpeeds) +
          " (each speed keeps a trim and a linear model in memory): a larger step or a narrower range";
  return why.empty() ? static_cast<long>(steps) + 1 : 0;
}

const std::vector<std::string>& getSwingarmLoaderKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const io::Field& f : getSwingarmFields().fields) k.push_back(f.key);
    return k;
  }();
  return keys;
}

std::string checkInertia(const InertiaSpec& I) {
  Eigen::Matrix3d M;
  M << I.xx, I.xy, I.xz, I.xy, I.yy, I.yz, I.xz, I.yz, I.zz;
  const Eigen::Vector3d p = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(M).eigenvalues();
  if (p.minCoeff() <= 0) return "inertia tensor is not positive definite (principal moments " +
                                std::to_string(p(0)) + ", " + std::to_string(p(1)) + ", " +
                                std::to_string(p(2)) + " kg m^2)";
  const double tol = 1e-12 * p.sum();
  if (p(0) + p(1) < p(2) - tol)
    return "inertia tensor violates the triangle inequality (principal moments " + std::to_string(p(0)) +
           " + " + std::to_string(p(1)) + " < " + std::to_string(p(2)) + " kg m^2)";
  return "";
}

namespace {

// The key path an override "a.b=value" sets ("a.b").
std::string getOverridePath(const std::string& assignment) { return assignment.substr(0, assignment.find('=')); }

Scenario readScenario(const std::string& file, YamlMap& m);

}  // namespace

void rethrowNamingOverride(const InputError& e, const std::vector<std::string>& overrides) {
  const std::string& key = e.getLocation().key;
  for (auto o = overrides.rbegin(); o != overrides.rend(); ++o) {
    const std::string p = getOverridePath(*o);
    if (key == p || key.rfind(p + ".", 0) == 0 || key.rfind(p + "[", 0) == 0)
      throw e.withReasonAdded(" (value from --set " + *o + ")");
  }
  throw e;
}

Scenario readScenarioTree(const YAML::Node& tree, const std::string& file, const std::vector<std::string>& overrides,
                          std::shared_ptr<io::InputStore> inputs) {
  YamlMap m(tree, file, "");
  Scenario s = readScenario(file, m);
  s.overrides = overrides;
  if (inputs) s.inputs = std::move(inputs);
  s.warnings = checkPlausibility(s, tree, file);
  return s;
}

Scenario loadScenario(const std::string& file, const std::vector<std::string>& overrides) {
  const ScenarioSource source(file);  // the file's own errors first, then the overrides'
  return source.load(ParameterOverrides(overrides));
}

namespace {

// The rear frame, or the whole vehicle (`total`, read by readTotal once the other bodies are known);
// the front frame and the wheels, whose mass properties may be left out beside `total`.
void readFramesAndWheels(YamlMap& m, Scenario& s) {
  s.hasTotal = m.has("total");
  if (s.hasTotal && m.has("rear_frame"))
    m.fail("rear_frame", "give only one of rear_frame and total (with total the rear frame is derived from it)");
  if (!s.hasTotal && !m.has("rear_frame"))
    m.fail("", "missing key 'rear_frame' (or 'total': the whole vehicle with rider, the rear frame then derived)");
  std::vector<AssumedValue>* assumed = s.hasTotal ? &s.assumed : nullptr;
  if (!s.hasTotal) s.rearFrame = readBody(m.getMap("rear_frame"));
  if (m.has("front_frame")) s.frontFrame = readBody(m.getMap("front_frame"));
  s.rearWheel = readWheel(m.getMap("rear_wheel"), false, assumed);
  s.frontWheel = readWheel(m.getMap("front_wheel"), true, assumed);
  if (m.has("front_frame")) return;
  if (!s.hasTotal) m.getMap("front_frame");  // the missing-key error
  s.frontFrame = makeDefaultFrontFrame(s.geometry, s.frontWheel.radius);
  const BodySpec& f = s.frontFrame;
  std::ostringstream os;
  os << f.mass << " kg, CoM [" << f.com[0] << ", 0, " << f.com[2] << "] m, inertia xx " << f.inertia.xx << ", yy "
     << f.inertia.yy << ", zz " << f.inertia.zz << ", xz " << f.inertia.xz << " kg m^2";
  s.assumed.push_back({"front_frame", os.str(), kWholeVehicleDefaultSource});
}

// `total: {mass_kg, com_m, inertia_kgm2}`: the whole vehicle with rider about its own CoM. The rear
// frame is what is left of it without the other bodies; it must be a physical body.
void readTotal(YamlMap& root, Scenario& s) {
  YamlMap m = root.getMap("total");
  s.total = readBodyKeys(m);
  m.finish();
  const double x = s.total.com[0], w = s.geometry.wheelbase;
  if (!(x > 0 && x < w))
    m.fail("com_m", "the centre of mass must lie between the contact points (0 < x < wheelbase_m = " +
                        formatAssumed(w, "m") + "), else a wheel load is negative");
  s.rearFrame = calcRearFrameFromTotal(s, s.total);
  const BodySpec& r = s.rearFrame;
  double others = 0;
  for (const NamedBody& b : listOtherBodies(s)) others += b.body.mass;
  if (!(r.mass > 0))
    root.fail("total", "the other bodies (front frame, wheels, swingarm) weigh " + formatAssumed(others, "kg") +
                   ", no less than the total: nothing is left for the rear frame");
  const std::string why = checkInertia(r.inertia);
  if (!why.empty())
    root.fail("total", "the rear frame left by the total without the other bodies (" + formatAssumed(r.mass, "kg") +
                   ") is not a physical body: its " + why);
}

Scenario readScenario(const std::string& file, YamlMap& m) {
  Scenario s;
  s.sourceFile = file;
  const io::SectionFields& top = getTopLevelFields();
  s.name = m.getString(top.get("name").key);
  if (const std::string why = io::describeBadFolderName(s.name); !why.empty())
    m.fail("name", "the name becomes the output folder's name and " + why);
  s.description = m.getString(top.get("description").key, "");
  s.gravity = readNumber(m, top.get("gravity_mps2"));
  if (m.has(top.get("speeds_mps").key)) {
    YamlMap sp = m.getMap("speeds_mps");
    const io::SectionFields& f = getSpeedRangeFields();
    s.speeds.start = readNumber(sp, f.get("start"));
    s.speeds.stop = readNumber(sp, f.get("stop"));
    s.speeds.step = readNumber(sp, f.get("step"));
    if (s.speeds.stop < s.speeds.start) sp.fail("stop", "must not be below start");
    std::string why;
    countSpeeds(s.speeds.start, s.speeds.stop, s.speeds.step, why);
    if (!why.empty()) sp.fail(s.speeds.stop > SpeedRange::kMaxSpeed ? "stop" : "step", why);
    sp.finish();
  }
  {
    YamlMap g = m.getMap("geometry");
    const io::SectionFields& f = getGeometryFields();
    s.geometry.wheelbase = readNumber(g, f.get("wheelbase_m"));
    s.geometry.steerAxisTilt = readNumber(g, f.get("steer_axis_tilt_deg")) * M_PI / 180.0;
    if (std::abs(s.geometry.steerAxisTilt) >= M_PI / 2) g.fail("steer_axis_tilt_deg", "must lie in (-90, 90) degrees");
    if (!g.has("trail_m") && !g.has("normal_trail_m"))
      g.failMissing("trail_m", "normal_trail_m");
    if (g.has("trail_m") && g.has("normal_trail_m")) g.fail("normal_trail_m", "give only one of trail_m and normal_trail_m");
    s.geometry.trail = g.has("trail_m") ? readNumber(g, f.get("trail_m"))
                                        : readNumber(g, f.get("normal_trail_m")) / std::cos(s.geometry.steerAxisTilt);
    g.finish();
  }
  readFramesAndWheels(m, s);
  {
    YamlMap c = m.getMap("contact");
    s.contact.model = c.getString("model");
    s.contact.params = c.getNode();
    s.contact.file = file;
    s.contact.path = "contact";
  }
  if (m.has("swingarm")) {
    YamlMap sw = m.getMap("swingarm");
    s.hasSwingarm = true;
    s.swingarm.pivot = readVector3(sw, getSwingarmFields().get("pivot_m"));
    s.swingarm.body = readBodyKeys(sw);
    s.swingarm.compliance = sw.getString(getSwingarmFields().get("compliance").key);
    s.swingarm.params = sw.getNode();
    s.swingarm.file = file;
    const double dx = s.swingarm.pivot[0], dz = s.swingarm.pivot[2] - s.rearWheel.radius;
    if (dx <= 0 || std::hypot(dx, dz) < 1e-3) sw.fail("pivot_m", "the pivot must lie ahead of the rear wheel centre");
    // The swingarm's own model-extension section, read by its plugin at build.
    if (sw.has(kSwingarmSuspension)) {
      if (!sw.getNode()[kSwingarmSuspension].IsMap()) sw.fail(kSwingarmSuspension, "expected a mapping");
      const std::string path = "swingarm." + std::string(kSwingarmSuspension);
      s.extensions.push_back({path, sw.getNode()[kSwingarmSuspension], file, path, sw.locate(kSwingarmSuspension)});
    }
    for (const auto& k : getSwingarmLoaderKeys()) sw.markUsed(k);
    // The compliance plugin reads and checks the rest of this mapping.
  }
  if (s.hasTotal) readTotal(m, s);
  if (m.has("plugins")) {
    // Plugin libraries by path only (never searched by bare name), relative to the scenario.
    const auto names = m.getStringList("plugins");
    for (size_t i = 0; i < names.size(); ++i)
      if (names[i].find('/') == std::string::npos)
        m.failElement("plugins", i, "a plugin library is named by its path (e.g. ./" + names[i] +
                                        "), relative to this file; a bare name is not searched for");
    s.plugins = m.getFilePathList("plugins");
  }
  if (m.has("uncertainty")) s.uncertainty = readUncertainty(m.getMap("uncertainty"), m.getNode());
  // Every other mapping is a model-extension section, read by the plugin of its name at build.
  for (const std::string& key : m.getUnreadKeys()) {
    const YAML::Node section = m.getNode()[key];
    if (!section.IsMap())
      m.fail(key, "expected a mapping: a key the scenario format does not define is a model-extension section "
                  "(steer_damper, rider_lean, ...), a mapping of its own keys");
    if (key.find('.') != std::string::npos)
      m.fail(key, "a section's name has no '.': a section inside another is written nested (swingarm: {suspension: ...})");
    s.extensions.push_back({key, section, file, key, m.locate(key)});
    m.markUsed(key);
  }
  m.finish();
  return s;
}

}  // namespace


namespace {
// Inertia tensor about the design origin of a body given about its CoM (parallel axes).
Eigen::Matrix3d calcInertiaAboutOrigin(const BodySpec& b) {
  const InertiaSpec& I = b.inertia;
  Eigen::Matrix3d J;
  J << I.xx, I.xy, I.xz, I.xy, I.yy, I.yz, I.xz, I.yz, I.zz;
  const Eigen::Vector3d r(b.com[0], b.com[1], b.com[2]);
  return J + b.mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
}
}  // namespace

BodySpec calcBodyRemainder(const BodySpec& whole, const BodySpec& part) {
  BodySpec r;
  r.mass = whole.mass - part.mass;
  if (!(r.mass > 0)) return r;
  for (int i = 0; i < 3; ++i) r.com[i] = (whole.mass * whole.com[i] - part.mass * part.com[i]) / r.mass;
  const Eigen::Vector3d c(r.com[0], r.com[1], r.com[2]);
  const Eigen::Matrix3d J = calcInertiaAboutOrigin(whole) - calcInertiaAboutOrigin(part) -
                            r.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  r.inertia = {J(0, 0), J(1, 1), J(2, 2), J(0, 1), J(0, 2), J(1, 2)};
  return r;
}

const PluginSpec* findExtension(const Scenario& s, const std::string& name) {
  for (const PluginSpec& e : s.extensions)
    if (e.model == name) return &e;
  return nullptr;
}

MassSummary calcMassSummary(const Scenario& s) {
  MassSummary out;
  auto add = [&](double mass, const Vec3d& c) {
    for (int i = 0; i < 3; ++i) out.com[i] = (out.com[i] * out.mass + c[i] * mass) / (out.mass + mass);
    out.mass += mass;
  };
  add(s.rearFrame.mass, s.rearFrame.com);
  add(s.frontFrame.mass, s.frontFrame.com);
  add(s.rearWheel.mass, {0, 0, s.rearWheel.radius});
  add(s.frontWheel.mass, {s.geometry.wheelbase, 0, s.frontWheel.radius});
  if (s.hasSwingarm) add(s.swingarm.body.mass, calcSwingarmCom(s));
  return out;
}

SwingarmFrame calcSwingarmFrame(const Scenario& s) {
  SwingarmFrame f;
  f.origin = s.swingarm.pivot;
  const double dx = -s.swingarm.pivot[0], dz = s.rearWheel.radius - s.swingarm.pivot[2];
  f.length = std::hypot(dx, dz);
  f.x = {dx / f.length, 0, dz / f.length};
  f.z = {-f.x[2], 0, f.x[0]};  // x rotated by +90 deg about -y: up for a rearward x
  if (f.z[2] < 0) f.z = {-f.z[0], 0, -f.z[2]};
  f.y = {f.z[1] * f.x[2] - f.z[2] * f.x[1], f.z[2] * f.x[0] - f.z[0] * f.x[2], f.z[0] * f.x[1] - f.z[1] * f.x[0]};
  return f;
}

double calcForkOffset(const Scenario& s) {
  return s.frontWheel.radius * std::sin(s.geometry.steerAxisTilt) - calcNormalTrail(s.geometry);
}

double calcNormalTrail(const GeometrySpec& g) { return g.trail * std::cos(g.steerAxisTilt); }

std::array<double, 2> calcStaticWheelLoads(const Scenario& s) {
  const MassSummary ms = calcMassSummary(s);
  const double weight = ms.mass * s.gravity;
  const double front = weight * ms.com[0] / s.geometry.wheelbase;
  return {weight - front, front};
}

double calcStaticPivotMoment(const Scenario& s) {
  // M_y = -(x - x_pivot) F_z for a vertical force F_z at x: rear tyre load at the contact point
  // (x = 0), wheel weight at the hub (x = 0), swingarm weight at its centre of mass.
  const double xP = s.swingarm.pivot[0], g = s.gravity;
  const double rearLoad = calcStaticWheelLoads(s)[0];
  return xP * (rearLoad - s.rearWheel.mass * g) + (calcSwingarmCom(s)[0] - xP) * s.swingarm.body.mass * g;
}

}  // namespace motostab::scenario
