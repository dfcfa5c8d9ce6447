#include "tyres/motorcycle_magic_formula.h"

#include <cmath>
#include <limits>

namespace motostab::tyres {

namespace {

double sgn(double x) { return (x > 0) - (x < 0); }

// x - E (x - atan x): the Magic Formula's curvature-corrected argument.
double curved(double x, double E) { return x - E * (x - std::atan(x)); }

struct Coefficients {
  double FNOMIN, R0, crown, LFZO, LMUX, LKX, LMUY, LKY, LKYC, LTR, LRES;
  double PCX1, PDX1, PDX2, PEX1, PEX2, PEX3, PEX4, PKX1, PKX2, PKX3;
  double PCY1, PCY2, PDY1, PDY2, PDY3, PEY1, PEY2, PEY4, PEY5, PKY1, PKY2, PKY3, PKY4, PKY5, PKY6, PKY7;
  double QHZ3, QHZ4, QBZ1, QBZ2, QBZ5, QBZ6, QBZ9, QBZ10, QCZ1, QDZ1, QDZ2, QDZ3, QDZ4, QDZ8, QDZ9, QDZ10, QDZ11, QEZ1,
      QEZ2, QEZ3, QEZ5;
  double RBX1, RBX2, RCX1, RBY1, RBY2, RBY3, RCY1;
  double relax[3] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                      std::numeric_limits<double>::quiet_NaN()};  ///< c1 (m/N), c2 (s/N), c3 (s^2/(N m)) of sigma = K_ya (c1 + c2 V + c3 V^2)
};

const std::vector<std::string> kScaling = {"LFZO", "LMUX", "LKX", "LMUY", "LKY", "LKYC", "LTR", "LRES"};

class MotorcycleMagicFormula : public TyreForceLaw {
 public:
  MotorcycleMagicFormula(const Coefficients& c, const MotorcycleConventions& conventions)
      : c_(c), sign_(conventions.axes == MotorcyclePaperAxes::ZDown ? 1.0 : -1.0), angle_(conventions.slip == MotorcycleSlipVariable::Angle) {}

  // The paper's equations at a = sign (alpha or tan alpha), g = sign gamma; Fy and Mz back to ISO by
  // -sign (the paper's y and z are -sign times ISO's), Fx unchanged.
  TyreForces calcForces(const TyreSlip& in) const override {
    const double a = sign_ * (angle_ ? in.alpha : std::tan(in.alpha)), g = sign_ * in.gamma, k = in.kappa, Fz = in.Fz;
    const double dfz = calcDfz(Fz);
    const Lateral lat = calcLateral(Fz, dfz, a, g);
    const Lateral lat0 = g == 0 ? lat : calcLateral(Fz, dfz, a, 0.0);  // the camber-free side force
    const double Kx = calcKx(Fz, dfz);
    const double Gyk = std::cos(c_.RCY1 * std::atan(c_.RBY1 * std::cos(std::atan(c_.RBY2 * (a - c_.RBY3))) * k));
    TyreForces f;
    f.Fx = calcFx0(Fz, dfz, Kx, k) * std::cos(c_.RCX1 * std::atan(c_.RBX1 * std::cos(std::atan(c_.RBX2 * k)) * a));
    f.Fy = -sign_ * Gyk * lat.Fy0;
    f.Mz = -sign_ * calcAligning(Fz, dfz, Kx, k, a, g, lat0, Gyk);
    return f;
  }

  // ISO signs: dFy/dalpha_ISO = -sign dFy/da sign = -K_ya, likewise for camber.
  double calcCorneringStiffness(double Fz) const override { return -calcKya(Fz, 0); }
  double calcCamberStiffness(double Fz) const override { return -calcKyg(Fz, calcDfz(Fz)); }
  double calcLongitudinalStiffness(double Fz) const override { return calcKx(Fz, calcDfz(Fz)); }
  // sigma = K_ya (c1 + c2 V + c3 V^2) (Sharp et al. 2004 sec. 4; Evangelou 2004 Table 9.5), K_ya at the
  // camber (even in it); NaN without the c's.
  double calcRelaxationLength(double Fz, double gamma, double Vx) const override {
    const double V = std::abs(Vx);
    return calcKya(Fz, gamma) * (c_.relax[0] + c_.relax[1] * V + c_.relax[2] * V * V);
  }
  double getNominalLoad() const override { return calcFz0(); }
  double getUnloadedRadius() const override { return c_.R0; }
  double getCrownRadius() const override { return c_.crown; }

 private:
  static constexpr double kEps = 1e-12;
  double calcFz0() const { return c_.FNOMIN * c_.LFZO; }
  double calcDfz(double Fz) const { return (Fz - calcFz0()) / calcFz0(); }
  double calcKx(double Fz, double dfz) const { return Fz * (c_.PKX1 + c_.PKX2 * dfz) * std::exp(c_.PKX3 * dfz) * c_.LKX; }
  // K_ya = PKY1 Fz0 sin(PKY2 atan(Fz/((PKY3 + PKY4 g^2) Fz0)))/(1 + PKY5 g^2) (Sharp et al. 2004 sec. 4).
  double calcKya(double Fz, double g) const {
    const double Fz0 = calcFz0(), g2 = g * g;
    return c_.PKY1 * Fz0 * std::sin(c_.PKY2 * std::atan(Fz / ((c_.PKY3 + c_.PKY4 * g2) * Fz0))) / (1 + c_.PKY5 * g2) * c_.LKY;
  }
  // K_yg = (PKY6 + PKY7 dfz) Fz (Sharp et al. 2004 sec. 4).
  double calcKyg(double Fz, double dfz) const { return (c_.PKY6 + c_.PKY7 * dfz) * Fz * c_.LKYC; }
  // Pure longitudinal slip.
  double calcFx0(double Fz, double dfz, double Kx, double k) const {
    const double Cx = c_.PCX1, Dx = (c_.PDX1 + c_.PDX2 * dfz) * c_.LMUX * Fz;
    const double Ex = (c_.PEX1 + c_.PEX2 * dfz + c_.PEX3 * dfz * dfz) * (1 - c_.PEX4 * sgn(k));
    return Dx * std::sin(Cx * std::atan(curved(Kx / (Cx * Dx + kEps) * k, Ex)));
  }

  struct Lateral {
    double Fy0, Kya, By;
  };
  // Pure side slip and camber in the paper's signs: slip a and camber g (rad).
  Lateral calcLateral(double Fz, double dfz, double a, double g) const {
    Lateral l;
    const double Cy = c_.PCY1, Cg = c_.PCY2;
    const double Dy = c_.PDY1 * std::exp(c_.PDY2 * dfz) / (1 + c_.PDY3 * g * g) * c_.LMUY * Fz;
    l.Kya = calcKya(Fz, g);
    l.By = l.Kya / (Cy * Dy + kEps);
    const double Bg = calcKyg(Fz, dfz) / (Cg * Dy + kEps);
    const double Ey = c_.PEY1 + c_.PEY2 * g * g + c_.PEY4 * g * sgn(a);
    l.Fy0 = Dy * std::sin(Cy * std::atan(curved(l.By * a, Ey)) + Cg * std::atan(curved(Bg * g, c_.PEY5)));
    return l;
  }

  // Aligning moment in the paper's signs: the trail acts on the camber-free side force and its slip is
  // unshifted; the camber shift S_Hr = (QHZ3 + QHZ4 dfz) g moves the residual-torque slip only; the
  // combined-slip equivalent slips use K_ya at zero camber.
  double calcAligning(double Fz, double dfz, double Kx, double k, double a, double g, const Lateral& lat0, double Gyk) const {
    const double ratio = Kx * k / (lat0.Kya + kEps);
    const double ar = a + (c_.QHZ3 + c_.QHZ4 * dfz) * g;
    const double ateq = std::sqrt(a * a + ratio * ratio) * sgn(a);
    const double areq = std::sqrt(ar * ar + ratio * ratio) * sgn(ar);
    const double cosA = 1 / std::sqrt(1 + a * a);
    const double absG = std::abs(g);
    const double Bt = (c_.QBZ1 + c_.QBZ2 * dfz) * (1 + c_.QBZ5 * absG + c_.QBZ6 * g * g);
    const double Ct = c_.QCZ1;
    const double Dt = Fz * (c_.crown / calcFz0()) * (c_.QDZ1 + c_.QDZ2 * dfz) * (1 + c_.QDZ3 * absG + c_.QDZ4 * g * g) * c_.LTR;
    const double Et = (c_.QEZ1 + c_.QEZ2 * dfz + c_.QEZ3 * dfz * dfz) * (1 + c_.QEZ5 * g * (2 / M_PI) * std::atan(Bt * Ct * a));
    const double t = Dt * std::cos(Ct * std::atan(curved(Bt * ateq, Et))) * cosA;
    const double Br = c_.QBZ9 + c_.QBZ10 * lat0.By * c_.PCY1;
    const double Dr = Fz * c_.crown * ((c_.QDZ8 + c_.QDZ9 * dfz) * g + (c_.QDZ10 + c_.QDZ11 * dfz) * g * absG) * c_.LRES * cosA;
    return -t * Gyk * lat0.Fy0 + Dr * std::cos(std::atan(Br * areq));
  }

  Coefficients c_;
  double sign_;  ///< +1: the paper's axes are ISO turned by pi about x (z down); -1: ISO's
  bool angle_;   ///< the slip variable is the angle (else its tangent)
};

// The relaxation law's c1, c2, c3: all three or none; with them, c1 > 0 (the length at standstill is
// K_ya c1) and c1 + c2 V + c3 V^2 > 0 at every speed V >= 0.
void readRelaxation(const CoefficientSource& s, Coefficients& c) {
  const char* names[] = {"RELAX_C1", "RELAX_C2", "RELAX_C3"};
  int given = 0;
  for (int i = 0; i < 3; ++i) {
    if (const auto v = s.find(names[i])) {
      c.relax[i] = *v;
      ++given;
    }
  }
  if (given == 0) return;
  if (given != 3) s.fail("RELAX_C1", "give all of RELAX_C1, RELAX_C2, RELAX_C3 or none");
  const double c1 = c.relax[0], c2 = c.relax[1], c3 = c.relax[2];
  if (!(c1 > 0)) s.fail("RELAX_C1", "must be positive (the relaxation length at standstill is K_ya RELAX_C1)");
  if (c3 < 0) s.fail("RELAX_C3", "must not be negative (the relaxation length would turn negative at high speed)");
  if (c2 < 0 && !(c2 * c2 < 4 * c1 * c3))
    s.fail("RELAX_C2", "with RELAX_C1 and RELAX_C3 makes the relaxation length zero or negative at some speed");
}

// Signs the equations need (docs/tyres.md, "What is refused"); scaling factors by findScalingProblem.
void checkSigns(const CoefficientSource& s, const Coefficients& c) {
  const std::pair<const char*, double> positive[] = {
      {"FNOMIN", c.FNOMIN}, {"UNLOADED_RADIUS", c.R0}, {"CROWN_RADIUS", c.crown}, {"PCX1", c.PCX1}, {"PDX1", c.PDX1},
      {"PKX1", c.PKX1},     {"PCY1", c.PCY1},          {"PCY2", c.PCY2},         {"PDY1", c.PDY1}, {"PKY1", c.PKY1}};
  for (const auto& [name, v] : positive)
    if (!(v > 0)) s.fail(name, "must be positive (got " + std::to_string(v) + ")");
  // K_ya's divisors PKY3 + PKY4 g^2 and 1 + PKY5 g^2 stay positive up to 90 degrees of camber.
  if (!(c.PKY3 > 0)) s.fail("PKY3", "must be positive (got " + std::to_string(c.PKY3) + "): PKY3 FNOMIN divides Fz in the cornering stiffness");
  if (!(c.PKY3 + c.PKY4 * M_PI * M_PI / 4 > 0))
    s.fail("PKY4", "with PKY3 makes PKY3 + PKY4 camber^2 zero or negative below 90 deg of camber");
  if (!(1 + c.PKY5 * M_PI * M_PI / 4 > 0)) s.fail("PKY5", "must be above -4/pi^2 (the cornering stiffness would change sign with camber)");
  // 1 + PDY3 g^2 > 0 up to 90 degrees of camber.
  if (!(c.PDY3 > -4 / (M_PI * M_PI))) s.fail("PDY3", "must be above -4/pi^2 (the friction would change sign with camber)");
  for (const char* name : {"LFZO", "LMUX", "LKX", "LMUY", "LKY", "LKYC", "LTR", "LRES"}) {
    const std::string problem = findScalingProblem(name, s.getScaling(name));
    if (!problem.empty()) s.fail(name, problem);
  }
}

}  // namespace

const std::vector<std::string>& getMotorcycleScalingNames() { return kScaling; }

std::unique_ptr<TyreForceLaw> makeMotorcycleMagicFormula(const CoefficientSource& s, const MotorcycleConventions& conventions) {
  Coefficients c{};
  const std::pair<const char*, double*> required[] = {
      {"FNOMIN", &c.FNOMIN}, {"UNLOADED_RADIUS", &c.R0}, {"CROWN_RADIUS", &c.crown}, {"PCX1", &c.PCX1}, {"PDX1", &c.PDX1}, {"PDX2", &c.PDX2},
      {"PEX1", &c.PEX1}, {"PEX2", &c.PEX2}, {"PEX3", &c.PEX3}, {"PEX4", &c.PEX4}, {"PKX1", &c.PKX1}, {"PKX2", &c.PKX2},
      {"PKX3", &c.PKX3}, {"PCY1", &c.PCY1}, {"PCY2", &c.PCY2}, {"PDY1", &c.PDY1}, {"PEY1", &c.PEY1}, {"PEY2", &c.PEY2},
      {"PEY4", &c.PEY4}, {"PEY5", &c.PEY5}, {"PKY1", &c.PKY1}, {"PKY2", &c.PKY2}, {"PKY3", &c.PKY3}, {"PKY4", &c.PKY4},
      {"PKY5", &c.PKY5}, {"PKY6", &c.PKY6}, {"PKY7", &c.PKY7}, {"QHZ3", &c.QHZ3}, {"QHZ4", &c.QHZ4}, {"QBZ1", &c.QBZ1},
      {"QBZ2", &c.QBZ2}, {"QBZ5", &c.QBZ5}, {"QBZ6", &c.QBZ6}, {"QBZ9", &c.QBZ9}, {"QBZ10", &c.QBZ10}, {"QCZ1", &c.QCZ1},
      {"QDZ1", &c.QDZ1}, {"QDZ2", &c.QDZ2}, {"QDZ3", &c.QDZ3}, {"QDZ4", &c.QDZ4}, {"QDZ8", &c.QDZ8}, {"QDZ9", &c.QDZ9},
      {"QDZ10", &c.QDZ10}, {"QDZ11", &c.QDZ11}, {"QEZ1", &c.QEZ1}, {"QEZ2", &c.QEZ2},
      {"QEZ5", &c.QEZ5}, {"RBX1", &c.RBX1}, {"RBX2", &c.RBX2}, {"RCX1", &c.RCX1}, {"RBY1", &c.RBY1}, {"RBY2", &c.RBY2},
      {"RBY3", &c.RBY3}, {"RCY1", &c.RCY1}};
  for (const auto& [name, field] : required) *field = s.get(name);
  // Optional terms, 0 when absent (docs/tyres.md, "The motorcycle conventions").
  for (auto [name, field] : {std::pair<const char*, double*>{"PDY2", &c.PDY2}, {"PDY3", &c.PDY3}, {"QEZ3", &c.QEZ3}})
    *field = s.get(name, 0.0);
  const std::pair<const char*, double*> scaling[] = {{"LFZO", &c.LFZO}, {"LMUX", &c.LMUX}, {"LKX", &c.LKX},
                                                     {"LMUY", &c.LMUY}, {"LKY", &c.LKY},   {"LKYC", &c.LKYC},
                                                     {"LTR", &c.LTR},   {"LRES", &c.LRES}};
  for (const auto& [name, field] : scaling) *field = s.getScaling(name);
  checkSigns(s, c);
  readRelaxation(s, c);
  return std::make_unique<MotorcycleMagicFormula>(c, conventions);
}

}  // namespace motostab::tyres
