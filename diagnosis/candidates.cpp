#include "diagnosis/candidates.h"

#include <fnmatch.h>

#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "diagnosis/physical_candidates.h"
#include "diagnosis/priors.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "io/yaml_map.h"
#include "plugins/builtin.h"
#include "scenario/parameter_paths.h"
#include "scenario/scenario.h"
#include "tyres/relaxation_linear.h"
#include "vehicle/vehicle_model.h"

namespace motostab::diagnosis {

using io::formatNumber;
using scenario::ParameterKind;
using scenario::ScalarParameter;
using scenario::getDefaultSigma;
using scenario::listScalarParameters;

namespace {

double getScalar(const YAML::Node& tree, const char* section, const char* key, double fallback) {
  const YAML::Node s = tree[section];
  if (!s || !s.IsMap() || !s[key] || !s[key].IsScalar()) return fallback;
  try {
    return s[key].as<double>();
  } catch (const YAML::Exception&) {
    return fallback;
  }
}

// The rear frame (with rider) of a scenario tree: as given, or as the loader derives it from `total`
// (none when the tree does not load: the loader reports that).
std::optional<scenario::BodySpec> getRearFrame(const YAML::Node& tree) {
  try {
    return scenario::readScenarioTree(tree, "", {}).rearFrame;
  } catch (const io::InputError&) {
    return std::nullopt;
  }
}

// The rear frame as the model of a scenario tree builds it: getRearFrame less what the model
// extensions take from it (the grips of `rider_arms`, a leaning upper body); none when it does not build.
std::optional<scenario::BodySpec> getModelRearFrame(const YAML::Node& tree) {
  try {
    return vehicle::listModelBodies(scenario::readScenarioTree(tree, "", {})).front().body;
  } catch (const io::InputError&) {
    return std::nullopt;
  }
}

// A steer torque per steer rate that matters for the vehicle: front weight times trail times 1 s.
double calcSteerDampingScale(const YAML::Node& tree) {
  const double m = getScalar(tree, "front_frame", "mass_kg", 5) + getScalar(tree, "front_wheel", "mass_kg", 2);
  const double trail = std::abs(getScalar(tree, "geometry", "trail_m", getScalar(tree, "geometry", "normal_trail_m", 0.08)));
  return std::max(m * 9.81 * std::max(trail, 0.02), 1e-3);
}

// A parameter free within [lower, upper] from `start`, differenced with `step` (key units).
CandidateParameter makeFreeParameter(const std::string& name, const std::string& path, double lower, double upper,
                                     double start, double step) {
  CandidateParameter c;
  c.name = name, c.path = path, c.lower = lower, c.upper = upper, c.start = start, c.step = step;
  return c;
}

Candidate makeSteerDamper(const YAML::Node& tree) {
  const double s = calcSteerDampingScale(tree);
  CandidateParameter c = makeFreeParameter("damping_Nms_per_rad", "steer_damper.damping_Nms_per_rad", 0, 20 * s, 0.05 * s, 1e-3 * s);
  c.off = 0;
  c.offAtBound = true;
  return {"steer_damper", {"steer_damper={damping_Nms_per_rad: 0}"}, {c}};
}

// Steer-head friction, a Coulomb torque T_f (N m), as the describing-function equivalent viscous damping
// c_eq = 4 T_f / (pi Omega) at the measured steer-rate amplitude Omega (physical_candidates.h eq. 1),
// added to the scenario's steer damper coefficient, or a damper of its own where there is none. Its
// bounds, start and step are steer_damper's mapped through c_eq, so that both search alike.
Candidate makeSteerFriction(const YAML::Node& tree, const SteerRateAmplitude& omega) {
  Candidate c = makeSteerDamper(tree);
  c.name = "steer_friction";
  c.sameModelAs = "steer_damper";
  const double k = calcFrictionDampingFactor(omega.value_rad_s);
  CandidateParameter& p = c.parameters[0];
  p.name = "friction_torque_Nm";
  p.lower /= k, p.upper /= k, p.start /= k, p.step /= k;
  p.keyScale = k;
  p.note = "at a steer-rate amplitude of " + formatNumber(omega.value_rad_s, 4) + " rad/s (" + omega.source +
           "): damping " + formatNumber(k, 4) + " N m s/rad per N m";
  if (tree["steer_damper"]) {  // added to the damper there is
    p.keyOffset = getScalar(tree, "steer_damper", "damping_Nms_per_rad", 0);
    c.fixedOverrides = {};
  }
  return c;
}

// A steer controller's effective gain and delay (extensions/steer_controller.h): `steer_controller_gain`
// scales every gain (gain_factor, log scale over [0.05, 20], off at 1), `steer_controller_delay` adds
// a Pade delay (delay_s in [0, 0.3] s, off at the bound 0; absent when the scenario has one).
void addSteerControllerCandidates(const YAML::Node& tree, std::vector<Candidate>& out) {
  const YAML::Node c = tree["steer_controller"];
  if (!c || !c.IsMap()) return;
  CandidateParameter g = makeFreeParameter("gain_factor", "steer_controller.gain_factor", 0.05, 20, 1, 1e-4);
  g.logScale = true;
  g.off = 1;
  out.push_back({"steer_controller_gain", {}, {g}});
  if (c["delay_s"]) return;
  CandidateParameter d = makeFreeParameter("delay_s", "steer_controller.delay_s", 0, 0.3, 0.02, 1e-4);
  d.off = 0;
  d.offAtBound = true;
  out.push_back({"steer_controller_delay", {}, {d}});
}

// A stiffness fitted on a log scale from `start` within [start/1e3, start*1e3]; off at infinity.
CandidateParameter makeStiffness(const std::string& name, const std::string& path, double start) {
  CandidateParameter c = makeFreeParameter(name, path, start * 1e-3, start * 1e3, start, 1e-4);
  c.logScale = true;
  c.offAtInfinity = true;
  return c;
}

Candidate makeForkCompliance(const YAML::Node& tree) {
  // Start: a fork bending stiffness whose wheel-load deflection is ~1 mrad per kg of vehicle.
  const auto rear = tree["total"] ? getRearFrame(tree) : std::nullopt;
  const double m = (rear ? rear->mass : getScalar(tree, "rear_frame", "mass_kg", 50)) + getScalar(tree, "front_frame", "mass_kg", 5);
  const double k = std::max(1e3, 200.0 * m);
  return {"fork_compliance",
          {"fork_compliance={stiffness_Nm_per_rad: " + formatNumber(k) + ", damping_Nms_per_rad: 0}"},
          {makeStiffness("stiffness_Nm_per_rad", "fork_compliance.stiffness_Nm_per_rad", k)}};
}

// Slipping tyres (relaxation_linear, bicycle preset) on a vehicle modelled with rolling constraints:
// the normalised cornering stiffness of both tyres free (preset 15 /rad); rolling is its stiff limit.
void addTyreSlipCandidate(const YAML::Node& tree, std::vector<Candidate>& out) {
  const YAML::Node c = tree["contact"];
  if (!c || !c.IsMap() || !c["model"] || c["model"].Scalar() != "rolling_no_slip") return;
  CandidateParameter k = makeStiffness("cornering_stiffness_per_rad", "contact.front.cornering_stiffness_per_rad", 15);
  k.alsoPaths = {"contact.rear.cornering_stiffness_per_rad"};
  // The relaxation length of both tyres free too, from the preset's 0.1 m.
  CandidateParameter length = makeFreeParameter("relaxation_length_m", "contact.front.relaxation_length_m", 0.005, 1.0, 0.1, 1e-4);
  length.alsoPaths = {"contact.rear.relaxation_length_m"};
  out.push_back({"tyre_slip",
                 {"contact={model: relaxation_linear, preset: bicycle, front: {cornering_stiffness_per_rad: 15}, "
                  "rear: {cornering_stiffness_per_rad: 15}}"},
                 {k, length}});
}

// Rider lean: the rider's upper body, a 75 kg rider's head-arms-trunk (Winter 2009,
// Table 4.1: 0.678 of the body mass; the rider mass is an estimate), taken out of the rear frame as a
// proportional slice (CoM at the rear frame's, inertia scaled by the mass share: the rest stays a valid
// body), hinged 0.25 m below that CoM (docs/rider-lean-parameters.py: 0.24 m for rider Jason). Free:
// the lean stiffness (log scale, off at infinity: a rigid rider), from 4 times the upper body's gravity
// stiffness m g d, bounded below by 1.1 m g d (the rider alone upright-stable); damping fixed at 0.3
// of critical at the start. A rear frame lighter than the rider holds none (a riderless vehicle).
void addRiderLeanCandidate(const YAML::Node& tree, std::vector<Candidate>& out, std::vector<std::string>& unavailable) {
  if (tree["rider_lean"]) {
    unavailable.push_back("rider_lean: the scenario has one already (its stiffness and damping are parameter candidates)");
    return;
  }
  const auto rf = getModelRearFrame(tree);  // with `total:` the derived one; without the grips of rider_arms
  const double mB = rf ? rf->mass : getScalar(tree, "rear_frame", "mass_kg", 0);
  if (!(mB > kRiderMass_kg)) {
    unavailable.push_back("rider_lean: the rear frame (" + formatNumber(mB) + " kg) is lighter than a " +
                          formatNumber(kRiderMass_kg) + " kg rider: a riderless vehicle has no upper body to lean");
    return;
  }
  if (!rf) return;  // the loader reports it
  const scenario::InertiaSpec& I = rf->inertia;
  const double mU = 0.678 * kRiderMass_kg, share = mU / mB, d = 0.25, g = 9.81;
  const double zU = rf->com[2], ixx = share * I.xx;
  std::string body = "hinge_height_m: " + formatNumber(zU - d) + ", mass_kg: " + formatNumber(mU) + ", com_m: [" +
                     formatNumber(rf->com[0]) + ", 0, " + formatNumber(zU) + "], inertia_kgm2: {";
  const char* keys[] = {"xx", "yy", "zz", "xy", "xz", "yz"};
  const double values[] = {I.xx, I.yy, I.zz, I.xy, I.xz, I.yz};
  for (int i = 0; i < 6; ++i) body += std::string(i ? ", " : "") + keys[i] + ": " + formatNumber(share * values[i]);
  const double gravity = mU * g * d, k = 4 * gravity, damping = 2 * 0.3 * std::sqrt(k * (ixx + mU * d * d));
  CandidateParameter p = makeStiffness("stiffness_Nm_per_rad", "rider_lean.stiffness_Nm_per_rad", k);
  p.lower = 1.1 * gravity;
  out.push_back({"rider_lean",
                 {"rider_lean={" + body + "}, stiffness_Nm_per_rad: " + formatNumber(k) +
                  ", damping_Nms_per_rad: " + formatNumber(damping) + "}"},
                 {p}});
}

void addSwingarmCandidates(const YAML::Node& tree, std::vector<Candidate>& out) {
  const YAML::Node sw = tree["swingarm"];
  if (!sw || !sw.IsMap()) return;
  const std::string current = sw["compliance"] && sw["compliance"].IsScalar() ? sw["compliance"].Scalar() : "rigid";
  for (const char* variant : {"bending", "torsion", "twist"}) {
    if (!sw[variant] || current == variant) continue;
    Candidate c{std::string("swingarm_") + variant, {std::string("swingarm.compliance=") + variant},
                {makeStiffness("stiffness_scale", "swingarm.stiffness_scale", 1.0)}};
    c.parameters[0].lower = 0.02;
    c.parameters[0].upper = 50;
    out.push_back(c);
  }
}

double findSigma(const ScalarParameter& p, const std::vector<std::pair<std::string, double>>& uncertainty) {
  for (const auto& u : uncertainty)
    if (u.first == p.path) return u.second;
  return getDefaultSigma(p);
}

bool isMeasured(const ScalarParameter& p, const std::vector<std::pair<std::string, double>>& uncertainty) {
  for (const auto& u : uncertainty)
    if (u.first == p.path) return true;
  return false;
}

// Bounds keep the vehicle physical: a parameter whose field keeps its sign (a mass, a radius, a trail,
// a principal moment; io::Field::keepsSign) stays above a tenth of a positive value; a measured parameter within
// kParameterRangeSigmas sigma (room for a gross error), one with the default sigma within 30 (already
// wide: 30 % of a mass, 30 deg); and masses and inertias within a factor 5.
Candidate makeParameterCandidate(const ScalarParameter& p, double sigma, bool measured = false) {
  const double range = (measured ? kParameterRangeSigmas : 30) * sigma;
  CandidateParameter c = makeFreeParameter("value", p.path, p.value - range, p.value + range, p.value, 1e-3 * sigma);
  if (p.positive && p.value > 0) {
    c.lower = std::max(c.lower, 0.1 * p.value);
    if (p.kind == ParameterKind::Mass || p.kind == ParameterKind::Inertia) c.upper = std::min(c.upper, 5 * p.value);
  }
  c.off = p.value;
  c.priorMean = p.value;
  c.priorSigma = sigma;
  return {"parameter:" + p.path, {}, {c}};
}

// Magic Formula tyres: each tyre's scaling factors of cornering stiffness (LKY), camber stiffness
// (LKYC) and pneumatic trail (LTR), the factors that shape straight-running modes, as parameters
// (value as given in `scaling`, else 1; prior sigma 0.1; kept within [0.2, 5] of it).
void addTyreScalingCandidates(const YAML::Node& tree, std::vector<Candidate>& out) {
  const YAML::Node c = tree["contact"];
  if (!c || !c.IsMap() || !c["model"] || c["model"].Scalar() != "magic_formula") return;
  for (const char* tyre : {"front", "rear"}) {
    if (!c[tyre] || !c[tyre].IsMap()) continue;  // the loader reports it
    for (const char* factor : {"LKY", "LKYC", "LTR"}) {
      ScalarParameter p;
      p.path = std::string("contact.") + tyre + ".scaling." + factor;
      p.value = getScalar(c[tyre], "scaling", factor, 1.0);
      p.scale = std::abs(p.value);
      Candidate candidate = makeParameterCandidate(p, 0.1 * p.scale);
      candidate.parameters[0].lower = 0.2 * p.value;
      candidate.parameters[0].upper = 5 * p.value;
      out.push_back(candidate);
    }
  }
}

// The rider's arms on the handlebar (extensions/rider_arms.h): added steer inertia fixed at Sharp's
// (1994) hands-on 0.20 kg m^2 (front-frame steer inertia 0.71 -> 0.91), stiffness and damping free with
// Student-t priors from the published hands-on values: Sharp (1994) k = 50 N m/rad, c = 6 - 1 = 5 N m s/rad
// added by the hands; the "arms yaw" spring-damper of the sport-bike model of Passigato et al. (2020, Appl.
// Sci. 10:6826; data after Sharp, Evangelou & Limebeer 2004) 1053 N m/rad, 19.3 N m s/rad. Priors:
// k 50 +/- 300 (t, nu = 4: both values inside 3.5 sigma), c 5 +/- 8; bounds [0, 2000] and [0, 40]. The
// candidate is on from its start (J is not zero at k = c = 0): its likelihood ratio is read as nested
// at k = c = 0 with J's 0.2 kg m^2 a fixed part of the hands-on model. Needs a rider on the rear frame.
void addRiderArmsCandidate(const YAML::Node& tree, std::vector<Candidate>& out, std::vector<std::string>& unavailable) {
  if (tree["rider_arms"]) {
    unavailable.push_back("rider_arms: the scenario has them already (their values are parameter candidates)");
    return;
  }
  const auto rf = getRearFrame(tree);
  const double mB = rf ? rf->mass : getScalar(tree, "rear_frame", "mass_kg", 0);
  if (!(mB > kRiderMass_kg)) {
    unavailable.push_back("rider_arms: the rear frame (" + formatNumber(mB) + " kg) is lighter than a " +
                          formatNumber(kRiderMass_kg) + " kg rider: no rider's hands on the handlebar");
    return;
  }
  CandidateParameter k = makeFreeParameter("stiffness_Nm_per_rad", "rider_arms.stiffness_Nm_per_rad", 0, 2000, 50, 1e-2);
  k.priorMean = 50, k.priorSigma = 300, k.off = 0, k.offAtBound = true;
  CandidateParameter c = makeFreeParameter("damping_Nms_per_rad", "rider_arms.damping_Nms_per_rad", 0, 40, 5, 1e-3);
  c.priorMean = 5, c.priorSigma = 8, c.off = 0, c.offAtBound = true;
  out.push_back({"rider_arms",
                 {"rider_arms={inertia_kgm2: " + formatNumber(kRiderArmsInertia_kgm2) + ", stiffness_Nm_per_rad: 50, damping_Nms_per_rad: 5}"},
                 {k, c}});
}

// Tyre relaxation (relaxation_linear tyres): both tyres' relaxation lengths times one factor, log scale
// in [0.2, 5], off at 1 (the scenario's lengths). Prior: Student-t about 1 with sigma 0.4. Published
// motorcycle-tyre relaxation lengths at nominal load span about 0.13-0.26 m: Sharp (1994, load-dependent
// 0.18-0.24 m), Sharp & Limebeer (2001, 0.25 m), the sport tyres of Sharp, Evangelou & Limebeer (2004,
// 0.16-0.26 m from speed 0 to 40 m/s), as their public model files transcribe them; a factor 0.5-2 about
// a scenario's value covers that spread.
void addTyreRelaxationCandidate(const YAML::Node& tree, std::vector<Candidate>& out) {
  const YAML::Node c = tree["contact"];
  if (!c || !c.IsMap() || !c["model"] || c["model"].Scalar() != "relaxation_linear") return;
  const auto length = [&](const char* tyre) {
    const YAML::Node t = c[tyre];
    return t && t.IsMap() && t["relaxation_length_m"] ? t["relaxation_length_m"].as<double>(0.0) : 0.0;
  };
  const double front = length("front"), rear = length("rear");
  if (!(front > 0 && rear > 0)) return;
  CandidateParameter p = makeFreeParameter("relaxation_scale", "contact.front.relaxation_length_m", 0.2, 5, 1, 1e-4);
  p.logScale = true;
  p.off = 1;
  p.keyScale = front;
  p.alsoPaths = {"contact.rear.relaxation_length_m"};
  p.alsoScales = {rear};
  p.priorMean = 1, p.priorSigma = 0.4;
  p.note = "times the scenario's relaxation lengths, front " + formatNumber(front, 4) + " m, rear " + formatNumber(rear, 4) + " m";
  out.push_back({"tyre_relaxation", {}, {p}});
}

// Sharp, Evangelou & Limebeer (2004) sec. 4, Evangelou (2004) Table 9.5: sigma = K_ya (C1 + C2 V + C3 V^2)
// for the 120/70 ZR17 front and 180/55 ZR17 rear sport tyres, i.e. a lateral compliance 1/k_y = C1 (1 +
// b1 V + b2 V^2) with b1 = C2/C1, b2 = C3/C1 (tyres/relaxation_linear.h).
struct PublishedCarcass {
  double C1, C2, C3;  // m/N, s/N, s^2/(N m)
  double getB1() const { return C2 / C1; }
  double getB2() const { return C3 / C1; }
};
constexpr PublishedCarcass kSharpFront{8.633e-6, 3.725e-8, 8.389e-10}, kSharpRear{9.694e-6, -1.333e-8, 1.898e-9};

// Tyre carcass (relaxation_linear tyres with constant relaxation lengths): each tyre's sigma becomes
// the carcass's, Fz k_alpha (1 + lambda (b1 V + b2 V^2)) / k_y0 (tyres/relaxation_linear.h), with k_y0 =
// Fz0 k_alpha / sigma0 at the static load Fz0 (so that sigma is the scenario's at rest) and the published
// speed coefficients b1, b2 of each wheel's tyre (kSharpFront, kSharpRear) times one factor lambda, free
// in [0, 4], off at the bound 0 (the load dependence alone, a fixed part of the candidate). Prior:
// Student-t about 1 (the published speed dependence) with sigma 0.5: only one published set is known to
// us, so the width is our choice (no speed dependence and twice the published at 2 sigma).
void addTyreCarcassCandidate(const YAML::Node& tree, std::vector<Candidate>& out, std::vector<std::string>& unavailable) {
  const YAML::Node c = tree["contact"];
  if (!c || !c.IsMap() || !c["model"] || c["model"].Scalar() != "relaxation_linear") return;
  std::pair<tyres::LinearTyreParameters, tyres::LinearTyreParameters> parsed;
  std::array<double, 2> loads{};
  try {
    const scenario::Scenario s = scenario::readScenarioTree(tree, "", {});
    io::YamlMap contact(s.contact.params, s.contact.file, s.contact.path);
    contact.markUsed("model");
    parsed = tyres::readRelaxationLinearTyres(contact);
    loads = scenario::calcStaticWheelLoads(s);
  } catch (const io::InputError&) {
    return;  // the loader reports it
  }
  auto& [front, rear] = parsed;
  if (front.lateralCarcassStiffness > 0 || rear.lateralCarcassStiffness > 0) {
    unavailable.push_back("tyre_carcass: the tyres have a lateral carcass stiffness already (set its keys with --set)");
    return;
  }
  if (!(front.relaxationLength > 0 && rear.relaxationLength > 0)) return;
  const double sigmaFront = front.relaxationLength, sigmaRear = rear.relaxationLength;
  front.lateralCarcassStiffness = loads[1] * front.corneringStiffness / sigmaFront;
  rear.lateralCarcassStiffness = loads[0] * rear.corneringStiffness / sigmaRear;
  const std::string contact = "contact={model: relaxation_linear, front: " + tyres::formatLinearTyre(front) +
                              ", rear: " + tyres::formatLinearTyre(rear) + "}";
  CandidateParameter p = makeFreeParameter("speed_dependence", "contact.front.carcass_compliance_speed_coefficient_s_per_m", 0, 4, 1, 1e-3);
  p.keyScale = kSharpFront.getB1();
  p.alsoPaths = {"contact.front.carcass_compliance_speed_coefficient_s2_per_m2", "contact.rear.carcass_compliance_speed_coefficient_s_per_m",
                 "contact.rear.carcass_compliance_speed_coefficient_s2_per_m2"};
  p.alsoScales = {kSharpFront.getB2(), kSharpRear.getB1(), kSharpRear.getB2()};
  p.off = 0, p.offAtBound = true;
  p.priorMean = 1, p.priorSigma = 0.5;
  p.note = "times the speed dependence of Sharp, Evangelou & Limebeer (2004); carcass stiffness front " +
           formatNumber(front.lateralCarcassStiffness, 4) + " N/m, rear " + formatNumber(rear.lateralCarcassStiffness, 4) +
           " N/m (the scenario's relaxation lengths " + formatNumber(sigmaFront, 4) + ", " + formatNumber(sigmaRear, 4) +
           " m at the static loads)";
  out.push_back({"tyre_carcass", {contact}, {p}});
}

}  // namespace

const std::vector<io::SectionFields>& getBuiltinSectionFields() {
  static const std::vector<io::SectionFields> sections = plugins::listSectionFields(plugins::makeBuiltinRegistry());
  return sections;
}

std::vector<Candidate> listCandidates(const YAML::Node& tree,
                                      const std::vector<std::pair<std::string, double>>& uncertainty,
                                      std::vector<std::string>* unavailable, const SteerRateAmplitude& steerRate,
                                      const std::vector<io::SectionFields>& sections) {
  std::vector<Candidate> out;
  std::vector<std::string> none;
  if (!tree["steer_damper"]) out.push_back(makeSteerDamper(tree));
  if (steerRate.value_rad_s > 0) out.push_back(makeSteerFriction(tree, steerRate));
  else if (!steerRate.source.empty()) (unavailable ? *unavailable : none).push_back("steer_friction: " + steerRate.source);
  if (!tree["fork_compliance"]) out.push_back(makeForkCompliance(tree));
  addRiderLeanCandidate(tree, out, unavailable ? *unavailable : none);
  addRiderArmsCandidate(tree, out, unavailable ? *unavailable : none);
  addSwingarmCandidates(tree, out);
  addTyreSlipCandidate(tree, out);
  addTyreRelaxationCandidate(tree, out);
  addTyreCarcassCandidate(tree, out, unavailable ? *unavailable : none);
  addSteerControllerCandidates(tree, out);
  addTyreScalingCandidates(tree, out);
  addPhysicalCandidates(tree, out);
  for (const ScalarParameter& p : listScalarParameters(tree, sections)) {
    const double sigma = findSigma(p, uncertainty);
    if (sigma > 0) out.push_back(makeParameterCandidate(p, sigma, isMeasured(p, uncertainty)));
    if (sigma > 0) out.back().parameters[0].priorMeasured = isMeasured(p, uncertainty);
  }
  return out;
}

std::vector<Candidate> filterCandidates(const std::vector<Candidate>& all, const std::vector<std::string>& patterns) {
  if (patterns.empty()) return all;
  std::vector<Candidate> out;
  std::vector<bool> used(patterns.size(), false);
  for (const auto& c : all) {
    bool take = false;
    for (size_t i = 0; i < patterns.size(); ++i)
      if (patterns[i] == c.name || fnmatch(patterns[i].c_str(), c.name.c_str(), 0) == 0) take = used[i] = true;  // [i] is no glob class here
    if (take) out.push_back(c);
  }
  for (size_t i = 0; i < patterns.size(); ++i)
    if (!used[i]) throw io::InputError({"--candidates", 0, 0, patterns[i]}, "matches no candidate of this scenario");
  return out;
}

}  // namespace motostab::diagnosis
