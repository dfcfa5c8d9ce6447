// MF 6.1/6.2: coefficients, force law and stiffnesses; the factory of the Magic Formula variants.
#include "tyres/magic_formula.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <sstream>
#include <vector>

#include "io/csv.h"

#include "tyres/motorcycle_magic_formula.h"

namespace motostab::tyres {

namespace {

double sgn(double x) { return (x > 0) - (x < 0); }

// The Magic Formula's sine and cosine versions: D sin(C atan(B x - E (B x - atan(B x)))).
double magicSin(double B, double C, double D, double E, double x) {
  const double Bx = B * x;
  return D * std::sin(C * std::atan(Bx - E * (Bx - std::atan(Bx))));
}
double magicCos(double B, double C, double E, double x) {
  const double Bx = B * x;
  return std::cos(C * std::atan(Bx - E * (Bx - std::atan(Bx))));
}

// MF 6.1 coefficients (Pacejka 2012 sec. 4.3.2), names as in the .tir file.
struct Mf61 {
  double FNOMIN, R0, NOMPRES, LONGVL, VXLOW, pressure;
  double LFZO, LCX, LMUX, LEX, LKX, LHX, LVX, LCY, LMUY, LEY, LKY, LKYC, LKZC, LHY, LVY, LTR, LRES, LXAL, LYKA,
      LVYKA, LS, LMX, LVMX, LMY, LSGAL, LSGKP;
  double PCX1, PDX1, PDX2, PDX3, PEX1, PEX2, PEX3, PEX4, PKX1, PKX2, PKX3, PHX1, PHX2, PVX1, PVX2, PPX1, PPX2, PPX3,
      PPX4, RBX1, RBX2, RBX3, RCX1, REX1, REX2, RHX1;
  double PCY1, PDY1, PDY2, PDY3, PEY1, PEY2, PEY3, PEY4, PEY5, PKY1, PKY2, PKY3, PKY4, PKY5, PKY6, PKY7, PHY1, PHY2,
      PVY1, PVY2, PVY3, PVY4, PPY1, PPY2, PPY3, PPY4, PPY5, RBY1, RBY2, RBY3, RBY4, RCY1, REY1, REY2, RHY1, RHY2,
      RVY1, RVY2, RVY3, RVY4, RVY5, RVY6;
  double PTY1 = 0, PTY2 = 0;                          ///< MF 5.2 relaxation (fallback, below)
  double CY0 = 0, PCFY1 = 0, PCFY2 = 0, PCFY3 = 0;    ///< lateral carcass stiffness, N/m (0: not given)
  double CX0 = 0, PCFX1 = 0, PCFX2 = 0, PCFX3 = 0;    ///< longitudinal carcass stiffness, N/m (0: not given)
  double QBZ1, QBZ2, QBZ3, QBZ4, QBZ5, QBZ6, QBZ9, QBZ10, QCZ1, QDZ1, QDZ2, QDZ3, QDZ4, QDZ6, QDZ7, QDZ8, QDZ9, QDZ10,
      QDZ11, QEZ1, QEZ2, QEZ3, QEZ4, QEZ5, QHZ1, QHZ2, QHZ3, QHZ4, SSZ1, SSZ2, SSZ3, SSZ4, PPZ1, PPZ2;
  double QSX1, QSX2, QSX3, QSX4, QSX5, QSX6, QSX7, QSX8, QSX9, QSX10, QSX11, QSX12, QSX13, QSX14, PPMX1;
  double QSY1, QSY2, QSY3, QSY4, QSY5, QSY6, QSY7, QSY8;
};

const std::vector<std::string> kMf61Scaling = {"LFZO", "LCX",  "LMUX", "LEX",  "LKX",  "LHX",   "LVX", "LCY",
                                               "LMUY", "LEY",  "LKY",  "LKYC", "LKZC", "LHY",   "LVY", "LTR",
                                               "LRES", "LXAL", "LYKA", "LVYKA", "LS",  "LMX",   "LVMX", "LMY",
                                               "LSGAL", "LSGKP"};

// A quadratic 1 + q1 x + q2 x^2 is positive on [lo, hi] (its ends and, if inside, its vertex).
bool isPositiveOn(double q1, double q2, double lo, double hi) {
  auto f = [&](double x) { return 1 + q1 * x + q2 * x * x; };
  if (!(f(lo) > 0) || !(f(hi) > 0)) return false;
  if (q2 != 0) {
    const double x = -q1 / (2 * q2);
    if (x > lo && x < hi && !(f(x) > 0)) return false;
  }
  return true;
}

// A carcass stiffness (N/m, positive) and its three load and pressure coefficients (0 when absent), if
// the source has the stiffness (Besselink, Schmeitz & Pacejka 2010, eqs. 17-18). The stiffness
// C0 (1 + c1 dfz + c2 dfz^2)(1 + c3 dpi) must stay positive over the checked loads (dfz from -1 to
// kCheckedLoadFactor - 1) at the pressure's dpi.
bool readCarcass(const CoefficientSource& s, const char* name, const std::array<const char*, 3>& names, double dpi,
                 double& stiffness, const std::array<double*, 3>& fields) {
  if (!s.find(name)) return false;
  stiffness = s.get(name);
  if (!(stiffness > 0)) s.fail(name, "must be positive");
  for (int i = 0; i < 3; ++i) *fields[i] = s.get(names[i], 0.0);
  if (!isPositiveOn(*fields[0], *fields[1], -1, kCheckedLoadFactor - 1))
    s.fail(names[0], std::string("with ") + names[1] + " makes " + name + " zero or negative between 0 and " +
                         std::to_string(static_cast<int>(kCheckedLoadFactor)) + " FNOMIN");
  if (!(1 + *fields[2] * dpi > 0)) s.fail(names[2], std::string("makes ") + name + " zero or negative at the inflation pressure");
  return true;
}

// The sign checks of readMf61 (docs/tyres.md, "What is refused").
void checkMf61Signs(const CoefficientSource& s, const Mf61& c) {
  const std::pair<const char*, double> positive[] = {
      {"FNOMIN", c.FNOMIN}, {"UNLOADED_RADIUS", c.R0}, {"NOMPRES", c.NOMPRES}, {"LONGVL", c.LONGVL}, {"VXLOW", c.VXLOW},
      {"PCX1", c.PCX1},     {"PDX1", c.PDX1},          {"PCY1", c.PCY1},       {"PDY1", c.PDY1}};
  for (const auto& [name, v] : positive)
    if (!(v > 0)) s.fail(name, "must be positive (got " + std::to_string(v) + ")");
  if (!(c.pressure > 0)) s.fail("INFLPRES", "must be positive");
  // K_ya = PKY1 Fz0' sin(PKY4 atan(Fz / ((PKY2 + PKY5 gamma^2) Fz0'))) (1 - PKY3 |gamma|) (ISO: K_ya < 0).
  if (!(c.PKY1 < 0))
    s.fail("PKY1", "must be negative in ISO signs (got " + io::formatNumber(c.PKY1, 6) +
                       "): the cornering stiffness PKY1 FNOMIN pushes against the slip; 0 gives none");
  if (!(c.PKY2 > 0))
    s.fail("PKY2", "must be positive (got " + io::formatNumber(c.PKY2, 6) +
                       "): the load at which the cornering stiffness peaks, PKY2 FNOMIN, divides Fz (0/0 at zero load)");
  // (1 - PKY3 |gamma|) keeps its sign up to the checked camber, 60 deg.
  if (!(1 - c.PKY3 * M_PI / 3 > 0))
    s.fail("PKY3", "must be below 3/pi = 0.955 (got " + io::formatNumber(c.PKY3, 6) +
                       "): the cornering stiffness's factor 1 - PKY3 |camber| would reach zero below 60 deg of camber");
  for (const auto& name : kMf61Scaling) {
    const std::string problem = findScalingProblem(name, s.getScaling(name));
    if (!problem.empty()) s.fail(name, problem);
  }
}

Mf61 readMf61(const CoefficientSource& s, std::optional<double> pressure) {
  Mf61 c{};
  std::vector<std::pair<const char*, double*>> required = {
      {"FNOMIN", &c.FNOMIN}, {"UNLOADED_RADIUS", &c.R0}, {"NOMPRES", &c.NOMPRES}, {"LONGVL", &c.LONGVL}, {"VXLOW", &c.VXLOW},
      {"PCX1", &c.PCX1}, {"PDX1", &c.PDX1}, {"PDX2", &c.PDX2}, {"PDX3", &c.PDX3}, {"PEX1", &c.PEX1}, {"PEX2", &c.PEX2},
      {"PEX3", &c.PEX3}, {"PEX4", &c.PEX4}, {"PKX1", &c.PKX1}, {"PKX2", &c.PKX2}, {"PKX3", &c.PKX3}, {"PHX1", &c.PHX1},
      {"PHX2", &c.PHX2}, {"PVX1", &c.PVX1}, {"PVX2", &c.PVX2}, {"PPX1", &c.PPX1}, {"PPX2", &c.PPX2}, {"PPX3", &c.PPX3},
      {"PPX4", &c.PPX4}, {"RBX1", &c.RBX1}, {"RBX2", &c.RBX2}, {"RBX3", &c.RBX3}, {"RCX1", &c.RCX1}, {"REX1", &c.REX1},
      {"REX2", &c.REX2}, {"RHX1", &c.RHX1},
      {"PCY1", &c.PCY1}, {"PDY1", &c.PDY1}, {"PDY2", &c.PDY2}, {"PDY3", &c.PDY3}, {"PEY1", &c.PEY1}, {"PEY2", &c.PEY2},
      {"PEY3", &c.PEY3}, {"PEY4", &c.PEY4}, {"PEY5", &c.PEY5}, {"PKY1", &c.PKY1}, {"PKY2", &c.PKY2}, {"PKY3", &c.PKY3},
      {"PKY4", &c.PKY4}, {"PKY5", &c.PKY5}, {"PKY6", &c.PKY6}, {"PKY7", &c.PKY7}, {"PHY1", &c.PHY1}, {"PHY2", &c.PHY2},
      {"PVY1", &c.PVY1}, {"PVY2", &c.PVY2}, {"PVY3", &c.PVY3}, {"PVY4", &c.PVY4}, {"PPY1", &c.PPY1}, {"PPY2", &c.PPY2},
      {"PPY3", &c.PPY3}, {"PPY4", &c.PPY4}, {"PPY5", &c.PPY5}, {"RBY1", &c.RBY1}, {"RBY2", &c.RBY2}, {"RBY3", &c.RBY3},
      {"RBY4", &c.RBY4}, {"RCY1", &c.RCY1}, {"REY1", &c.REY1}, {"REY2", &c.REY2}, {"RHY1", &c.RHY1}, {"RHY2", &c.RHY2},
      {"RVY1", &c.RVY1}, {"RVY2", &c.RVY2}, {"RVY3", &c.RVY3}, {"RVY4", &c.RVY4}, {"RVY5", &c.RVY5}, {"RVY6", &c.RVY6},
      {"QBZ1", &c.QBZ1}, {"QBZ2", &c.QBZ2}, {"QBZ3", &c.QBZ3}, {"QBZ4", &c.QBZ4}, {"QBZ5", &c.QBZ5}, {"QBZ9", &c.QBZ9},
      {"QBZ10", &c.QBZ10}, {"QCZ1", &c.QCZ1}, {"QDZ1", &c.QDZ1}, {"QDZ2", &c.QDZ2}, {"QDZ3", &c.QDZ3}, {"QDZ4", &c.QDZ4},
      {"QDZ6", &c.QDZ6}, {"QDZ7", &c.QDZ7}, {"QDZ8", &c.QDZ8}, {"QDZ9", &c.QDZ9}, {"QDZ10", &c.QDZ10},
      {"QDZ11", &c.QDZ11}, {"QEZ1", &c.QEZ1}, {"QEZ2", &c.QEZ2}, {"QEZ3", &c.QEZ3}, {"QEZ4", &c.QEZ4},
      {"QEZ5", &c.QEZ5}, {"QHZ1", &c.QHZ1}, {"QHZ2", &c.QHZ2}, {"QHZ3", &c.QHZ3}, {"QHZ4", &c.QHZ4}, {"SSZ1", &c.SSZ1},
      {"SSZ2", &c.SSZ2}, {"SSZ3", &c.SSZ3}, {"SSZ4", &c.SSZ4}, {"PPZ1", &c.PPZ1}, {"PPZ2", &c.PPZ2},
      {"QSX1", &c.QSX1}, {"QSX2", &c.QSX2}, {"QSX3", &c.QSX3}, {"QSX4", &c.QSX4}, {"QSX5", &c.QSX5}, {"QSX6", &c.QSX6},
      {"QSX7", &c.QSX7}, {"QSX8", &c.QSX8}, {"QSX9", &c.QSX9}, {"QSX10", &c.QSX10}, {"QSX11", &c.QSX11},
      {"PPMX1", &c.PPMX1}, {"QSY1", &c.QSY1}, {"QSY2", &c.QSY2}, {"QSY3", &c.QSY3}, {"QSY4", &c.QSY4},
      {"QSY5", &c.QSY5}, {"QSY6", &c.QSY6}, {"QSY7", &c.QSY7}, {"QSY8", &c.QSY8}};
  for (auto& [name, field] : required) *field = s.get(name);
  // Optional, 0 when absent: QBZ6 (camber squared in the trail slope, Pacejka 2012 eq. 4.E40; not a
  // key of MF-Tyre files) and QSX12-14 (overturning moment, MF-Tyre 6.1; files converted from MF 5.2
  // lack them).
  for (auto [name, field] : {std::pair<const char*, double*>{"QBZ6", &c.QBZ6}, {"QSX12", &c.QSX12}, {"QSX13", &c.QSX13},
                             {"QSX14", &c.QSX14}})
    *field = s.get(name, 0.0);
  if (!(c.NOMPRES > 0)) s.fail("NOMPRES", "must be positive");
  c.pressure = pressure ? *pressure : s.get("INFLPRES", c.NOMPRES);
  if (!(c.pressure > 0)) s.fail("INFLPRES", "must be positive");
  const double dpi = (c.pressure - c.NOMPRES) / c.NOMPRES;
  // Relaxation length: from the lateral carcass stiffness (MF 6.1/6.2) when the file gives it, else
  // from PTY1, PTY2 (the MF 5.2 form, positive for PTY1, PTY2 > 0), else none (the scenario must give one).
  const bool hasCy = readCarcass(s, "LATERAL_STIFFNESS", {"PCFY1", "PCFY2", "PCFY3"}, dpi, c.CY0, {&c.PCFY1, &c.PCFY2, &c.PCFY3});
  if (!hasCy && (s.find("PTY1") || s.find("PTY2"))) {
    c.PTY1 = s.get("PTY1");
    c.PTY2 = s.get("PTY2");
    if (!(c.PTY1 > 0)) s.fail("PTY1", "must be positive (the relaxation length is proportional to it)");
    if (!(c.PTY2 > 0)) s.fail("PTY2", "must be positive");
  }
  readCarcass(s, "LONGITUDINAL_STIFFNESS", {"PCFX1", "PCFX2", "PCFX3"}, dpi, c.CX0, {&c.PCFX1, &c.PCFX2, &c.PCFX3});
  // A mirrored (right-hand) fit would need the lateral signs flipped: not done, so refused.
  if (const auto side = s.findText("TYRESIDE")) {
    std::string v = *side;
    for (char& ch : v) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    if (v != "LEFT" && v != "SYMMETRIC")
      s.fail("TYRESIDE", "'" + *side + "': only 'Left' or 'Symmetric' fits are supported (no mirroring is done)");
  }
  std::vector<std::pair<const char*, double*>> scaling = {
      {"LFZO", &c.LFZO}, {"LCX", &c.LCX}, {"LMUX", &c.LMUX}, {"LEX", &c.LEX}, {"LKX", &c.LKX}, {"LHX", &c.LHX},
      {"LVX", &c.LVX}, {"LCY", &c.LCY}, {"LMUY", &c.LMUY}, {"LEY", &c.LEY}, {"LKY", &c.LKY}, {"LKYC", &c.LKYC},
      {"LKZC", &c.LKZC}, {"LHY", &c.LHY}, {"LVY", &c.LVY}, {"LTR", &c.LTR}, {"LRES", &c.LRES}, {"LXAL", &c.LXAL},
      {"LYKA", &c.LYKA}, {"LVYKA", &c.LVYKA}, {"LS", &c.LS}, {"LMX", &c.LMX}, {"LVMX", &c.LVMX}, {"LMY", &c.LMY},
      {"LSGAL", &c.LSGAL}, {"LSGKP", &c.LSGKP}};
  for (auto& [name, field] : scaling) *field = s.getScaling(name);
  checkMf61Signs(s, c);
  return c;
}

// MF 6.1/6.2 (Pacejka 2012 sec. 4.3.2), turn slip and speed-dependent friction left out (zeta = 1,
// lambda*_mu = lambda_mu, lambda'_mu with A_mu = 10); equation numbers of the book in the comments.
// Everything that depends on the coefficients and the pressure only is computed once, here.
class MagicFormula61 : public TyreForceLaw {
 public:
  explicit MagicFormula61(const Mf61& c) : c_(c) {
    Fz0p_ = c.FNOMIN * c.LFZO;
    const double dpi = (c.pressure - c.NOMPRES) / c.NOMPRES;
    dpi_ = dpi;
    const double A = 10;  // A_mu of 4.E8
    lmuxPrime_ = A * c.LMUX / (1 + (A - 1) * c.LMUX);
    lmuyPrime_ = A * c.LMUY / (1 + (A - 1) * c.LMUY);
    pKya_ = c.PKY1 * Fz0p_ * (1 + c.PPY1 * dpi) * c.LKY;
    pKyaPeak_ = 1 + c.PPY2 * dpi;
    pKyg_ = (1 + c.PPY5 * dpi) * c.LKYC;
    pKx_ = (1 + c.PPX1 * dpi + c.PPX2 * dpi * dpi) * c.LKX;
    pMux_ = (1 + c.PPX3 * dpi + c.PPX4 * dpi * dpi) * c.LMUX;
    pMuy_ = (1 + c.PPY3 * dpi + c.PPY4 * dpi * dpi) * c.LMUY;
    pDt_ = (1 - c.PPZ1 * dpi) * c.LTR;
    pDr_ = 1 + c.PPZ2 * dpi;
    pMx_ = 1 + c.PPMX1 * dpi;
    pMy_ = std::pow(c.pressure / c.NOMPRES, c.QSY8);
    pCy_ = 1 + c.PCFY3 * dpi;
  }

  TyreForces calcForces(const TyreSlip& in) const override {
    const Common k = makeCommon(in.Fz, in.gamma, in.alpha, in.Vx);
    const double Fz = in.Fz, g = k.gammaStar, g2 = g * g, dfz = k.dfz;
    const PureLateral py = calcPureLateral(k, Fz, g);
    const double Kxk = calcKxk(Fz, dfz);
    // Longitudinal, pure (4.E9-4.E18) and combined (4.E50-4.E57).
    const double Cx = c_.PCX1 * c_.LCX;
    const double Dx = (c_.PDX1 + c_.PDX2 * dfz) * pMux_ * (1 - c_.PDX3 * g2) * Fz;
    const double SHx = (c_.PHX1 + c_.PHX2 * dfz) * c_.LHX * k.w;
    const double kappax = in.kappa + SHx;
    const double Ex = std::min(1.0, (c_.PEX1 + c_.PEX2 * dfz + c_.PEX3 * dfz * dfz) * (1 - c_.PEX4 * sgn(kappax)) * c_.LEX);
    const double Bx = Kxk / (Cx * Dx + kEps);
    const double SVx = Fz * (c_.PVX1 + c_.PVX2 * dfz) * c_.LVX * lmuxPrime_ * k.w;
    const double Fx0 = magicSin(Bx, Cx, Dx, Ex, kappax) + SVx;
    const double Bxa = (c_.RBX1 + c_.RBX3 * g2) * cosAtan(c_.RBX2 * in.kappa) * c_.LXAL;
    const double Cxa = c_.RCX1, Exa = std::min(1.0, c_.REX1 + c_.REX2 * dfz), SHxa = c_.RHX1;
    const double Gxa = magicCos(Bxa, Cxa, Exa, k.alphaStar + SHxa) / (SHxa == 0 ? 1.0 : magicCos(Bxa, Cxa, Exa, SHxa));
    TyreForces f;
    f.Fx = Gxa * Fx0;
    // Lateral, combined (4.E58-4.E67).
    const double Gyk = calcGyk(k, in.kappa);
    const double DVyk = py.muy * Fz * (c_.RVY1 + c_.RVY2 * dfz + c_.RVY3 * g) * cosAtan(c_.RVY4 * k.alphaStar);
    const double SVyk = DVyk * std::sin(c_.RVY5 * std::atan(c_.RVY6 * in.kappa)) * c_.LVYKA;
    f.Fy = Gyk * py.Fy0 + SVyk;
    // Aligning moment, combined (4.E71-4.E78, with the pure-slip parts 4.E31-4.E49).
    f.Mz = calcAligning(k, Fz, in.kappa, py, Kxk, Gyk, f.Fx, f.Fy);
    // Overturning moment: 4.E69 with MF-Tyre 6.1's bracketing of the QSX4-6 term and its QSX12-14 terms
    // (Besselink, Schmeitz & Pacejka 2010, eq. 49), gamma* for gamma and Fz0' for Fz0 as in the rest.
    const double R0 = c_.R0, FyN = f.Fy / Fz0p_, FzN = Fz / Fz0p_;
    f.Mx = R0 * c_.LMX *
           (Fz * (c_.QSX1 * c_.LVMX * k.w - c_.QSX2 * g * pMx_ + c_.QSX3 * FyN +
                  c_.QSX4 * std::cos(c_.QSX5 * std::atan(square(c_.QSX6 * FzN))) *
                      std::sin(c_.QSX7 * g + c_.QSX8 * std::atan(c_.QSX9 * FyN)) +
                  c_.QSX10 * std::atan(c_.QSX11 * FzN) * g) +
            f.Fy * (c_.QSX13 + c_.QSX14 * std::abs(g)) - Fz * c_.QSX12 * g * std::abs(g));
    // Rolling resistance (4.E70), with sgn(Vx) so that it opposes the rolling either way.
    const double vr = in.Vx / c_.LONGVL;
    f.My = Fz <= 0 ? 0.0
                   : -R0 * Fz0p_ * c_.LMY * k.w * sgn(in.Vx) *
                         (c_.QSY1 + c_.QSY2 * f.Fx / Fz0p_ + c_.QSY3 * std::abs(vr) + c_.QSY4 * square(square(vr)) +
                          (c_.QSY5 + c_.QSY6 * FzN) * g2) *
                         std::pow(FzN, c_.QSY7) * pMy_;
    return f;
  }

  double calcCorneringStiffness(double Fz) const override { return calcKya(Fz, 0); }
  double calcCamberStiffness(double Fz) const override { return calcKyg0(Fz, (Fz - Fz0p_) / Fz0p_); }
  double calcLongitudinalStiffness(double Fz) const override { return calcKxk(Fz, (Fz - Fz0p_) / Fz0p_); }
  // MF 6.1/6.2: sigma_y = |K_ya / C_y| with C_y = LATERAL_STIFFNESS (1 + PCFY1 dfz + PCFY2 dfz^2)(1 + PCFY3 dpi)
  // (Besselink, Schmeitz & Pacejka 2010, eqs. 18-19; Pacejka 2012 sec. 7.2). Files without the carcass
  // stiffness but with PTY1, PTY2 get MF 5.2's PTY1 sin(2 atan(Fz/(PTY2 Fz0'))) (1 - PKY3 |gamma*|) R0 LFZO
  // LSGAL (the MF-Tyre 5.2 manual); else NaN.
  double calcRelaxationLength(double Fz, double gamma, double) const override {
    const double g = std::sin(gamma);
    if (c_.CY0 > 0) {
      const double dfz = (Fz - Fz0p_) / Fz0p_;
      const double Cy = c_.CY0 * (1 + c_.PCFY1 * dfz + c_.PCFY2 * dfz * dfz) * pCy_;
      return std::abs(calcKya(Fz, g) / Cy) * c_.LSGAL;
    }
    if (c_.PTY2 != 0)
      return c_.PTY1 * std::sin(2 * std::atan(Fz / (c_.PTY2 * Fz0p_))) * (1 - c_.PKY3 * std::abs(g)) * c_.R0 * c_.LFZO *
             c_.LSGAL;
    return std::numeric_limits<double>::quiet_NaN();
  }
  // sigma_x = |K_xk / C_x|, C_x = LONGITUDINAL_STIFFNESS (1 + PCFX1 dfz + PCFX2 dfz^2)(1 + PCFX3 dpi)
  // (Besselink et al. 2010, eqs. 17, 19), LSGKP applied; NaN without LONGITUDINAL_STIFFNESS.
  double calcLongitudinalRelaxationLength(double Fz) const override {
    if (!(c_.CX0 > 0)) return std::numeric_limits<double>::quiet_NaN();
    const double dfz = (Fz - Fz0p_) / Fz0p_;
    const double Cx = c_.CX0 * (1 + c_.PCFX1 * dfz + c_.PCFX2 * dfz * dfz) * (1 + c_.PCFX3 * dpi_);
    return std::abs(calcKxk(Fz, dfz) / Cx) * c_.LSGKP;
  }
  double getNominalLoad() const override { return Fz0p_; }
  double getUnloadedRadius() const override { return c_.R0; }
  double getReferenceSpeed() const override { return c_.LONGVL; }

 private:
  static constexpr double kEps = 1e-12;  // the book's epsilon against 0/0 at zero load, N

  struct Common {
    double dfz, alphaStar, gammaStar, cosAlpha;
    double w = 1;  ///< low-speed factor of the forces at zero slip (calcLowSpeedFactor)
  };
  // 4.E1-4.E8 (the pressure and scaling parts are in the constructor).
  Common makeCommon(double Fz, double gamma, double alpha, double Vx) const {
    Common k;
    k.dfz = (Fz - Fz0p_) / Fz0p_;
    k.alphaStar = std::tan(alpha);
    k.gammaStar = std::sin(gamma);
    k.cosAlpha = cosAtan(k.alphaStar);  // cos(alpha), |alpha| < pi/2
    k.w = calcLowSpeedFactor(Vx);
    return k;
  }
  // Not from the book: the forces at zero slip (SHx, SVx, SHy, SVy, the QDZ6-7 residual torque, the
  // QSX1 overturning offset and the rolling resistance) fade out below VXLOW as sin^2(pi/2 |Vx|/VXLOW):
  // at standstill no slip can balance them (MF-Tyre has a low-speed treatment of its own, not copied).
  double calcLowSpeedFactor(double Vx) const {
    const double v = std::abs(Vx) / c_.VXLOW;
    if (v >= 1) return 1;
    const double s = std::sin(M_PI / 2 * v);
    return s * s;
  }
  // K_ya (4.E25) at camber gamma* = g.
  double calcKya(double Fz, double g) const {
    return pKya_ * (1 - c_.PKY3 * std::abs(g)) *
           std::sin(c_.PKY4 * std::atan((Fz / Fz0p_) / ((c_.PKY2 + c_.PKY5 * g * g) * pKyaPeak_)));
  }
  // K_yg0 (4.E30).
  double calcKyg0(double Fz, double dfz) const { return Fz * (c_.PKY6 + c_.PKY7 * dfz) * pKyg_; }
  // K_xk (4.E15).
  double calcKxk(double Fz, double dfz) const { return Fz * (c_.PKX1 + c_.PKX2 * dfz) * std::exp(c_.PKX3 * dfz) * pKx_; }
  // G_yk (4.E59-4.E66).
  double calcGyk(const Common& k, double kappa) const {
    const double Byk =
        (c_.RBY1 + c_.RBY4 * k.gammaStar * k.gammaStar) * cosAtan(c_.RBY2 * (k.alphaStar - c_.RBY3)) * c_.LYKA;
    const double Cyk = c_.RCY1, Eyk = std::min(1.0, c_.REY1 + c_.REY2 * k.dfz), SHyk = c_.RHY1 + c_.RHY2 * k.dfz;
    return magicCos(Byk, Cyk, Eyk, kappa + SHyk) / (SHyk == 0 ? 1.0 : magicCos(Byk, Cyk, Eyk, SHyk));
  }

  struct PureLateral {
    double Fy0, Kya, By, Cy, muy, SHy, SVy;
  };
  // Pure side slip (4.E19-4.E30) at camber gamma* = g.
  PureLateral calcPureLateral(const Common& k, double Fz, double g) const {
    PureLateral p;
    const double dfz = k.dfz;
    p.Kya = calcKya(Fz, g);
    const double SVyg = Fz * (c_.PVY3 + c_.PVY4 * dfz) * g * c_.LKYC * lmuyPrime_;
    p.SVy = Fz * (c_.PVY1 + c_.PVY2 * dfz) * c_.LVY * lmuyPrime_ * k.w + SVyg;
    p.SHy = (c_.PHY1 + c_.PHY2 * dfz) * c_.LHY * k.w + (calcKyg0(Fz, dfz) * g - SVyg) / (p.Kya + kEps * sgnOr1(p.Kya));
    const double alphay = k.alphaStar + p.SHy;
    p.Cy = c_.PCY1 * c_.LCY;
    p.muy = (c_.PDY1 + c_.PDY2 * dfz) * pMuy_ * (1 - c_.PDY3 * g * g);
    const double Dy = p.muy * Fz;
    const double Ey =
        std::min(1.0, (c_.PEY1 + c_.PEY2 * dfz) * (1 + c_.PEY5 * g * g - (c_.PEY3 + c_.PEY4 * g) * sgn(alphay)) * c_.LEY);
    p.By = p.Kya / (p.Cy * Dy + kEps * sgnOr1(p.Cy * Dy));
    p.Fy0 = magicSin(p.By, p.Cy, Dy, Ey, alphay) + p.SVy;
    return p;
  }
  static double sgnOr1(double x) { return x < 0 ? -1.0 : 1.0; }

  // Mz = -t F'y + Mzr + s Fx (4.E71), F'y = G_yk Fy0(gamma = 0) (4.E74).
  double calcAligning(const Common& k, double Fz, double kappa, const PureLateral& py, double Kxk, double Gyk, double Fx,
                      double Fy) const {
    const double g = k.gammaStar, absG = std::abs(g), dfz = k.dfz, R0 = c_.R0;
    const double Kyap = py.Kya + kEps * sgnOr1(py.Kya);                                       // 4.E39
    const double SHt = c_.QHZ1 + c_.QHZ2 * dfz + (c_.QHZ3 + c_.QHZ4 * dfz) * g;                // 4.E35
    const double alphat = k.alphaStar + SHt;                                                   // 4.E34
    const double alphar = k.alphaStar + py.SHy + py.SVy / Kyap;                                // 4.E37-4.E38
    const double ratio = Kxk / Kyap * kappa;
    const double alphateq = std::sqrt(alphat * alphat + ratio * ratio) * sgn(alphat);         // 4.E77
    const double alphareq = std::sqrt(alphar * alphar + ratio * ratio) * sgn(alphar);         // 4.E78
    // 4.E40 with MF-Tyre 6.1's QBZ4 gamma term (Besselink et al. 2010, eq. A58) and the book's QBZ6.
    const double Bt = (c_.QBZ1 + c_.QBZ2 * dfz + c_.QBZ3 * dfz * dfz) * (1 + c_.QBZ4 * g + c_.QBZ5 * absG + c_.QBZ6 * g * g) *
                      c_.LKY / c_.LMUY;
    const double Ct = c_.QCZ1;                                                                 // 4.E41
    const double Dt = Fz * (R0 / Fz0p_) * (c_.QDZ1 + c_.QDZ2 * dfz) * pDt_ * (1 + c_.QDZ3 * absG + c_.QDZ4 * g * g);  // 4.E42-43
    const double Et = std::min(1.0, (c_.QEZ1 + c_.QEZ2 * dfz + c_.QEZ3 * dfz * dfz) *
                                        (1 + (c_.QEZ4 + c_.QEZ5 * g) * (2 / M_PI) * std::atan(Bt * Ct * alphat)));  // 4.E44
    const double t = Dt * magicCos(Bt, Ct, Et, alphateq) * k.cosAlpha;                        // 4.E73
    const double Br = c_.QBZ9 * c_.LKY / c_.LMUY + c_.QBZ10 * py.By * py.Cy;                  // 4.E45
    const double Dr = Fz * R0 *
                      ((c_.QDZ6 + c_.QDZ7 * dfz) * c_.LRES * k.w +
                       ((c_.QDZ8 + c_.QDZ9 * dfz) * pDr_ + (c_.QDZ10 + c_.QDZ11 * dfz) * absG) * g * c_.LKZC) *
                      c_.LMUY * k.cosAlpha;                                                    // 4.E47 (cos alpha here only)
    const double Mzr = Dr * cosAtan(Br * alphareq);                                            // 4.E75, Cr = 1 (4.E46)
    const double FyPrime = Gyk * (g == 0 ? py.Fy0 : calcPureLateral(k, Fz, 0.0).Fy0);         // 4.E74
    const double s = R0 * (c_.SSZ1 + c_.SSZ2 * Fy / Fz0p_ + (c_.SSZ3 + c_.SSZ4 * dfz) * g) * c_.LS;  // 4.E76
    return -t * FyPrime + Mzr + s * Fx;
  }

  static double square(double x) { return x * x; }
  static double cosAtan(double x) { return 1 / std::sqrt(1 + x * x); }  // cos(atan(x))

  Mf61 c_;
  // Constants of the coefficients and the pressure (constructor).
  double Fz0p_, dpi_, lmuxPrime_, lmuyPrime_, pKya_, pKyaPeak_, pKyg_, pKx_, pMux_, pMuy_, pDt_, pDr_, pMx_, pMy_, pCy_;
};

}  // namespace

std::optional<MagicFormulaVariant> parseMagicFormulaVariant(const std::string& name) {
  if (name == "mf61") return MagicFormulaVariant::MF61;
  if (name == "mf62") return MagicFormulaVariant::MF62;
  if (name == "motorcycle") return MagicFormulaVariant::Motorcycle;
  return std::nullopt;
}

std::optional<MotorcyclePaperAxes> parseMotorcyclePaperAxes(const std::string& name) {
  if (name == "z_down") return MotorcyclePaperAxes::ZDown;
  if (name == "z_up") return MotorcyclePaperAxes::ZUp;
  return std::nullopt;
}

std::optional<MotorcycleSlipVariable> parseMotorcycleSlipVariable(const std::string& name) {
  if (name == "angle") return MotorcycleSlipVariable::Angle;
  if (name == "tangent") return MotorcycleSlipVariable::Tangent;
  return std::nullopt;
}

const std::vector<std::string>& getScalingNames(MagicFormulaVariant v) {
  return v == MagicFormulaVariant::Motorcycle ? getMotorcycleScalingNames() : kMf61Scaling;
}

std::string findScalingProblem(const std::string& name, double value) {
  static const std::vector<std::string> positive = {"LFZO", "LMUX", "LMUY", "LCX", "LCY", "LKX", "LKY", "LSGAL", "LSGKP"};
  const bool mustBePositive = std::find(positive.begin(), positive.end(), name) != positive.end();
  if (!std::isfinite(value)) return "must be a finite number";
  if (mustBePositive && !(value > 0))
    return "must be positive (got " + std::to_string(value) + ")" +
           (name == "LSGAL" ? "; for no relaxation give the tyre relaxation_length_m: 0" : "");
  if (value < 0) return "must not be negative (got " + std::to_string(value) + "; 0 turns its term off)";
  return "";
}

std::unique_ptr<TyreForceLaw> makeTyreForceLaw(MagicFormulaVariant v, const CoefficientSource& source,
                                               std::optional<double> pressure, const MotorcycleConventions& motorcycle) {
  std::unique_ptr<TyreForceLaw> law;
  if (v == MagicFormulaVariant::Motorcycle)
    law = makeMotorcycleMagicFormula(source, motorcycle);
  else
    law = std::make_unique<MagicFormula61>(readMf61(source, pressure));
  const std::string problem = findForceLawProblem(*law);
  if (!problem.empty()) source.fail("", "these coefficients cannot be used: " + problem);
  return law;
}

namespace {

std::string describePoint(const TyreSlip& p) {
  std::ostringstream s;
  s << "Fz " << p.Fz << " N, slip angle " << p.alpha * 180 / M_PI << " deg, camber " << p.gamma * 180 / M_PI
    << " deg, slip ratio " << p.kappa << ", speed " << p.Vx << " m/s";
  return s.str();
}

bool isFinite(const TyreForces& f) {
  return std::isfinite(f.Fx) && std::isfinite(f.Fy) && std::isfinite(f.Mx) && std::isfinite(f.My) && std::isfinite(f.Mz);
}

// Forces and moments finite on the grid of the checked range (makeTyreForceLaw).
std::string findNonFinitePoint(const TyreForceLaw& law, double Fz0) {
  const double deg = M_PI / 180;
  for (double load : {0.0, 0.05, 1.0, 2.0, kCheckedLoadFactor})
    for (double alpha : {0.0, 2 * deg, -20 * deg, 89 * deg, -89 * deg})
      for (double gamma : {0.0, 20 * deg, 60 * deg, -60 * deg})
        for (double kappa : {0.0, 0.1, 1.0, -1.0})
          for (double V : {0.0, 60.0}) {
            const TyreSlip p{load * Fz0, kappa, alpha, gamma, V};
            if (!isFinite(law.calcForces(p))) return "a force or moment is not finite at " + describePoint(p);
          }
  return "";
}

// Slopes and slip forces with the right signs at positive loads, and the own relaxation length.
std::string findDegenerateLoad(const TyreForceLaw& law, double Fz0) {
  const bool hasRelaxation = !std::isnan(law.calcRelaxationLength(Fz0, 0, 0));
  for (double load : {0.05, 0.25, 0.5, 1.0, 2.0, kCheckedLoadFactor}) {
    const double Fz = load * Fz0;
    const std::string at = " at Fz " + io::formatNumber(Fz, 6) + " N";
    const double Kya = law.calcCorneringStiffness(Fz), Kxk = law.calcLongitudinalStiffness(Fz);
    if (!(std::isfinite(Kya) && Kya < 0)) return "the cornering stiffness " + io::formatNumber(Kya, 6) + " N/rad does not push against the slip" + at;
    if (!(std::isfinite(Kxk) && Kxk > 0)) return "the slip stiffness " + io::formatNumber(Kxk, 6) + " N is not finite and positive" + at;
    if (!std::isfinite(law.calcCamberStiffness(Fz))) return "the camber stiffness is not finite" + at;
    const double a = 5 * M_PI / 180, V = 20;
    if (!(law.calcForces({Fz, 0, a, 0, V}).Fy < law.calcForces({Fz, 0, -a, 0, V}).Fy))
      return "the side force does not oppose a 5 degree slip angle" + at;
    if (!(law.calcForces({Fz, 0.1, 0, 0, V}).Fx > law.calcForces({Fz, -0.1, 0, 0, V}).Fx))
      return "the longitudinal force does not oppose a 0.1 slip ratio" + at;
    if (!hasRelaxation) continue;
    for (double gamma : {0.0, 30 * M_PI / 180, 60 * M_PI / 180})
      for (double speed : {0.0, 10.0, 60.0}) {
        const double sigma = law.calcRelaxationLength(Fz, gamma, speed);
        if (!(std::isfinite(sigma) && sigma >= kMinRelaxationLength))
          return "the relaxation length " + io::formatNumber(sigma, 6) + " m is not finite and at least " +
                 io::formatNumber(kMinRelaxationLength, 6) + " m" + at + ", camber " +
                 io::formatNumber(gamma * 180 / M_PI, 3) + " deg, speed " + io::formatNumber(speed, 3) + " m/s";
      }
  }
  return "";
}

}  // namespace

std::string findForceLawProblem(const TyreForceLaw& law) {
  const double Fz0 = law.getNominalLoad();
  if (!(std::isfinite(Fz0) && Fz0 > 0)) return "the nominal load is not positive";
  const std::string nonFinite = findNonFinitePoint(law, Fz0);
  return nonFinite.empty() ? findDegenerateLoad(law, Fz0) : nonFinite;
}

}  // namespace motostab::tyres
