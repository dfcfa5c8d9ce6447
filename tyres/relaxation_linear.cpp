#include "tyres/relaxation_linear.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "io/csv.h"
#include "scenario/scenario.h"
#include "tyres/tyre_contact.h"

namespace motostab::tyres {

using io::YamlMap;
using plugins::BuildContext;
using plugins::ContactModel;
using plugins::PluginRegistrar;
using plugins::WheelSite;


namespace {

constexpr const char* kCarcassKey = "lateral_carcass_stiffness_N_per_m";
constexpr const char* kSpeedKey = "carcass_compliance_speed_coefficient_s_per_m";
constexpr const char* kSpeedKey2 = "carcass_compliance_speed_coefficient_s2_per_m2";

// The smallest of 1 + b1 V + b2 V^2 over 0 <= V <= vMax, and the speed where it is.
std::pair<double, double> findComplianceMinimum(double b1, double b2, double vMax) {
  auto f = [&](double V) { return 1 + b1 * V + b2 * V * V; };
  std::pair<double, double> best{f(vMax), vMax};
  if (best.first > 1) best = {1, 0};
  const double vertex = b2 > 0 ? -b1 / (2 * b2) : -1;
  if (vertex > 0 && vertex < vMax && f(vertex) < best.first) best = {f(vertex), vertex};
  return best;
}

// The keys of one tyre (`contact.front`, `contact.rear`), per unit load where the unit says /rad or
// m/rad (header); each required without a preset, optional over one.
std::vector<io::Field> makeTyreFieldList() {
  using io::Field;
  using io::Range;
  return {
      Field::number("cornering_stiffness_per_rad", "1/rad", Range::Positive, "k_alpha: Fy = Fz k_alpha alpha (seed Table 6)"),
      Field::number("camber_stiffness_per_rad", "1/rad", Range::Any, "k_phi: Fy = Fz k_phi phi, towards the lean").within(">= 0"),
      Field::number("self_aligning_stiffness_m_per_rad", "m/rad", Range::Any,
                    "k_mz: Mz = Fz k_mz alpha, -pneumatic trail x k_alpha (turns the wheel towards its velocity)")
          .within("<= 0"),
      Field::number("twisting_stiffness_m_per_rad", "m/rad", Range::Any, "k_mt: Mz = Fz k_mt phi, the twisting moment of camber"),
      Field::number("relaxation_length_m", "m", Range::Any,
                    "sigma, constant (0: no lag, no state); give this or `lateral_carcass_stiffness_N_per_m`")
          .within("0 or >= 1e-4")
          .optional(),
      Field::number(kCarcassKey, "N/m", Range::Positive,
                    "k_y0, the lateral carcass stiffness at standstill: sigma = Fz k_alpha (1 + b1 V + b2 V^2) / k_y0, "
                    "instead of `relaxation_length_m`")
          .optional(),
      Field::number(kSpeedKey, "s/m", Range::Any, "b1, with the carcass stiffness").withDefault(0),
      Field::number(kSpeedKey2, "s^2/m^2", Range::Any, "b2, with the carcass stiffness; 1 + b1 V + b2 V^2 > 0 up to 150 m/s")
          .withDefault(0),
      Field::number("radial_stiffness_N_per_m", "N/m", Range::Positive, "k_r, radial (vertical) stiffness"),
      Field::number("radial_damping_Ns_per_m", "N s/m", Range::NonNegative, "c_r, radial damping"),
      Field::number("longitudinal_stiffness", "", Range::Positive, "k_kappa: Fx = Fz k_kappa kappa")};
}

// The relaxation keys (header): relaxation_length_m or the carcass stiffness with its speed
// coefficients. Over a preset the one given replaces the preset's.
void readRelaxation(YamlMap& m, const io::SectionFields& f, LinearTyreParameters& p, bool overPreset) {
  const bool length = m.has("relaxation_length_m"), carcass = m.has(kCarcassKey);
  if (length && carcass)
    m.fail(kCarcassKey, "give relaxation_length_m (a constant sigma) or lateral_carcass_stiffness_N_per_m (sigma = Fz k_alpha / k_y), not both");
  if (!overPreset && !length && !carcass)
    m.fail("relaxation_length_m", "required (0: no lag), unless lateral_carcass_stiffness_N_per_m gives the relaxation length");
  if (length) {
    p.relaxationLength = m.getZeroOrAtLeast(f.get("relaxation_length_m").key, kMinRelaxationLength, "m");
    p.lateralCarcassStiffness = p.carcassSpeedCoefficient = p.carcassSpeedCoefficient2 = 0;
  }
  if (carcass) {
    p.lateralCarcassStiffness = io::readNumber(m, f.get(kCarcassKey));
    p.carcassWhere = m.locate(kCarcassKey);
    p.relaxationLength = 0;
  }
  for (const char* key : {kSpeedKey, kSpeedKey2}) {
    if (!m.has(key)) continue;
    if (!(p.lateralCarcassStiffness > 0))
      m.fail(key, "needs lateral_carcass_stiffness_N_per_m (the speed coefficient is of the carcass's lateral compliance)");
    (key == kSpeedKey ? p.carcassSpeedCoefficient : p.carcassSpeedCoefficient2) = io::readNumber(m, f.get(key));
  }
  const double vMax = scenario::SpeedRange::kMaxSpeed;
  const auto [factor, at] = findComplianceMinimum(p.carcassSpeedCoefficient, p.carcassSpeedCoefficient2, vMax);
  if (!(factor > 0)) {
    const char* key = m.has(kSpeedKey) ? kSpeedKey : kSpeedKey2;
    m.fail(key, "makes the lateral compliance factor 1 + b1 V + b2 V^2 " + io::formatNumber(factor, 4) + " at " +
                    io::formatNumber(at, 4) + " m/s: it must stay positive (a positive carcass stiffness) from 0 to " +
                    io::formatNumber(vMax) + " m/s");
  }
}

// One tyre's keys. With a preset every key is optional (given ones override the preset's value).
LinearTyreParameters readTyre(YamlMap m, const io::SectionFields& f, const LinearTyreParameters* preset) {
  LinearTyreParameters p = preset ? *preset : LinearTyreParameters{};
  auto read = [&](const char* key, double& v) {
    if (!preset || m.has(key)) v = io::readNumber(m, f.get(key));
  };
  read("cornering_stiffness_per_rad", p.corneringStiffness);
  read("camber_stiffness_per_rad", p.camberStiffness);
  read("self_aligning_stiffness_m_per_rad", p.selfAligningStiffness);
  // The header's signs: camber thrust pushes the tyre towards the lean (k_phi >= 0) and the
  // self-aligning moment of a small slip turns the wheel towards its velocity (k_mz <= 0, a positive
  // pneumatic trail). The twisting moment may have either sign (measured bicycle tyres change it with load).
  if (m.has("camber_stiffness_per_rad") && p.camberStiffness < 0)
    m.fail("camber_stiffness_per_rad", "must not be negative: camber thrust pushes a tyre towards its lean (Fy = Fz k_phi phi)");
  if (m.has("self_aligning_stiffness_m_per_rad") && p.selfAligningStiffness > 0)
    m.fail("self_aligning_stiffness_m_per_rad",
           "must not be positive: the self-aligning moment of a slip turns the wheel towards its velocity (k_mz = -trail k_alpha)");
  read("twisting_stiffness_m_per_rad", p.twistingStiffness);
  readRelaxation(m, f, p, preset != nullptr);
  read("radial_stiffness_N_per_m", p.radialStiffness);
  read("radial_damping_Ns_per_m", p.radialDamping);
  read("longitudinal_stiffness", p.longitudinalStiffness);
  m.finish();
  return p;
}

// The linear force law of the header on the shared tyre contact (tyres/tyre_contact.h).
class LinearTyreForce : public TyreForceElement {
 public:
  LinearTyreForce(SimTK::GeneralForceSubsystem& forces, const WheelSite& w, const LinearTyreParameters& p)
      : TyreForceElement(forces, w, {p.radialStiffness, p.radialDamping}, isLagged(p)), p_(p),
        loadFloor_(kCarcassLoadFloor * w.staticLoad) {
    checkCarcass(w);
  }

 protected:
  TyreContactForces calcTyreForces(const TyreKinematics& k, double z, double& slipDot) const override {
    const double ratio = p_.camberStiffness / p_.corneringStiffness;
    const LaggedSlip s = calcLaggedSlip(k.alpha + ratio * k.camber, k.alpha, isLagged(p_), z, k.V, calcRelaxationLength(k));
    slipDot = s.slipDot;
    TyreContactForces f;
    f.Fx = k.Fz * p_.longitudinalStiffness * k.kappa;
    f.Fy = k.Fz * p_.corneringStiffness * s.slip;
    // The slip part of the lagged state drives the self-aligning moment too (alpha lagged as Fy).
    f.Mz = k.Fz * (p_.selfAligningStiffness * s.alphaLagged + p_.twistingStiffness * k.camber);
    return f;
  }
  // The carcass's sigma at the load, floored at kCarcassLoadFloor of the static load (an unloading
  // wheel's lag rate V/sigma stays finite; its force Fz k_alpha s vanishes anyway).
  double calcRelaxationLength(const TyreKinematics& k) const override {
    if (!(p_.lateralCarcassStiffness > 0)) return p_.relaxationLength;
    return tyres::calcRelaxationLength(p_, std::max(k.Fz, loadFloor_), k.forwardSpeed);
  }

 private:
  // The carcass's sigma at the static load is at least kMinRelaxationLength over the speed range.
  void checkCarcass(const WheelSite& w) const {
    if (!(p_.lateralCarcassStiffness > 0)) return;
    const double vMax = scenario::SpeedRange::kMaxSpeed;
    const auto [factor, at] = findComplianceMinimum(p_.carcassSpeedCoefficient, p_.carcassSpeedCoefficient2, vMax);
    const double sigma = tyres::calcRelaxationLength(p_, w.staticLoad, at);
    if (!(sigma >= kMinRelaxationLength))
      throw io::InputError(p_.carcassWhere, "gives the " + w.name + "'s tyre a relaxation length of " + io::formatNumber(sigma, 4) +
                                                " m at its static load " + io::formatNumber(w.staticLoad, 6) + " N and " +
                                                io::formatNumber(at, 4) + " m/s (Fz k_alpha / k_y): at least " +
                                                io::formatNumber(kMinRelaxationLength) + " m");
  }

  static constexpr double kCarcassLoadFloor = 0.05;
  LinearTyreParameters p_;
  double loadFloor_;
};

class RelaxationLinear : public TyreContactModel {
 public:
  RelaxationLinear(const LinearTyreParameters& front, const LinearTyreParameters& rear)
      : TyreContactModel(false), front_(front), rear_(rear) {}

 protected:
  TyreForceElement* makeForceElement(BuildContext& ctx, const WheelSite& w) const override {
    return new LinearTyreForce(ctx.forces, w, paramsFor(w));
  }
  bool isLagged(const WheelSite& w) const override { return tyres::isLagged(paramsFor(w)); }

 private:
  const LinearTyreParameters& paramsFor(const WheelSite& w) const { return w.side == plugins::WheelSide::Front ? front_ : rear_; }
  LinearTyreParameters front_, rear_;
};

}  // namespace

// The linear law of the header, steady state, in ISO-W signs: alpha = -tan(alpha_ISO) (the contact's
// -(v_P . e_t)/V), phi = -gamma_ISO, so Fy = Fz (k_alpha alpha + k_phi phi), Mz = Fz (k_mz alpha + k_mt phi).
class LinearTyreForceLaw : public TyreForceLaw {
 public:
  explicit LinearTyreForceLaw(const LinearTyreParameters& p) : p_(p) {}
  TyreForces calcForces(const TyreSlip& in) const override {
    const double alpha = -std::tan(in.alpha), phi = -in.gamma;
    TyreForces f;
    f.Fx = in.Fz * p_.longitudinalStiffness * in.kappa;
    f.Fy = in.Fz * (p_.corneringStiffness * alpha + p_.camberStiffness * phi);
    f.Mz = in.Fz * (p_.selfAligningStiffness * alpha + p_.twistingStiffness * phi);
    return f;
  }
  double calcCorneringStiffness(double Fz) const override { return -Fz * p_.corneringStiffness; }
  double calcCamberStiffness(double Fz) const override { return -Fz * p_.camberStiffness; }
  double calcLongitudinalStiffness(double Fz) const override { return Fz * p_.longitudinalStiffness; }
  double calcRelaxationLength(double Fz, double, double Vx) const override { return tyres::calcRelaxationLength(p_, Fz, Vx); }
  double getNominalLoad() const override { return std::numeric_limits<double>::quiet_NaN(); }
  double getUnloadedRadius() const override { return std::numeric_limits<double>::quiet_NaN(); }

 private:
  LinearTyreParameters p_;
};

LinearTyreParameters getRelaxationLinearPreset(const std::string& name) {
  if (name != "bicycle") throw std::logic_error("unknown relaxation_linear preset '" + name + "'");
  // docs/scenario-format.md, "Bicycle tyre preset", gives each value's source.
  LinearTyreParameters p;
  p.corneringStiffness = 15.0;      // Dressel (2013): 0.15-0.35 /deg normalised, mean about 0.25 /deg
  p.camberStiffness = 0.9;          // Dell'Orto et al. (2024): 0.63-0.94 /rad; Dressel (2013) 0.43-0.86 /rad
  p.selfAligningStiffness = -0.24;  // pneumatic trail about 16 mm times k_alpha (Dell'Orto et al. 2024)
  p.twistingStiffness = 0.012;      // estimate, no published bicycle value found (see docs)
  p.relaxationLength = 0.1;         // Hjort & Niska (2018): earlier study about 0.1 m, their estimate 0.2-0.3 m
  p.radialStiffness = 1.0e5;        // Rothhaemel (2023): 31-147 N/mm, set by the inflation pressure
  p.radialDamping = 100;            // estimate (the linear modes barely depend on it)
  p.longitudinalStiffness = 20;     // estimate, motorcycle order (Cossalter 2006 ch. 2)
  return p;
}

std::vector<std::string> getRelaxationLinearPresetNames() { return {"bicycle"}; }

bool isLagged(const LinearTyreParameters& p) { return p.relaxationLength > 0 || p.lateralCarcassStiffness > 0; }

double calcCarcassComplianceFactor(const LinearTyreParameters& p, double speed) {
  const double V = std::min(std::abs(speed), scenario::SpeedRange::kMaxSpeed);
  return 1 + p.carcassSpeedCoefficient * V + p.carcassSpeedCoefficient2 * V * V;
}

double calcRelaxationLength(const LinearTyreParameters& p, double Fz, double speed) {
  if (!(p.lateralCarcassStiffness > 0)) return p.relaxationLength;
  return Fz * p.corneringStiffness * calcCarcassComplianceFactor(p, speed) / p.lateralCarcassStiffness;
}

std::string formatLinearTyre(const LinearTyreParameters& p) {
  auto f = [](double v) { return io::formatNumber(v, 17); };
  std::string s = "{cornering_stiffness_per_rad: " + f(p.corneringStiffness) + ", camber_stiffness_per_rad: " +
                  f(p.camberStiffness) + ", self_aligning_stiffness_m_per_rad: " + f(p.selfAligningStiffness) +
                  ", twisting_stiffness_m_per_rad: " + f(p.twistingStiffness) + ", radial_stiffness_N_per_m: " +
                  f(p.radialStiffness) + ", radial_damping_Ns_per_m: " + f(p.radialDamping) +
                  ", longitudinal_stiffness: " + f(p.longitudinalStiffness) + ", ";
  if (!(p.lateralCarcassStiffness > 0)) return s + "relaxation_length_m: " + f(p.relaxationLength) + "}";
  return s + kCarcassKey + ": " + f(p.lateralCarcassStiffness) + ", " + kSpeedKey + ": " + f(p.carcassSpeedCoefficient) +
         ", " + kSpeedKey2 + ": " + f(p.carcassSpeedCoefficient2) + "}";
}

std::unique_ptr<TyreForceLaw> makeLinearTyreForceLaw(const LinearTyreParameters& p) {
  return std::make_unique<LinearTyreForceLaw>(p);
}

const std::vector<io::SectionFields>& getRelaxationLinearFields() {
  using io::Field;
  using io::Shape;
  static const std::vector<io::SectionFields> all = [] {
    auto tyre = [](const char* side) {
      return Field::of(Shape::Other, side, "", "", std::string(side) + " tyre (section `contact." + side + "`); optional over a preset");
    };
    const io::SectionFields contact{
        "contact",
        {Field::of(Shape::Other, "model", "", "", "`relaxation_linear`"),
         Field::of(Shape::Other, "preset", "", "", "`bicycle`: both tyres from a measured set, each key given overrides it (below)").optional(),
         tyre("front"), tyre("rear")}};
    std::vector<io::SectionFields> out{contact.selectedBy("contact.model", "relaxation_linear")};
    for (const char* side : {"front", "rear"})
      out.push_back(io::SectionFields{std::string("contact.") + side, makeTyreFieldList()}.selectedBy("contact.model", "relaxation_linear"));
    return out;
  }();
  return all;
}

std::pair<LinearTyreParameters, LinearTyreParameters> readRelaxationLinearTyres(YamlMap& m) {
  const auto& sections = getRelaxationLinearFields();
  const io::SectionFields &front = sections[1], &rear = sections[2];
  if (!m.has("preset")) return {readTyre(m.getMap("front"), front, nullptr), readTyre(m.getMap("rear"), rear, nullptr)};
  const std::string name = m.getString("preset");
  const auto names = getRelaxationLinearPresetNames();
  if (std::find(names.begin(), names.end(), name) == names.end()) m.fail("preset", "unknown preset '" + name + "' (known: bicycle)");
  const LinearTyreParameters preset = getRelaxationLinearPreset(name);
  auto side = [&](const char* key, const io::SectionFields& f) {
    if (!m.has(key)) return preset;
    return readTyre(m.getMap(key), f, &preset);
  };
  const LinearTyreParameters frontTyre = side("front", front);
  return {frontTyre, side("rear", rear)};
}

std::unique_ptr<ContactModel> makeRelaxationLinear(const LinearTyreParameters& front, const LinearTyreParameters& rear) {
  return std::make_unique<RelaxationLinear>(front, rear);
}

void registerRelaxationLinear(PluginRegistrar& registry) {
  for (const io::SectionFields& f : getRelaxationLinearFields()) registry.addSectionFields(f);
  registry.addContactModel("relaxation_linear", [](YamlMap& m) -> std::unique_ptr<ContactModel> {
    const auto [front, rear] = readRelaxationLinearTyres(m);
    return makeRelaxationLinear(front, rear);
  });
}

}  // namespace motostab::tyres
