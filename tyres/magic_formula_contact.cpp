#include "tyres/magic_formula_contact.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>

#include "io/input_error.h"
#include "tyres/magic_formula.h"
#include "tyres/tyre_contact.h"

namespace motostab::tyres {

using io::InputError;
using io::InputLocation;
using io::YamlMap;
using plugins::BuildContext;
using plugins::ContactModel;
using plugins::PluginRegistrar;
using plugins::WheelSite;


namespace {

// The load below which the cornering stiffness and the relaxation length are taken at this floor
// (fraction of the nominal load): keeps s_ss = Fy/C and V/sigma finite when a wheel unloads.
constexpr double kLoadFloor = 0.05;

struct MagicFormulaTyre {
  std::shared_ptr<const TyreForceLaw> law;
  double relaxationLength = std::numeric_limits<double>::quiet_NaN();  ///< m; NaN: the law's
  RadialLaw radial;
  InputLocation where;  ///< the tyre's scenario map, for errors found when the wheel is known
  bool isLagged() const { return std::isnan(relaxationLength) || relaxationLength > 0; }
};

std::map<std::string, double> readScaling(YamlMap& m, MagicFormulaVariant variant) {
  std::map<std::string, double> out;
  if (!m.has("scaling")) return out;
  YamlMap s = m.getMap("scaling");
  const auto& names = getScalingNames(variant);
  for (const auto& kv : s.getNode()) {
    const std::string name = kv.first.as<std::string>();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      std::string known;
      for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
      s.fail(name, "not a scaling factor of this Magic Formula variant (known: " + known + ")");
    }
    out[name] = s.getDouble(name);
  }
  s.finish();
  return out;
}

// A radial law value: the scenario's key, else the coefficient `fileKey` of the source.
double readRadial(YamlMap& m, const char* key, const CoefficientSource& source, const char* fileKey, bool positive) {
  const auto fromFile = source.find(fileKey);  // read always, so that an inline map's key counts as used
  if (m.has(key)) return positive ? m.getPositive(key) : m.getNonNegative(key);
  if (!fromFile) m.fail(key, std::string("missing: give it here or as ") + fileKey + " with the coefficients");
  if (positive ? !(*fromFile > 0) : !(*fromFile >= 0)) source.fail(fileKey, positive ? "must be positive" : "must be >= 0");
  return *fromFile;
}

MagicFormulaTyre readTyre(YamlMap m) {
  if (m.has("tir") == m.has("coefficients")) m.fail("tir", "give exactly one of `tir: FILE` and `coefficients: {...}`");
  std::optional<MagicFormulaVariant> variant;
  if (m.has("variant")) {
    variant = parseMagicFormulaVariant(m.getString("variant"));
    if (!variant) m.fail("variant", "unknown Magic Formula variant (known: mf61, mf62, motorcycle)");
  }
  std::optional<double> pressure;
  if (m.has("pressure_Pa")) pressure = m.getPositive("pressure_Pa");
  MagicFormulaTyre t;
  auto build = [&](const CoefficientSource& source) {
    t.law = makeTyreForceLaw(*variant, source, pressure);
    t.radial.stiffness = readRadial(m, "radial_stiffness_N_per_m", source, "VERTICAL_STIFFNESS", true);
    t.radial.damping = readRadial(m, "radial_damping_Ns_per_m", source, "VERTICAL_DAMPING", false);
  };
  if (m.has("tir")) {
    const std::string path = m.getFilePath("tir");
    if (!std::filesystem::is_regular_file(path)) m.fail("tir", "cannot open the tyre property file " + path);
    const TirFile file = TirFile::load(path);
    if (!variant) variant = file.getFitType() == 62 ? MagicFormulaVariant::MF62 : MagicFormulaVariant::MF61;
    const auto scaling = readScaling(m, *variant);
    const auto source = makeTirSource(file, &scaling);
    build(*source);
    warnUnused(*source, path, std::cerr);
  } else {
    if (!variant) m.fail("variant", "required with inline coefficients (mf61, mf62 or motorcycle)");
    const auto scaling = readScaling(m, *variant);
    YamlMap coefficients = m.getMap("coefficients");
    build(*makeYamlSource(coefficients, &scaling));
    coefficients.finish();
  }
  if (m.has("relaxation_length_m")) t.relaxationLength = m.getNonNegative("relaxation_length_m");
  t.where = m.locate();
  if (std::isnan(t.relaxationLength) && std::isnan(t.law->calcRelaxationLength(t.law->getNominalLoad(), 0, 0)))
    m.fail("relaxation_length_m", "required: this Magic Formula variant has no relaxation length of its own");
  if (!(-t.law->calcCorneringStiffness(t.law->getNominalLoad()) > 0))
    m.fail(m.has("tir") ? "tir" : "coefficients", "the cornering stiffness at the nominal load must push against the slip");
  m.finish();
  return t;
}

// The force law of the header on the shared tyre contact.
class MagicFormulaTyreForce : public TyreForceElement {
 public:
  MagicFormulaTyreForce(SimTK::GeneralForceSubsystem& forces, const WheelSite& w, const MagicFormulaTyre& t)
      : TyreForceElement(forces, w, t.radial, t.isLagged()), t_(t) {}

 protected:
  TyreContactForces calcTyreForces(const TyreKinematics& k, double z, double& slipDot) const override {
    const TyreForceLaw& law = *t_.law;
    const double gammaIso = -k.camber;
    slipDot = 0;
    if (!t_.isLagged()) return toContactForces(law.calcForces({k.Fz, k.kappa, std::atan(-k.alpha), gammaIso, k.forwardSpeed}));
    // The linear equivalent slip alpha + (K_yg/K_ya) phi relaxes (the ratio of the ISO stiffnesses is
    // the project's k_phi/k_alpha); every force comes from the law at the lagged slip angle.
    const double Fz = std::max(k.Fz, kLoadFloor * law.getNominalLoad());
    const double ratio = law.calcCamberStiffness(Fz) / law.calcCorneringStiffness(Fz);
    const LaggedSlip s = calcLaggedSlip(k.alpha + ratio * k.camber, k.alpha, true, z, k.V, calcRelaxationLength(k));
    slipDot = s.slipDot;
    return toContactForces(law.calcForces({k.Fz, k.kappa, std::atan(-s.alphaLagged), gammaIso, k.forwardSpeed}));
  }

  static TyreContactForces toContactForces(const TyreForces& f) {
    TyreContactForces out;
    out.Fx = f.Fx;
    out.Fy = f.Fy;
    out.Mx = f.Mx;
    out.My = f.My;
    out.Mz = f.Mz;
    return out;
  }

  double calcRelaxationLength(const TyreKinematics& k) const override {
    if (!std::isnan(t_.relaxationLength)) return t_.relaxationLength;
    const TyreForceLaw& law = *t_.law;
    return law.calcRelaxationLength(std::max(k.Fz, kLoadFloor * law.getNominalLoad()), -k.camber, k.forwardSpeed);
  }

 private:
  MagicFormulaTyre t_;
};

class MagicFormulaContact : public TyreContactModel {
 public:
  MagicFormulaContact(MagicFormulaTyre front, MagicFormulaTyre rear)
      : TyreContactModel(true), front_(std::move(front)), rear_(std::move(rear)) {}

 protected:
  TyreForceElement* makeForceElement(BuildContext& ctx, const WheelSite& w) const override {
    // A law whose moments use a crown radius (the motorcycle one) must be on a wheel of that crown.
    const MagicFormulaTyre& t = tyreFor(w);
    const double crown = t.law->getCrownRadius();
    if (!std::isnan(crown) && std::abs(crown - w.crownRadius) > 1e-9)
      throw InputError(t.where, "CROWN_RADIUS " + std::to_string(crown) + " m of the coefficients differs from " + w.name +
                                    ".crown_radius_m " + std::to_string(w.crownRadius) + " m");
    return new MagicFormulaTyreForce(ctx.forces, w, t);
  }
  bool isLagged(const WheelSite& w) const override { return tyreFor(w).isLagged(); }

 private:
  const MagicFormulaTyre& tyreFor(const WheelSite& w) const { return w.side == plugins::WheelSide::Front ? front_ : rear_; }
  MagicFormulaTyre front_, rear_;
};

}  // namespace

void registerMagicFormula(PluginRegistrar& registry) {
  registry.addContactModel("magic_formula", [](YamlMap& m) -> std::unique_ptr<ContactModel> {
    return std::make_unique<MagicFormulaContact>(readTyre(m.getMap("front")), readTyre(m.getMap("rear")));
  });
}

}  // namespace motostab::tyres
