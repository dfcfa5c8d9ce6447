#include "tyres/magic_formula.h"

#include <cmath>
#include <vector>

#include "tyres/motorcycle_magic_formula.h"

namespace motostab {

std::optional<double> CoefficientSource::find(const std::string& name) const {
  if (scaling_) {
    const auto it = scaling_->find(name);
    if (it != scaling_->end()) return it->second;
  }
  return findOwn(name);
}

double CoefficientSource::get(const std::string& name) const {
  const auto v = find(name);
  if (!v) fail(name, "missing coefficient (needed by the chosen Magic Formula equations)");
  return *v;
}

double CoefficientSource::getScaling(const std::string& name) const { return get(name, 1.0); }

double CoefficientSource::get(const std::string& name, double fallback) const {
  const auto v = find(name);
  return v ? *v : fallback;
}

namespace {

class TirSource : public CoefficientSource {
 public:
  TirSource(const TirFile& f, const std::map<std::string, double>* scaling) : CoefficientSource(scaling), f_(f) {}
  [[noreturn]] void fail(const std::string& name, const std::string& message) const override { f_.fail(name, message); }

 protected:
  std::optional<double> findOwn(const std::string& name) const override {
    if (!f_.find(name)) return std::nullopt;
    return f_.getNumber(name);
  }

 private:
  const TirFile& f_;
};

class YamlSource : public CoefficientSource {
 public:
  YamlSource(YamlMap& m, const std::map<std::string, double>* scaling) : CoefficientSource(scaling), m_(m) {}
  [[noreturn]] void fail(const std::string& name, const std::string& message) const override { m_.fail(name, message); }

 protected:
  std::optional<double> findOwn(const std::string& name) const override {
    if (!m_.has(name)) return std::nullopt;
    return m_.getDouble(name);
  }

 private:
  YamlMap& m_;
};

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
      LVYKA, LS, LMX, LVMX, LMY, LSGAL;
  double PCX1, PDX1, PDX2, PDX3, PEX1, PEX2, PEX3, PEX4, PKX1, PKX2, PKX3, PHX1, PHX2, PVX1, PVX2, PPX1, PPX2, PPX3,
      PPX4, RBX1, RBX2, RBX3, RCX1, REX1, REX2, RHX1;
  double PCY1, PDY1, PDY2, PDY3, PEY1, PEY2, PEY3, PEY4, PEY5, PKY1, PKY2, PKY3, PKY4, PKY5, PKY6, PKY7, PHY1, PHY2,
      PVY1, PVY2, PVY3, PVY4, PPY1, PPY2, PPY3, PPY4, PPY5, RBY1, RBY2, RBY3, RBY4, RCY1, REY1, REY2, RHY1, RHY2,
      RVY1, RVY2, RVY3, RVY4, RVY5, RVY6, PTY1, PTY2;
  double QBZ1, QBZ2, QBZ3, QBZ5, QBZ6, QBZ9, QBZ10, QCZ1, QDZ1, QDZ2, QDZ3, QDZ4, QDZ6, QDZ7, QDZ8, QDZ9, QDZ10,
      QDZ11, QEZ1, QEZ2, QEZ3, QEZ4, QEZ5, QHZ1, QHZ2, QHZ3, QHZ4, SSZ1, SSZ2, SSZ3, SSZ4, PPZ1, PPZ2;
  double QSX1, QSX2, QSX3, QSX4, QSX5, QSX6, QSX7, QSX8, QSX9, QSX10, QSX11, PPMX1;
  double QSY1, QSY2, QSY3, QSY4, QSY5, QSY6, QSY7, QSY8;
};

const std::vector<std::string> kMf61Scaling = {"LFZO", "LCX",  "LMUX", "LEX",  "LKX",  "LHX",   "LVX", "LCY",
                                               "LMUY", "LEY",  "LKY",  "LKYC", "LKZC", "LHY",   "LVY", "LTR",
                                               "LRES", "LXAL", "LYKA", "LVYKA", "LS",  "LMX",   "LVMX", "LMY",
                                               "LSGAL"};

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
      {"PTY1", &c.PTY1}, {"PTY2", &c.PTY2},
      {"QBZ1", &c.QBZ1}, {"QBZ2", &c.QBZ2}, {"QBZ3", &c.QBZ3}, {"QBZ5", &c.QBZ5}, {"QBZ9", &c.QBZ9},
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
  // QBZ6 (camber squared in the trail slope) is new in MF 6.1; files converted from MF 5.2 lack it.
  c.QBZ6 = s.get("QBZ6", 0.0);
  // MF 6.2's further overturning-moment terms are not implemented: they must be absent or zero.
  for (const char* name : {"QSX12", "QSX13", "QSX14"})
    if (s.get(name, 0.0) != 0.0) s.fail(name, "nonzero, but this reader does not implement this MF 6.2 term");
  std::vector<std::pair<const char*, double*>> scaling = {
      {"LFZO", &c.LFZO}, {"LCX", &c.LCX}, {"LMUX", &c.LMUX}, {"LEX", &c.LEX}, {"LKX", &c.LKX}, {"LHX", &c.LHX},
      {"LVX", &c.LVX}, {"LCY", &c.LCY}, {"LMUY", &c.LMUY}, {"LEY", &c.LEY}, {"LKY", &c.LKY}, {"LKYC", &c.LKYC},
      {"LKZC", &c.LKZC}, {"LHY", &c.LHY}, {"LVY", &c.LVY}, {"LTR", &c.LTR}, {"LRES", &c.LRES}, {"LXAL", &c.LXAL},
      {"LYKA", &c.LYKA}, {"LVYKA", &c.LVYKA}, {"LS", &c.LS}, {"LMX", &c.LMX}, {"LVMX", &c.LVMX}, {"LMY", &c.LMY},
      {"LSGAL", &c.LSGAL}};
  for (auto& [name, field] : scaling) *field = s.getScaling(name);
  c.pressure = pressure ? *pressure : s.get("INFLPRES", c.NOMPRES);
  if (!(c.FNOMIN > 0)) s.fail("FNOMIN", "must be positive");
  if (!(c.R0 > 0)) s.fail("UNLOADED_RADIUS", "must be positive");
  if (!(c.NOMPRES > 0)) s.fail("NOMPRES", "must be positive");
  if (!(c.LONGVL > 0)) s.fail("LONGVL", "must be positive");
  if (!(c.VXLOW > 0)) s.fail("VXLOW", "must be positive");
  if (!(c.LFZO > 0)) s.fail("LFZO", "must be positive");
  if (!(c.pressure > 0)) s.fail("INFLPRES", "must be positive");
  return c;
}

// MF 6.1/6.2 (Pacejka 2012 sec. 4.3.2), turn slip and speed-dependent friction left out (zeta = 1,
// lambda*_mu = lambda_mu, lambda'_mu with A_mu = 10); equation numbers of the book in the comments.
class MagicFormula61 : public TyreForceLaw {
 public:
  explicit MagicFormula61(const Mf61& c) : c_(c), pressureFactorMy_(std::pow(c.pressure / c.NOMPRES, c.QSY8)) {}

  TyreForces calcForces(const TyreSlip& in) const override {
    Common k = makeCommon(in.Fz, in.gamma, in.alpha);
    k.w = calcLowSpeedFactor(in.Vx);
    const PureLateral py = calcPureLateral(k, in.Fz, k.gammaStar);
    const double Kxk = calcKxk(k, in.Fz);
    // Longitudinal, pure (4.E9-4.E18) and combined (4.E50-4.E57).
    const double Cx = c_.PCX1 * c_.LCX;
    const double mux = (c_.PDX1 + c_.PDX2 * k.dfz) * (1 + c_.PPX3 * k.dpi + c_.PPX4 * k.dpi * k.dpi) *
                       (1 - c_.PDX3 * k.gammaStar * k.gammaStar) * c_.LMUX;
    const double Dx = mux * in.Fz;
    const double SHx = (c_.PHX1 + c_.PHX2 * k.dfz) * c_.LHX * k.w;
    const double kappax = in.kappa + SHx;
    const double Ex = std::min(1.0, (c_.PEX1 + c_.PEX2 * k.dfz + c_.PEX3 * k.dfz * k.dfz) * (1 - c_.PEX4 * sgn(kappax)) * c_.LEX);
    const double Bx = Kxk / (Cx * Dx + kEps);
    const double SVx = in.Fz * (c_.PVX1 + c_.PVX2 * k.dfz) * c_.LVX * k.lmuxPrime * k.w;
    const double Fx0 = magicSin(Bx, Cx, Dx, Ex, kappax) + SVx;
    const double Bxa = (c_.RBX1 + c_.RBX3 * k.gammaStar * k.gammaStar) * cosAtan(c_.RBX2 * in.kappa) * c_.LXAL;
    const double Cxa = c_.RCX1, Exa = std::min(1.0, c_.REX1 + c_.REX2 * k.dfz), SHxa = c_.RHX1;
    const double Gxa = magicCos(Bxa, Cxa, Exa, k.alphaStar + SHxa) / (SHxa == 0 ? 1.0 : magicCos(Bxa, Cxa, Exa, SHxa));
    TyreForces f;
    f.Fx = Gxa * Fx0;
    // Lateral, combined (4.E58-4.E67).
    const double Gyk = calcGyk(k, in.kappa);
    f.Fy = calcCombinedSideForce(k, in, py, Gyk);
    // Aligning moment, combined (4.E71-4.E78, with the pure-slip parts 4.E31-4.E49).
    f.Mz = calcAligning(k, in, py, Kxk, Gyk, f.Fx, f.Fy);
    // Overturning moment (4.E69, MF 6.1 terms) and rolling resistance (4.E70).
    const double Fz0p = k.Fz0p, R0 = c_.R0;
    f.Mx = R0 * in.Fz * c_.LMX *
           (c_.QSX1 * c_.LVMX * k.w - c_.QSX2 * k.gammaStar * (1 + c_.PPMX1 * k.dpi) + c_.QSX3 * f.Fy / Fz0p +
            c_.QSX4 * std::cos(c_.QSX5 * std::atan(square(c_.QSX6 * in.Fz / Fz0p))) *
                std::sin(c_.QSX7 * k.gammaStar + c_.QSX8 * std::atan(c_.QSX9 * f.Fy / Fz0p)) +
            c_.QSX10 * std::atan(c_.QSX11 * in.Fz / Fz0p) * k.gammaStar);
    const double vr = in.Vx / c_.LONGVL;
    f.My = in.Fz <= 0 ? 0.0
                      : -R0 * Fz0p * c_.LMY * k.w *
                            (c_.QSY1 + c_.QSY2 * f.Fx / Fz0p + c_.QSY3 * std::abs(vr) + c_.QSY4 * square(square(vr)) +
                             (c_.QSY5 + c_.QSY6 * in.Fz / Fz0p) * k.gammaStar * k.gammaStar) *
                            std::pow(in.Fz / Fz0p, c_.QSY7) * pressureFactorMy_;
    return f;
  }

  double calcCorneringStiffness(double Fz) const override { return calcKya(makeCommon(Fz, 0, 0), Fz, 0); }
  double calcCamberStiffness(double Fz) const override {
    const Common k = makeCommon(Fz, 0, 0);
    return Fz * (c_.PKY6 + c_.PKY7 * k.dfz) * (1 + c_.PPY5 * k.dpi) * c_.LKYC;  // K_yg0 (4.E30)
  }
  double calcLongitudinalStiffness(double Fz) const override { return calcKxk(makeCommon(Fz, 0, 0), Fz); }
  // sigma_alpha = PTY1 sin(2 atan(Fz/(PTY2 Fz0'))) (1 - PKY3 |gamma*|) R0 LFZO LSGAL (Pacejka 2012 sec. 7.2.2,
  // MF-Tyre 6.1 form without the pressure term).
  double calcRelaxationLength(double Fz, double gamma) const override {
    const double Fz0p = c_.FNOMIN * c_.LFZO;
    return c_.PTY1 * std::sin(2 * std::atan(Fz / (c_.PTY2 * Fz0p))) * (1 - c_.PKY3 * std::abs(std::sin(gamma))) * c_.R0 *
           c_.LFZO * c_.LSGAL;
  }
  double getNominalLoad() const override { return c_.FNOMIN * c_.LFZO; }
  double getUnloadedRadius() const override { return c_.R0; }

 private:
  static constexpr double kEps = 1e-12;  // the book's epsilon against 0/0 at zero load, N

  struct Common {
    double Fz0p, dfz, dpi, alphaStar, gammaStar, cosAlpha, lmuxPrime, lmuyPrime;
    double w = 1;  ///< low-speed factor of the forces at zero slip (calcLowSpeedFactor)
  };
  // 4.E1-4.E8.
  Common makeCommon(double Fz, double gamma, double alpha) const {
    Common k;
    k.Fz0p = c_.FNOMIN * c_.LFZO;
    k.dfz = (Fz - k.Fz0p) / k.Fz0p;
    k.dpi = (c_.pressure - c_.NOMPRES) / c_.NOMPRES;
    k.alphaStar = std::tan(alpha);
    k.gammaStar = std::sin(gamma);
    k.cosAlpha = cosAtan(k.alphaStar);  // cos(alpha), |alpha| < pi/2
    const double A = 10;
    k.lmuxPrime = A * c_.LMUX / (1 + (A - 1) * c_.LMUX);
    k.lmuyPrime = A * c_.LMUY / (1 + (A - 1) * c_.LMUY);
    return k;
  }
  // The forces at zero slip (shifts SHx, SVx, SHy, SVy; residual torque QDZ6-7; overturning offset
  // QSX1; rolling resistance) fade out below VXLOW as sin^2(pi/2 |Vx|/VXLOW): they have no meaning at
  // standstill, where no slip can balance them (MF-Tyre's low-speed treatment in spirit, not its form).
  double calcLowSpeedFactor(double Vx) const {
    const double v = std::abs(Vx) / c_.VXLOW;
    if (v >= 1) return 1;
    const double s = std::sin(M_PI / 2 * v);
    return s * s;
  }
  // K_ya (4.E25) at camber gamma* = g.
  double calcKya(const Common& k, double Fz, double g) const {
    return c_.PKY1 * k.Fz0p * (1 + c_.PPY1 * k.dpi) * (1 - c_.PKY3 * std::abs(g)) *
           std::sin(c_.PKY4 * std::atan((Fz / k.Fz0p) / ((c_.PKY2 + c_.PKY5 * g * g) * (1 + c_.PPY2 * k.dpi)))) * c_.LKY;
  }
  // K_xk (4.E15).
  double calcKxk(const Common& k, double Fz) const {
    return Fz * (c_.PKX1 + c_.PKX2 * k.dfz) * std::exp(c_.PKX3 * k.dfz) * (1 + c_.PPX1 * k.dpi + c_.PPX2 * k.dpi * k.dpi) *
           c_.LKX;
  }
  // G_yk (4.E58-4.E66 without the shift's vertical part).
  double calcGyk(const Common& k, double kappa) const {
    const double Byk = (c_.RBY1 + c_.RBY4 * k.gammaStar * k.gammaStar) * cosAtan(c_.RBY2 * (k.alphaStar - c_.RBY3)) * c_.LYKA;
    const double Cyk = c_.RCY1, Eyk = std::min(1.0, c_.REY1 + c_.REY2 * k.dfz), SHyk = c_.RHY1 + c_.RHY2 * k.dfz;
    return magicCos(Byk, Cyk, Eyk, kappa + SHyk) / (SHyk == 0 ? 1.0 : magicCos(Byk, Cyk, Eyk, SHyk));
  }

  struct PureLateral;
  // Fy = Gyk Fy0 + SVyk (4.E58, 4.E67-4.E68).
  double calcCombinedSideForce(const Common& k, const TyreSlip& in, const PureLateral& py, double Gyk) const {
    const double DVyk = py.muy * in.Fz * (c_.RVY1 + c_.RVY2 * k.dfz + c_.RVY3 * k.gammaStar) * cosAtan(c_.RVY4 * k.alphaStar);
    const double SVyk = DVyk * std::sin(c_.RVY5 * std::atan(c_.RVY6 * in.kappa)) * c_.LVYKA;
    return Gyk * py.Fy0 + SVyk;
  }

  struct PureLateral {
    double Fy0, Kya, By, Cy, muy, SHy, SVy;
  };
  // Pure side slip (4.E19-4.E30) at camber gamma* = g.
  PureLateral calcPureLateral(const Common& k, double Fz, double g) const {
    PureLateral p;
    p.Kya = calcKya(k, Fz, g);
    const double Kyg0 = Fz * (c_.PKY6 + c_.PKY7 * k.dfz) * (1 + c_.PPY5 * k.dpi) * c_.LKYC;
    const double SVyg = Fz * (c_.PVY3 + c_.PVY4 * k.dfz) * g * c_.LKYC * k.lmuyPrime;
    p.SVy = Fz * (c_.PVY1 + c_.PVY2 * k.dfz) * c_.LVY * k.lmuyPrime * k.w + SVyg;
    p.SHy = (c_.PHY1 + c_.PHY2 * k.dfz) * c_.LHY * k.w + (Kyg0 * g - SVyg) / (p.Kya + kEps * sgnOr1(p.Kya));
    const double alphay = k.alphaStar + p.SHy;
    p.Cy = c_.PCY1 * c_.LCY;
    p.muy = (c_.PDY1 + c_.PDY2 * k.dfz) * (1 + c_.PPY3 * k.dpi + c_.PPY4 * k.dpi * k.dpi) * (1 - c_.PDY3 * g * g) * c_.LMUY;
    const double Dy = p.muy * Fz;
    const double Ey = std::min(1.0, (c_.PEY1 + c_.PEY2 * k.dfz) * (1 + c_.PEY5 * g * g - (c_.PEY3 + c_.PEY4 * g) * sgn(alphay)) * c_.LEY);
    p.By = p.Kya / (p.Cy * Dy + kEps * sgnOr1(p.Cy * Dy));
    p.Fy0 = magicSin(p.By, p.Cy, Dy, Ey, alphay) + p.SVy;
    return p;
  }
  static double sgnOr1(double x) { return x < 0 ? -1.0 : 1.0; }

  // Mz = -t F'y + Mzr + s Fx (4.E71), F'y the combined side force at zero camber.
  double calcAligning(const Common& k, const TyreSlip& in, const PureLateral& py, double Kxk, double Gyk, double Fx,
                      double Fy) const {
    const double Fz = in.Fz, g = k.gammaStar, R0 = c_.R0;
    const double Kyap = py.Kya + kEps * sgnOr1(py.Kya);
    const double SHt = c_.QHZ1 + c_.QHZ2 * k.dfz + (c_.QHZ3 + c_.QHZ4 * k.dfz) * g;  // 4.E35
    const double alphat = k.alphaStar + SHt;
    const double SHf = py.SHy + py.SVy / Kyap;  // 4.E38
    const double alphar = k.alphaStar + SHf;
    const double ratio = Kxk / Kyap * in.kappa;
    const double alphateq = std::sqrt(alphat * alphat + ratio * ratio) * sgn(alphat);  // 4.E77
    const double alphareq = std::sqrt(alphar * alphar + ratio * ratio) * sgn(alphar);  // 4.E78
    const double Bt = (c_.QBZ1 + c_.QBZ2 * k.dfz + c_.QBZ3 * k.dfz * k.dfz) * (1 + c_.QBZ5 * std::abs(g) + c_.QBZ6 * g * g) *
                      c_.LKY / c_.LMUY;  // 4.E40
    const double Ct = c_.QCZ1;
    const double Dt0 = Fz * (R0 / k.Fz0p) * (c_.QDZ1 + c_.QDZ2 * k.dfz) * (1 - c_.PPZ1 * k.dpi) * c_.LTR;  // 4.E42
    const double Dt = Dt0 * (1 + c_.QDZ3 * std::abs(g) + c_.QDZ4 * g * g);                                // 4.E43
    const double Et = std::min(1.0, (c_.QEZ1 + c_.QEZ2 * k.dfz + c_.QEZ3 * k.dfz * k.dfz) *
                                        (1 + (c_.QEZ4 + c_.QEZ5 * g) * (2 / M_PI) * std::atan(Bt * Ct * alphat)));  // 4.E44
    const double t = Dt * magicCos(Bt, Ct, Et, alphateq) * k.cosAlpha;                                    // 4.E73
    const double Br = c_.QBZ9 * c_.LKY / c_.LMUY + c_.QBZ10 * py.By * py.Cy;                             // 4.E45
    const double Dr = Fz * R0 *
                      ((c_.QDZ6 + c_.QDZ7 * k.dfz) * c_.LRES * k.w +
                       ((c_.QDZ8 + c_.QDZ9 * k.dfz) * (1 + c_.PPZ2 * k.dpi) + (c_.QDZ10 + c_.QDZ11 * k.dfz) * std::abs(g)) * g *
                           c_.LKZC) *
                      c_.LMUY * k.cosAlpha;                                                              // 4.E47
    const double Mzr = Dr * cosAtan(Br * alphareq) * k.cosAlpha;                            // 4.E75
    const double FyPrime = Gyk * (g == 0 ? py.Fy0 : calcPureLateral(k, Fz, 0.0).Fy0);                 // F'y at gamma = 0
    const double s = R0 * (c_.SSZ1 + c_.SSZ2 * Fy / k.Fz0p + (c_.SSZ3 + c_.SSZ4 * k.dfz) * g) * c_.LS;  // 4.E76
    return -t * FyPrime + Mzr + s * Fx;
  }

  static double square(double x) { return x * x; }
  static double cosAtan(double x) { return 1 / std::sqrt(1 + x * x); }  // cos(atan(x))

  Mf61 c_;
  double pressureFactorMy_;  ///< (p/NOMPRES)^QSY8 of My (4.E70)
};

}  // namespace

std::unique_ptr<CoefficientSource> makeTirSource(const TirFile& file, const std::map<std::string, double>* scaling) {
  return std::make_unique<TirSource>(file, scaling);
}

std::unique_ptr<CoefficientSource> makeYamlSource(YamlMap& coefficients, const std::map<std::string, double>* scaling) {
  return std::make_unique<YamlSource>(coefficients, scaling);
}

std::optional<MagicFormulaVariant> parseMagicFormulaVariant(const std::string& name) {
  if (name == "mf61") return MagicFormulaVariant::MF61;
  if (name == "mf62") return MagicFormulaVariant::MF62;
  if (name == "motorcycle") return MagicFormulaVariant::Motorcycle;
  return std::nullopt;
}

const std::vector<std::string>& getScalingNames(MagicFormulaVariant v) {
  return v == MagicFormulaVariant::Motorcycle ? getMotorcycleScalingNames() : kMf61Scaling;
}

std::unique_ptr<TyreForceLaw> makeTyreForceLaw(MagicFormulaVariant v, const CoefficientSource& source,
                                               std::optional<double> pressure) {
  if (v == MagicFormulaVariant::Motorcycle) return makeMotorcycleMagicFormula(source);
  return std::make_unique<MagicFormula61>(readMf61(source, pressure));
}

std::unique_ptr<TyreForceLaw> loadTirForceLaw(const std::string& path, const std::map<std::string, double>* scaling) {
  const TirFile file = TirFile::load(path);
  const auto source = makeTirSource(file, scaling);
  return makeTyreForceLaw(file.getFitType() == 62 ? MagicFormulaVariant::MF62 : MagicFormulaVariant::MF61, *source);
}

}  // namespace motostab
