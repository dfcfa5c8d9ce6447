#include "tyres/magic_formula_contact.h"

#include <algorithm>
#include <cmath>

#include "io/input_error.h"
#include "tyres/magic_formula.h"
#include "tyres/magic_formula_tyre.h"
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
    checkCrownRadius(t, w.name, w.crownRadius);
    return new MagicFormulaTyreForce(ctx.forces, w, t);
  }
  bool isLagged(const WheelSite& w) const override { return tyreFor(w).isLagged(); }

 private:
  const MagicFormulaTyre& tyreFor(const WheelSite& w) const { return w.side == plugins::WheelSide::Front ? front_ : rear_; }
  MagicFormulaTyre front_, rear_;
};

}  // namespace

std::unique_ptr<ContactModel> makeMagicFormulaContact(MagicFormulaTyre front, MagicFormulaTyre rear) {
  return std::make_unique<MagicFormulaContact>(std::move(front), std::move(rear));
}

void registerMagicFormula(PluginRegistrar& registry) {
  using io::Field;
  using io::Shape;
  auto tyre = [](const char* side) {
    return Field::of(Shape::Other, side, "", "", std::string(side) + " tyre (section `contact." + side + "`)");
  };
  const io::SectionFields contact{"contact", {Field::of(Shape::Other, "model", "", "", "`magic_formula`"), tyre("front"), tyre("rear")}};
  registry.addSectionFields(contact.selectedBy("contact.model", "magic_formula"));
  for (const char* side : {"front", "rear"}) {
    io::SectionFields t = getMagicFormulaTyreFields();
    t.path = std::string("contact.") + side;
    registry.addSectionFields(t.selectedBy("contact.model", "magic_formula"));
  }
  registry.addContactModel("magic_formula", [](YamlMap& m) -> std::unique_ptr<ContactModel> {
    return makeMagicFormulaContact(readMagicFormulaTyre(m.getMap("front")), readMagicFormulaTyre(m.getMap("rear")));
  });
}

}  // namespace motostab::tyres
