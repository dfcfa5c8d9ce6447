// MF 6.1 and the motorcycle Magic Formula against their equations written out here from the
// published sources, at drawn operating points and drawn scaling factors: Pacejka (2012), Tire and
// Vehicle Dynamics, 3rd ed., sec. 4.3.2 (eqs. 4.E1-4.E78) with MF-Tyre 6.1's QBZ4, QSX12-14 and carcass
// stiffnesses (Besselink, Schmeitz & Pacejka 2010), and Sharp, Evangelou & Limebeer (2004), Multibody
// Syst. Dyn. 12:251-283, sec. 4 with Evangelou (2004, PhD thesis) ch. 9 (coefficients Tables 9.1-9.3,
// relaxation Table 9.5). The slopes at zero slip must equal the closed-form stiffnesses.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <algorithm>
#include <functional>
#include <sstream>
#include <regex>

#include "core/portable_random.h"
#include "tyres/magic_formula.h"
#include "tyres/motorcycle_magic_formula.h"
#include "tests/support/catch_input_error.h"

namespace motostab::tyres {

using core::PortableRandom;
using io::InputError;

namespace {

const std::string kSample = std::string(MOTOSTAB_TEST_DATA_DIR) + "/reference/MF61-sample-tir/sample_MF61_ExternData.tir";

std::string readSample() {
  std::ifstream in(kSample);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The sample with the named coefficients set to zero.
TirFile sampleWithZeros(const std::vector<std::string>& keys) {
  std::string text = readSample();
  for (const auto& k : keys) text = std::regex_replace(text, std::regex("\n" + k + " [^\n]*"), "\n" + k + " = 0");
  return TirFile::parse(text, "sample-zeroed.tir");
}

// The sample with the named coefficients set to the given values (keys present in the sample).
TirFile sampleWithValues(const std::map<std::string, std::string>& values) {
  std::string text = readSample();
  for (const auto& [k, v] : values) text = std::regex_replace(text, std::regex("\n" + k + " [^\n]*"), "\n" + k + " = " + v);
  return TirFile::parse(text, "sample-edited.tir");
}

// The sample without the lines of the named keys.
TirFile sampleWithoutKeys(const std::vector<std::string>& keys) {
  std::string text = readSample();
  for (const auto& k : keys) text = std::regex_replace(text, std::regex("\n" + k + " [^\n]*"), "");
  return TirFile::parse(text, "sample-without.tir");
}

double sgn(double x) { return (x > 0) - (x < 0); }
double mfSin(double B, double C, double D, double E, double x) { return D * std::sin(C * std::atan(B * x - E * (B * x - std::atan(B * x)))); }
double mfCos(double B, double C, double E, double x) { return std::cos(C * std::atan(B * x - E * (B * x - std::atan(B * x)))); }

// MF 6.1 written out from Pacejka (2012) sec. 4.3.2 (no turn slip, zeta = 1), with the scaling factors
// of the map `L` (1 when absent) where the book puts them, lambda'_mu = 10 lambda/(1 + 9 lambda) (4.E8),
// and MF-Tyre 6.1's QBZ4 (Besselink, Schmeitz & Pacejka 2010, A58) and QSX12-14 (eq. 49). Coefficients by
// name from the file; forward speed at or above VXLOW.
struct BookMf61 {
  const TirFile& f;
  double p;                            // inflation pressure, Pa
  std::map<std::string, double> L;     // scaling factors
  double c(const char* k) const { return f.getNumber(k); }
  double l(const char* k) const { return L.count(k) ? L.at(k) : 1.0; }
  double lp(const char* k) const { return 10 * l(k) / (1 + 9 * l(k)); }  // 4.E8
  double Fz0() const { return c("FNOMIN") * l("LFZO"); }                 // 4.E1
  double dfz(double Fz) const { return (Fz - Fz0()) / Fz0(); }           // 4.E2a
  double dpi() const { return (p - c("NOMPRES")) / c("NOMPRES"); }       // 4.E2b
  double Kya(double Fz, double g) const {  // 4.E25
    return c("PKY1") * Fz0() * (1 + c("PPY1") * dpi()) * (1 - c("PKY3") * std::abs(g)) *
           std::sin(c("PKY4") * std::atan(Fz / Fz0() / ((c("PKY2") + c("PKY5") * g * g) * (1 + c("PPY2") * dpi())))) * l("LKY");
  }
  double Kyg0(double Fz) const { return Fz * (c("PKY6") + c("PKY7") * dfz(Fz)) * (1 + c("PPY5") * dpi()) * l("LKYC"); }  // 4.E30
  double Kxk(double Fz) const {  // 4.E15
    return Fz * (c("PKX1") + c("PKX2") * dfz(Fz)) * std::exp(c("PKX3") * dfz(Fz)) * (1 + c("PPX1") * dpi() + c("PPX2") * dpi() * dpi()) * l("LKX");
  }
  double muy(double Fz, double g) const {  // 4.E23
    return (c("PDY1") + c("PDY2") * dfz(Fz)) * (1 + c("PPY3") * dpi() + c("PPY4") * dpi() * dpi()) * (1 - c("PDY3") * g * g) * l("LMUY");
  }
  // Pure side force Fy0 (4.E19-4.E30) at gamma* = sin(gamma) = g and alpha* = tan(alpha) = a.
  double Fy0(double Fz, double a, double g, double* By = nullptr, double* SHy = nullptr, double* SVy = nullptr) const {
    const double SVyg = Fz * (c("PVY3") + c("PVY4") * dfz(Fz)) * g * l("LKYC") * lp("LMUY");                      // 4.E28
    const double sv = Fz * (c("PVY1") + c("PVY2") * dfz(Fz)) * l("LVY") * lp("LMUY") + SVyg;                      // 4.E29
    const double sh = (c("PHY1") + c("PHY2") * dfz(Fz)) * l("LHY") + (Kyg0(Fz) * g - SVyg) / Kya(Fz, g);          // 4.E27
    const double ay = a + sh, Cy = c("PCY1") * l("LCY"), Dy = muy(Fz, g) * Fz;
    const double Ey = (c("PEY1") + c("PEY2") * dfz(Fz)) * (1 + c("PEY5") * g * g - (c("PEY3") + c("PEY4") * g) * sgn(ay)) * l("LEY");
    const double B = Kya(Fz, g) / (Cy * Dy);
    if (By) *By = B;
    if (SHy) *SHy = sh;
    if (SVy) *SVy = sv;
    return mfSin(B, Cy, Dy, std::min(Ey, 1.0), ay) + sv;
  }
  // Pure longitudinal force Fx0 (4.E9-4.E18).
  double Fx0(double Fz, double k, double g) const {
    const double kx = k + (c("PHX1") + c("PHX2") * dfz(Fz)) * l("LHX"), Cx = c("PCX1") * l("LCX");
    const double Dx = (c("PDX1") + c("PDX2") * dfz(Fz)) * (1 + c("PPX3") * dpi() + c("PPX4") * dpi() * dpi()) * (1 - c("PDX3") * g * g) * l("LMUX") * Fz;
    const double Ex = (c("PEX1") + c("PEX2") * dfz(Fz) + c("PEX3") * dfz(Fz) * dfz(Fz)) * (1 - c("PEX4") * sgn(kx)) * l("LEX");
    return mfSin(Kxk(Fz) / (Cx * Dx), Cx, Dx, std::min(Ex, 1.0), kx) + Fz * (c("PVX1") + c("PVX2") * dfz(Fz)) * l("LVX") * lp("LMUX");
  }
  // Combined weights 4.E51-4.E57 and 4.E59-4.E67.
  double Gxa(double Fz, double k, double a, double g) const {
    const double B = (c("RBX1") + c("RBX3") * g * g) * std::cos(std::atan(c("RBX2") * k)) * l("LXAL"), C = c("RCX1"),
                 E = std::min(1.0, c("REX1") + c("REX2") * dfz(Fz)), sh = c("RHX1");
    return mfCos(B, C, E, a + sh) / mfCos(B, C, E, sh);
  }
  double Gyk(double Fz, double k, double a, double g) const {
    const double B = (c("RBY1") + c("RBY4") * g * g) * std::cos(std::atan(c("RBY2") * (a - c("RBY3")))) * l("LYKA"), C = c("RCY1"),
                 E = std::min(1.0, c("REY1") + c("REY2") * dfz(Fz)), sh = c("RHY1") + c("RHY2") * dfz(Fz);
    return mfCos(B, C, E, k + sh) / mfCos(B, C, E, sh);
  }
  double SVyk(double Fz, double k, double a, double g) const {
    const double D = muy(Fz, g) * Fz * (c("RVY1") + c("RVY2") * dfz(Fz) + c("RVY3") * g) * std::cos(std::atan(c("RVY4") * a));
    return D * std::sin(c("RVY5") * std::atan(c("RVY6") * k)) * l("LVYKA");
  }
  // Aligning moment (4.E71-4.E78 with the pure-slip parts 4.E31-4.E49): the trail acts on the
  // combined side force at zero camber, Gyk Fy0(gamma = 0) (4.E74); Fx and Fy are the combined forces.
  double Mz(double Fz, double k, double a, double g, double Fx, double Fy) const {
    double By, SHy, SVy;
    Fy0(Fz, a, g, &By, &SHy, &SVy);
    const double R0 = c("UNLOADED_RADIUS"), ca = 1 / std::sqrt(1 + a * a), d = dfz(Fz);
    const double at = a + c("QHZ1") + c("QHZ2") * d + (c("QHZ3") + c("QHZ4") * d) * g;                // 4.E34-35
    const double ar = a + SHy + SVy / Kya(Fz, g);                                                       // 4.E37-38
    const double r = Kxk(Fz) / Kya(Fz, g) * k;
    const double ateq = std::sqrt(at * at + r * r) * sgn(at), areq = std::sqrt(ar * ar + r * r) * sgn(ar);  // 4.E77-78
    const double Bt = (c("QBZ1") + c("QBZ2") * d + c("QBZ3") * d * d) * (1 + c("QBZ4") * g + c("QBZ5") * std::abs(g)) * l("LKY") / l("LMUY");
    const double Ct = c("QCZ1");
    const double Dt = Fz * R0 / Fz0() * (c("QDZ1") + c("QDZ2") * d) * (1 - c("PPZ1") * dpi()) * (1 + c("QDZ3") * std::abs(g) + c("QDZ4") * g * g) * l("LTR");
    const double Et = std::min(1.0, (c("QEZ1") + c("QEZ2") * d + c("QEZ3") * d * d) * (1 + (c("QEZ4") + c("QEZ5") * g) * 2 / M_PI * std::atan(Bt * Ct * at)));
    const double t = Dt * mfCos(Bt, Ct, Et, ateq) * ca;                                                 // 4.E73
    const double Br = c("QBZ9") * l("LKY") / l("LMUY") + c("QBZ10") * By * c("PCY1") * l("LCY");       // 4.E45
    const double Dr = Fz * R0 * ((c("QDZ6") + c("QDZ7") * d) * l("LRES") +
                                 ((c("QDZ8") + c("QDZ9") * d) * (1 + c("PPZ2") * dpi()) + (c("QDZ10") + c("QDZ11") * d) * std::abs(g)) * g * l("LKZC")) *
                      l("LMUY") * ca;                                                                   // 4.E47
    const double s = R0 * (c("SSZ1") + c("SSZ2") * Fy / Fz0() + (c("SSZ3") + c("SSZ4") * d) * g) * l("LS");  // 4.E76
    return -t * Gyk(Fz, k, a, g) * Fy0(Fz, a, 0) + Dr * std::cos(std::atan(Br * areq)) + s * Fx;        // 4.E71-75
  }
  // Overturning moment: MF-Tyre 6.1 (Besselink et al. 2010 eq. 49), with gamma* and Fz0'.
  double Mx(double Fz, double Fy, double g) const {
    const double R0 = c("UNLOADED_RADIUS");
    return R0 * Fz * l("LMX") * (c("QSX1") * l("LVMX") - c("QSX2") * g * (1 + c("PPMX1") * dpi()) + c("QSX3") * Fy / Fz0() +
                      c("QSX4") * std::cos(c("QSX5") * std::atan(std::pow(c("QSX6") * Fz / Fz0(), 2))) * std::sin(c("QSX7") * g + c("QSX8") * std::atan(c("QSX9") * Fy / Fz0())) +
                      c("QSX10") * std::atan(c("QSX11") * Fz / Fz0()) * g) +
           R0 * l("LMX") * (Fy * (c("QSX13") + c("QSX14") * std::abs(g)) - Fz * c("QSX12") * g * std::abs(g));
  }
  // Rolling resistance 4.E70, opposing the rolling (sgn Vx).
  double My(double Fz, double Fx, double Vx, double g) const {
    const double v = Vx / c("LONGVL");
    return -sgn(Vx) * c("UNLOADED_RADIUS") * Fz0() * l("LMY") * (c("QSY1") + c("QSY2") * Fx / Fz0() + c("QSY3") * std::abs(v) + c("QSY4") * std::pow(v, 4) + (c("QSY5") + c("QSY6") * Fz / Fz0()) * g * g) *
           std::pow(Fz / Fz0(), c("QSY7")) * std::pow(p / c("NOMPRES"), c("QSY8"));
  }
};

struct Point {
  double Fz, kappa, alpha, gamma, Vx, pressure;
};
Point drawPoint(PortableRandom& r) {
  return {r.drawUniform(400, 8000), r.drawUniform(-0.25, 0.25), r.drawUniform(-0.35, 0.35), r.drawUniform(-0.15, 0.15),
          r.drawUniform(1, 40), r.drawUniform(1.7e5, 2.3e5)};
}

// Every scaling factor the MF 6.1 equations use, drawn in [0.6, 1.4].
std::map<std::string, double> drawScaling(PortableRandom& r) {
  std::map<std::string, double> out;
  for (const auto& name : getScalingNames(MagicFormulaVariant::MF61)) out[name] = r.drawUniform(0.6, 1.4);
  return out;
}

TEST(MagicFormula61, MatchesTheBookAtDrawnPointsAndScalings) {
  // QSX12-14 are zero in the sample: set them so that they count.
  const TirFile f = sampleWithValues({{"QSX12", "0.03"}, {"QSX13", "0.2"}, {"QSX14", "-0.4"}});
  PortableRandom rng(20261125);
  for (int i = 0; i < 200; ++i) {
    const Point p = drawPoint(rng);
    const auto scaling = drawScaling(rng);
    const auto law = makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(f, &scaling), p.pressure);
    const BookMf61 book{f, p.pressure, scaling};
    const double a = std::tan(p.alpha), g = std::sin(p.gamma);
    const TyreForces pure = law->calcForces({p.Fz, 0, p.alpha, p.gamma, p.Vx});
    const double tol = 1e-9 * p.Fz;
    EXPECT_NEAR(pure.Fy, book.Gyk(p.Fz, 0, a, g) * book.Fy0(p.Fz, a, g) + book.SVyk(p.Fz, 0, a, g), tol) << i;
    const double FxPure = book.Gxa(p.Fz, 0, a, g) * book.Fx0(p.Fz, 0, g);  // the shifts leave a small Fx at kappa = 0
    EXPECT_NEAR(pure.Mz, book.Mz(p.Fz, 0, a, g, FxPure, pure.Fy), tol * 0.1) << i;
    const TyreForces longitudinal = law->calcForces({p.Fz, p.kappa, 0, p.gamma, p.Vx});
    EXPECT_NEAR(longitudinal.Fx, book.Fx0(p.Fz, p.kappa, g) * book.Gxa(p.Fz, p.kappa, 0, g), tol) << i;
    const TyreForces combined = law->calcForces({p.Fz, p.kappa, p.alpha, p.gamma, p.Vx});
    const double Fx = book.Gxa(p.Fz, p.kappa, a, g) * book.Fx0(p.Fz, p.kappa, g);
    const double Fy = book.Gyk(p.Fz, p.kappa, a, g) * book.Fy0(p.Fz, a, g) + book.SVyk(p.Fz, p.kappa, a, g);
    EXPECT_NEAR(combined.Fx, Fx, tol) << i;
    EXPECT_NEAR(combined.Fy, Fy, tol) << i;
    EXPECT_NEAR(combined.Mz, book.Mz(p.Fz, p.kappa, a, g, Fx, Fy), tol * 0.1) << i;
    EXPECT_NEAR(combined.Mx, book.Mx(p.Fz, Fy, g), tol * 0.1) << i;
    EXPECT_NEAR(combined.My, book.My(p.Fz, Fx, p.Vx, g), tol * 0.1) << i;
    const TyreForces backwards = law->calcForces({p.Fz, p.kappa, p.alpha, p.gamma, -p.Vx});
    EXPECT_NEAR(backwards.My, book.My(p.Fz, Fx, -p.Vx, g), tol * 0.1) << i;
  }
}

// Central-difference slope of one force component in one slip variable at zero slip and camber.
double slope(const TyreForceLaw& law, double Fz, double TyreSlip::*var, double TyreForces::*out) {
  const double h = 1e-6;
  TyreSlip plus{Fz, 0, 0, 0, 10}, minus = plus;
  plus.*var = h;
  minus.*var = -h;
  return (law.calcForces(plus).*out - law.calcForces(minus).*out) / (2 * h);
}

TEST(MagicFormula61, SlopesAtZeroAreTheClosedFormStiffnesses) {
  // Without shifts the zero-slip point is the origin of each curve; the slopes there are
  // K_ya = By Cy Dy (4.E25), K_yg0 (4.E30) and K_xk = Bx Cx Dx (4.E15).
  const TirFile f = sampleWithZeros({"PHX1", "PHX2", "PVX1", "PVX2", "PHY1", "PHY2", "PVY1", "PVY2", "RHX1", "RHY1", "RHY2",
                                     "RVY1", "RVY2", "RVY3"});
  const auto law = makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(f, nullptr));
  const BookMf61 book{f, 200000, {}};
  PortableRandom rng(7);
  for (int i = 0; i < 20; ++i) {
    const double Fz = rng.drawUniform(300, 9000);
    EXPECT_NEAR(slope(*law, Fz, &TyreSlip::alpha, &TyreForces::Fy), book.Kya(Fz, 0), 1e-6 * std::abs(book.Kya(Fz, 0)));
    EXPECT_NEAR(slope(*law, Fz, &TyreSlip::gamma, &TyreForces::Fy), book.Kyg0(Fz), 1e-6 * std::abs(book.Kyg0(Fz)));
    EXPECT_NEAR(slope(*law, Fz, &TyreSlip::kappa, &TyreForces::Fx), book.Kxk(Fz), 1e-6 * book.Kxk(Fz));
    EXPECT_NEAR(law->calcCorneringStiffness(Fz), book.Kya(Fz, 0), 1e-9 * std::abs(book.Kya(Fz, 0)));
    EXPECT_NEAR(law->calcCamberStiffness(Fz), book.Kyg0(Fz), 1e-9 * std::abs(book.Kyg0(Fz)));
    EXPECT_NEAR(law->calcLongitudinalStiffness(Fz), book.Kxk(Fz), 1e-9 * book.Kxk(Fz));
  }
}

TEST(MagicFormula61, RelaxationLengthFromTheCarcassStiffness) {
  // MF 6.1/6.2: sigma_y = |K_ya/C_y|, C_y = LATERAL_STIFFNESS (1 + PCFY1 dfz + PCFY2 dfz^2)(1 + PCFY3 dpi)
  // (Besselink, Schmeitz & Pacejka 2010, eqs. 18-19). The sample has no carcass stiffness: add one.
  const std::string text = readSample() +
                           "\n[STRUCTURAL]\nLATERAL_STIFFNESS = 190000\nPCFY1 = 0.2\nPCFY2 = 0.05\nPCFY3 = 0.3\n"
                           "LONGITUDINAL_STIFFNESS = 350000\nPCFX1 = 0.1\nPCFX2 = -0.02\nPCFX3 = 0.4\n";
  const TirFile f = TirFile::parse(text, "sample-structural.tir");
  PortableRandom rng(99);
  for (int i = 0; i < 20; ++i) {
    const double Fz = rng.drawUniform(500, 8000), gamma = rng.drawUniform(-0.1, 0.1), p = rng.drawUniform(1.8e5, 2.2e5);
    const auto law = makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(f, nullptr), p);
    const BookMf61 book{f, p, {}};
    const double dfz = book.dfz(Fz), dpi = book.dpi();
    const double Cy = 190000 * (1 + 0.2 * dfz + 0.05 * dfz * dfz) * (1 + 0.3 * dpi);
    EXPECT_NEAR(law->calcRelaxationLength(Fz, gamma, 20), std::abs(book.Kya(Fz, std::sin(gamma)) / Cy), 1e-12) << i;
    const double Cx = 350000 * (1 + 0.1 * dfz - 0.02 * dfz * dfz) * (1 + 0.4 * dpi);
    EXPECT_NEAR(law->calcLongitudinalRelaxationLength(Fz), book.Kxk(Fz) / Cx, 1e-12) << i;
  }
  // Without the carcass stiffness, MF 5.2's PTY1 sin(2 atan(Fz/(PTY2 Fz0))) R0 (sample: PTY1 = PTY2 = 1.8).
  const auto sample = makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(TirFile::load(kSample), nullptr));
  EXPECT_NEAR(sample->calcRelaxationLength(4000, 0, 20), 1.8 * std::sin(2 * std::atan(1 / 1.8)) * 0.3135, 1e-15);
  EXPECT_TRUE(std::isnan(sample->calcLongitudinalRelaxationLength(4000)));
  // Neither: no relaxation length of its own.
  const TirFile bare = sampleWithoutKeys({"PTY1", "PTY2"});
  EXPECT_TRUE(std::isnan(makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(bare, nullptr))->calcRelaxationLength(4000, 0, 20)));
}

TEST(MagicFormula61, UnusedNonzeroCoefficientsAreReported) {
  const TirFile f = TirFile::load(kSample);
  const auto source = makeTirSource(f, nullptr);
  makeTyreForceLaw(MagicFormulaVariant::MF61, *source);
  const auto unused = source->listUnused();
  auto has = [&](const std::string& key) {
    return std::any_of(unused.begin(), unused.end(), [&](const std::string& u) { return u.rfind(key + " (", 0) == 0; });
  };
  // Longitudinal relaxation and loaded radius are not modelled: reported. QBZ4 is used; LSGKP is 1.
  EXPECT_TRUE(has("PTX1"));
  EXPECT_TRUE(has("QFZ2"));
  EXPECT_FALSE(has("QBZ4"));
  EXPECT_FALSE(has("PTY1"));
  EXPECT_FALSE(has("LSGKP"));
  const std::string warning = describeUnused(*source, "sample.tir");
  EXPECT_EQ(warning.rfind("sample.tir: ", 0), 0u);
  EXPECT_NE(warning.find("PTX1 (line 134)"), std::string::npos);
}

TEST(MagicFormula61, RightHandFitsAreRefused) {
  std::string text = std::regex_replace(readSample(), std::regex("TYRESIDE *= 'Left'"), "TYRESIDE = 'Right'");
  const TirFile f = TirFile::parse(text, "right.tir");
  EXPECT_THROW(makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(f, nullptr)), InputError);
}

TEST(MagicFormula61, ZeroSlipForcesFadeBelowVxlow) {
  const TirFile f = TirFile::load(kSample);
  const auto law = makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(f, nullptr));
  const TyreForces still = law->calcForces({3000, 0, 0, 0, 0});
  for (double v : {still.Fx, still.Fy, still.Mz, still.Mx, still.My}) EXPECT_EQ(v, 0);
  // At VXLOW (1 m/s) and above: the book's, which has forces at zero slip (ply steer, conicity).
  const BookMf61 book{f, 200000, {}};
  EXPECT_NEAR(law->calcForces({3000, 0, 0, 0, 1.0}).Fy, book.Fy0(3000, 0, 0), 1e-9 * 3000);
  EXPECT_GT(std::abs(law->calcForces({3000, 0, 0, 0, 1.0}).Fy), 10);
  // Slip still makes force at standstill.
  EXPECT_GT(std::abs(law->calcForces({3000, 0, 0.05, 0, 0}).Fy), 100);
}

TEST(MagicFormula61, ScalingFactorsScaleWhatTheyName) {
  const TirFile f = TirFile::load(kSample);
  const std::map<std::string, double> scaling{{"LKY", 1.3}, {"LKYC", 0.7}, {"LKX", 1.1}};
  const auto plain = makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(f, nullptr));
  const auto scaled = makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(f, &scaling));
  EXPECT_NEAR(scaled->calcCorneringStiffness(3000), 1.3 * plain->calcCorneringStiffness(3000), 1e-9);
  EXPECT_NEAR(scaled->calcCamberStiffness(3000), 0.7 * plain->calcCamberStiffness(3000), 1e-9);
  EXPECT_NEAR(scaled->calcLongitudinalStiffness(3000), 1.1 * plain->calcLongitudinalStiffness(3000), 1e-9);
}

// The 1-based line of the first line of the sample that starts with `key` followed by a blank.
int sampleLineOf(const std::string& key) {
  std::istringstream in(readSample());
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.rfind(key + " ", 0) == 0) return n;
  return -1;
}

// Coefficients of the wrong sign, wherever the law reads them, are InputErrors at their own line and
// column of the file: a negative relaxation scale (LSGAL = -1 gave "relaxation" roots of +117 1/s), a
// zero shape factor (PCY1 = 0 gave a flat side force beside a cornering stiffness of -53353 N/rad), a
// friction, relaxation or carcass coefficient that makes its quantity zero or negative.
TEST(MagicFormula61, CoefficientsOfTheWrongSignAreRefusedAtTheirLine) {
  const std::string carcass = "\n[STRUCTURAL]\nLATERAL_STIFFNESS = 190000\nPCFY1 = 0.2\nPCFY2 = -0.5\nPCFY3 = 0\n";
  struct Case {
    std::map<std::string, std::string> values;
    std::string key;
  };
  const std::vector<Case> cases = {{{{"LSGAL", "-1"}}, "LSGAL"}, {{{"LSGAL", "0"}}, "LSGAL"},   {{{"PCY1", "0"}}, "PCY1"},
                                   {{{"PCX1", "-1.6"}}, "PCX1"}, {{{"PDY1", "0"}}, "PDY1"},     {{{"PDX1", "-1"}}, "PDX1"},
                                   {{{"PTY1", "-1.8"}}, "PTY1"}, {{{"PTY2", "0"}}, "PTY2"},     {{{"LMUY", "0"}}, "LMUY"},
                                   {{{"LKYC", "-0.5"}}, "LKYC"}, {{{"LONGVL", "-16.7"}}, "LONGVL"},
                                   // K_ya = PKY1 Fz0 sin(PKY4 atan(Fz/(PKY2 Fz0))): PKY1 = 0 gives none, PKY2 = 0
                                   // is 0/0 at zero load (both were refused without naming the coefficient).
                                   {{{"PKY1", "0"}}, "PKY1"}, {{{"PKY1", "15.3"}}, "PKY1"}, {{{"PKY2", "0"}}, "PKY2"},
                                   // (1 - PKY3 |gamma|) is zero at 1/PKY3 rad: 1.2 reaches it at 48 deg of camber.
                                   {{{"PKY3", "1.2"}}, "PKY3"}};
  for (const auto& c : cases) {
    const TirFile f = sampleWithValues(c.values);
    const InputError e = test::catchInputError([&] { makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(f, nullptr)); });
    EXPECT_EQ(e.getLocation().key, c.key) << e.what();
    EXPECT_EQ(e.getLocation().line, sampleLineOf(c.key)) << e.what();
    EXPECT_GT(e.getLocation().column, 1) << e.what();
  }
  // A lateral carcass stiffness whose load polynomial 1 + 0.2 dfz - 0.5 dfz^2 turns negative before
  // 3 FNOMIN (dfz = 2: -0.6) would give a relaxation length of the wrong sign: refused at PCFY1.
  const TirFile soft = TirFile::parse(readSample() + carcass, "carcass.tir");
  const InputError e = test::catchInputError([&] { makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(soft, nullptr)); });
  EXPECT_EQ(e.getLocation().key, "PCFY1") << e.what();
  // A scaling factor given by the scenario that overrides the file's is checked too.
  const std::map<std::string, double> scaling{{"LKY", -1.0}};
  const InputError lky = test::catchInputError(
      [&] { makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(TirFile::load(kSample), &scaling)); });
  EXPECT_EQ(lky.getLocation().key, "LKY") << lky.what();
  EXPECT_EQ(findScalingProblem("LRES", 0), "");
  EXPECT_NE(findScalingProblem("LRES", -0.1), "");
  EXPECT_NE(findScalingProblem("LKY", 0), "");
}

// Coefficients that pass the sign checks but make the law non-finite or degenerate somewhere in its
// range are refused at the coefficient set (the file), naming what went wrong and where.
TEST(MagicFormula61, DegenerateLawsAreRefusedNamingTheCoefficientSet) {
  // LSGAL = 1e-9: an own relaxation length of about 1e-10 m, below kMinRelaxationLength (a root of -1e11 1/s).
  const InputError short_ = test::catchInputError(
      [&] { makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(sampleWithValues({{"LSGAL", "1e-9"}}), nullptr)); });
  EXPECT_NE(short_.getReason().find("relaxation length"), std::string::npos) << short_.what();
  EXPECT_NE(short_.getReason().find("at least 0.0001 m"), std::string::npos) << short_.what();
  // PKY4 = 4: sin(4 atan(Fz/(PKY2 Fz0))) < 0 above Fz = PKY2 Fz0 = 1.7 FNOMIN, a cornering stiffness that
  // pushes along the slip.
  const InputError sign = test::catchInputError(
      [&] { makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(sampleWithValues({{"PKY4", "4"}}), nullptr)); });
  EXPECT_NE(sign.getReason().find("cornering stiffness"), std::string::npos) << sign.what();
  EXPECT_NE(sign.getReason().find("at Fz 8000 N"), std::string::npos) << sign.what();
  // The sample itself, and the grid's cost: a few thousand evaluations.
  const auto law = makeTyreForceLaw(MagicFormulaVariant::MF61, *makeTirSource(TirFile::load(kSample), nullptr));
  EXPECT_EQ(findForceLawProblem(*law), "");
}

// The motorcycle front tyre 120/70 ZR17 of Sharp, Evangelou & Limebeer (2004) (Evangelou 2004, Tables
// 9.1-9.3; relaxation Table 9.5), crown radius 0.06 m, as in scenarios/supersport-mf.yaml.
const std::map<std::string, double> kFront120 = {
    {"FNOMIN", 1100},     {"UNLOADED_RADIUS", 0.315}, {"CROWN_RADIUS", 0.06}, {"RELAX_C1", 8.633e-6},
    {"RELAX_C2", 3.725e-8}, {"RELAX_C3", 8.389e-10}, {"PCX1", 1.6064},   {"PDX1", 1.3806},    {"PDX2", -0.041429},
    {"PEX1", 0.0263},     {"PEX2", 0.27056},       {"PEX3", -0.076882}, {"PEX4", 1.1268},    {"PKX1", 25.939},
    {"PKX2", -4.2327},    {"PKX3", 0.33686},       {"PCY1", 0.83266},   {"PDY1", 1.3},       {"PEY1", -1.2556},
    {"PEY2", -3.2068},    {"PEY4", -3.9975},       {"PKY1", 22.841},    {"PKY2", 2.1578},    {"PKY3", 2.5058},
    {"PKY4", -0.08088},   {"PKY5", -0.22882},      {"PCY2", 0.86765},   {"PKY6", 0.69677},   {"PKY7", -0.03077},
    {"PEY5", -15.815},    {"QHZ3", -0.0037886},    {"QHZ4", -0.01557},  {"QBZ1", 10.486},    {"QBZ2", -0.0011536},
    {"QBZ5", -0.68973},   {"QBZ6", 1.0411},        {"QCZ1", 1.0917},    {"QDZ1", 0.19796},   {"QDZ2", 0.065629},
    {"QDZ3", 0.2199},     {"QDZ4", 0.21866},       {"QEZ1", -0.91586},  {"QEZ2", 0.11625},   {"QEZ3", -0.0024085},
    {"QEZ5", 1.4387},     {"QBZ9", 27.445},        {"QBZ10", -1.0792},  {"QDZ8", 0.3682},    {"QDZ9", 0.1218},
    {"QDZ10", 0.25439},   {"QDZ11", -0.17873},     {"RBX1", 13.476},    {"RBX2", 11.354},    {"RCX1", 1.1231},
    {"RBY1", 7.7856},     {"RBY2", 8.1697},        {"RBY3", -0.05914},  {"RCY1", 1.0533}};

// The motorcycle Magic Formula written out from Sharp, Evangelou & Limebeer (2004) sec. 4 and Evangelou
// (2004) ch. 9, in the paper's variables: a slip a and a camber g (rad) that both push the tyre to +y,
// cos a written 1/sqrt(1 + a^2), with the scaling factors L (1 when absent). R0 of the moments is the
// crown radius Rc. Optional terms 0 when absent: PDY2, PDY3 (the form of MBSim's magic_formula_sharp.cc
// and TUMFTM's motorcycle_model) and QEZ3 (Evangelou's Table 9.3).
struct SharpTyre {
  std::map<std::string, double> c, L;
  double Rc;
  double k(const char* n) const { return c.at(n); }
  double k0(const char* n) const { return c.count(n) ? c.at(n) : 0.0; }
  double l(const char* n) const { return L.count(n) ? L.at(n) : 1.0; }
  double Fz0() const { return k("FNOMIN") * l("LFZO"); }
  double dfz(double Fz) const { return (Fz - Fz0()) / Fz0(); }
  double Kya(double Fz, double g) const {
    return k("PKY1") * Fz0() * std::sin(k("PKY2") * std::atan(Fz / ((k("PKY3") + k("PKY4") * g * g) * Fz0()))) / (1 + k("PKY5") * g * g) * l("LKY");
  }
  double Kyg(double Fz) const { return (k("PKY6") + k("PKY7") * dfz(Fz)) * Fz * l("LKYC"); }
  double Kx(double Fz) const { return Fz * (k("PKX1") + k("PKX2") * dfz(Fz)) * std::exp(k("PKX3") * dfz(Fz)) * l("LKX"); }
  double Dy(double Fz, double g) const { return k("PDY1") * std::exp(k0("PDY2") * dfz(Fz)) / (1 + k0("PDY3") * g * g) * Fz * l("LMUY"); }
  double Fx0(double Fz, double s) const {
    const double D = (k("PDX1") + k("PDX2") * dfz(Fz)) * Fz * l("LMUX"), C = k("PCX1");
    const double E = (k("PEX1") + k("PEX2") * dfz(Fz) + k("PEX3") * std::pow(dfz(Fz), 2)) * (1 - k("PEX4") * sgn(s));
    return D * std::sin(C * std::atan(Kx(Fz) / (C * D) * s - E * (Kx(Fz) / (C * D) * s - std::atan(Kx(Fz) / (C * D) * s))));
  }
  double Fy0(double Fz, double a, double g) const {
    const double D = Dy(Fz, g), Cy = k("PCY1"), Cg = k("PCY2");
    const double By = Kya(Fz, g) / (Cy * D), Bg = Kyg(Fz) / (Cg * D);
    const double Ey = k("PEY1") + k("PEY2") * g * g + k("PEY4") * g * sgn(a), Eg = k("PEY5");
    return D * std::sin(Cy * std::atan(By * a - Ey * (By * a - std::atan(By * a))) + Cg * std::atan(Bg * g - Eg * (Bg * g - std::atan(Bg * g))));
  }
  double Gxa(double s, double a) const { return std::cos(k("RCX1") * std::atan(k("RBX1") * std::cos(std::atan(k("RBX2") * s)) * a)); }
  // The combined-slip factor whose RBY3 shift makes the law asymmetric in a.
  double Byk(double a) const { return k("RBY1") * std::cos(std::atan(k("RBY2") * (a - k("RBY3")))); }
  double Gyk(double s, double a) const { return std::cos(k("RCY1") * std::atan(Byk(a) * s)); }
  double Mz(double Fz, double s, double a, double g) const {
    const double d = dfz(Fz), ca = 1 / std::sqrt(1 + a * a), r = Kx(Fz) * s / Kya(Fz, 0);
    const double ateq = std::sqrt(a * a + r * r) * sgn(a);
    const double ar = a + (k("QHZ3") + k("QHZ4") * d) * g, areq = std::sqrt(ar * ar + r * r) * sgn(ar);
    const double Bt = (k("QBZ1") + k("QBZ2") * d) * (1 + k("QBZ5") * std::abs(g) + k("QBZ6") * g * g), Ct = k("QCZ1");
    const double Dt = Fz * Rc / Fz0() * (k("QDZ1") + k("QDZ2") * d) * (1 + k("QDZ3") * std::abs(g) + k("QDZ4") * g * g) * l("LTR");
    const double Et = (k("QEZ1") + k("QEZ2") * d + k0("QEZ3") * d * d) * (1 + k("QEZ5") * g * 2 / M_PI * std::atan(Bt * Ct * a));
    const double t = Dt * std::cos(Ct * std::atan(Bt * ateq - Et * (Bt * ateq - std::atan(Bt * ateq)))) * ca;
    const double By0 = Kya(Fz, 0) / (k("PCY1") * Dy(Fz, 0));
    const double Br = k("QBZ9") + k("QBZ10") * By0 * k("PCY1");
    const double Dr = Fz * Rc * ((k("QDZ8") + k("QDZ9") * d) * g + (k("QDZ10") + k("QDZ11") * d) * g * std::abs(g)) * l("LRES") * ca;
    return -t * Gyk(s, a) * Fy0(Fz, a, 0) + Dr * std::cos(std::atan(Br * areq));
  }
  // ISO-W forces at an ISO operating point under a convention (docs/tyres.md): z_down (MBSim, TUMFTM)
  // evaluates at a = s(alpha_ISO), g = gamma_ISO and turns Fy and Mz; z_up at a = -s, g = -gamma_ISO;
  // s is the angle or its tangent.
  TyreForces iso(const MotorcycleConventions& cv, double Fz, double kappa, double alpha, double gamma) const {
    const double sign = cv.axes == MotorcyclePaperAxes::ZDown ? 1.0 : -1.0;
    const double a = sign * (cv.slip == MotorcycleSlipVariable::Angle ? alpha : std::tan(alpha)), g = sign * gamma;
    TyreForces f;
    f.Fx = Fx0(Fz, kappa) * Gxa(kappa, a);
    f.Fy = -sign * Fy0(Fz, a, g) * Gyk(kappa, a);
    f.Mz = -sign * Mz(Fz, kappa, a, g);
    return f;
  }
};

const std::vector<MotorcycleConventions> kAllConventions = {
    {MotorcyclePaperAxes::ZDown, MotorcycleSlipVariable::Angle},
    {MotorcyclePaperAxes::ZDown, MotorcycleSlipVariable::Tangent},
    {MotorcyclePaperAxes::ZUp, MotorcycleSlipVariable::Angle},
    {MotorcyclePaperAxes::ZUp, MotorcycleSlipVariable::Tangent}};

// The motorcycle scaling factors drawn in [0.6, 1.4].
std::map<std::string, double> drawMotorcycleScaling(PortableRandom& r) {
  std::map<std::string, double> out;
  for (const auto& name : getScalingNames(MagicFormulaVariant::Motorcycle)) out[name] = r.drawUniform(0.6, 1.4);
  return out;
}

// Pure and combined slip at camber up to 60 degrees, slip on both sides of zero (and of RBY3), for every
// convention, with and without QEZ3 and with drawn PDY2, PDY3.
TEST(MotorcycleMagicFormula, MatchesSharpEvangelouLimebeerAtDrawnPoints) {
  PortableRandom rng(42);
  for (int i = 0; i < 400; ++i) {
    const MotorcycleConventions cv = kAllConventions[i % 4];
    const auto scaling = drawMotorcycleScaling(rng);
    auto coefficients = kFront120;
    if (i % 8 >= 4) coefficients.erase("QEZ3");
    if (i % 3 == 0) {
      coefficients["PDY2"] = rng.drawUniform(-0.2, 0.2);
      coefficients["PDY3"] = rng.drawUniform(0, 0.5);
    }
    const auto law = makeMotorcycleMagicFormula(*makeMapSource(coefficients, &scaling), cv);
    const SharpTyre ref{coefficients, scaling, coefficients.at("CROWN_RADIUS")};
    const double Fz = rng.drawUniform(200, 3000), alpha = rng.drawUniform(-0.25, 0.25), gamma = rng.drawUniform(-M_PI / 3, M_PI / 3);
    const double s = rng.drawUniform(-0.15, 0.15), V = rng.drawUniform(2, 60);
    auto expectNear = [&](const TyreForces& got, const TyreForces& want, const char* what) {
      EXPECT_NEAR(got.Fx, want.Fx, 1e-9 * Fz) << what << " " << i;
      EXPECT_NEAR(got.Fy, want.Fy, 1e-9 * Fz) << what << " " << i;
      EXPECT_NEAR(got.Mz, want.Mz, 1e-10 * Fz) << what << " " << i;
      EXPECT_EQ(got.Mx, 0) << what;
      EXPECT_EQ(got.My, 0) << what;
    };
    expectNear(law->calcForces({Fz, 0, alpha, gamma, V}), ref.iso(cv, Fz, 0, alpha, gamma), "pure side slip");
    expectNear(law->calcForces({Fz, s, 0, gamma, V}), ref.iso(cv, Fz, s, 0, gamma), "pure longitudinal slip");
    expectNear(law->calcForces({Fz, s, alpha, gamma, V}), ref.iso(cv, Fz, s, alpha, gamma), "combined slip");
    // Relaxation sigma = K_ya (c1 + c2 V + c3 V^2) at the camber.
    const double sigma = ref.Kya(Fz, gamma) * (kFront120.at("RELAX_C1") + kFront120.at("RELAX_C2") * V + kFront120.at("RELAX_C3") * V * V);
    EXPECT_NEAR(law->calcRelaxationLength(Fz, gamma, V), sigma, 1e-12) << i;
  }
  // Slopes at zero: cornering stiffness PKY1 Fz0 sin(PKY2 atan(Fz/(PKY3 Fz0))) and camber stiffness
  // (PKY6 + PKY7 dfz) Fz, both pushing to +y for a positive slip or camber in the paper's signs, so
  // negative in ISO signs whatever the convention.
  auto c = [](const char* k) { return kFront120.at(k); };
  for (const auto& cv : kAllConventions) {
    const auto law = makeMotorcycleMagicFormula(*makeMapSource(kFront120, nullptr), cv);
    for (double Fz : {600.0, 1100.0, 1900.0}) {
      const double Kya = c("PKY1") * c("FNOMIN") * std::sin(c("PKY2") * std::atan(Fz / (c("PKY3") * c("FNOMIN"))));
      const double Kyg = (c("PKY6") + c("PKY7") * (Fz - c("FNOMIN")) / c("FNOMIN")) * Fz;
      EXPECT_NEAR(-slope(*law, Fz, &TyreSlip::alpha, &TyreForces::Fy), Kya, 1e-6 * Kya);
      EXPECT_NEAR(-slope(*law, Fz, &TyreSlip::gamma, &TyreForces::Fy), Kyg, 1e-6 * Kyg);
      EXPECT_NEAR(-law->calcCorneringStiffness(Fz), Kya, 1e-9 * Kya);
      EXPECT_NEAR(-law->calcCamberStiffness(Fz), Kyg, 1e-9 * Kyg);
    }
    // Evangelou (2004) Table 9.5 order: the front relaxation length at its nominal load and 20 m/s is
    // about 0.18 m (K_ya = 18.36 kN/rad there).
    EXPECT_NEAR(law->calcRelaxationLength(1100, 0, 20), 0.178, 0.002);
  }
}

// The law is odd in slip and camber jointly except for RBY3: the two axes readings give the same forces
// without longitudinal slip, or with RBY3 = 0; with both, the combined-slip side force is cut more
// strongly on the side of zero slip where the paper's slip a is near RBY3 (a = alpha_ISO for z_down,
// -alpha_ISO for z_up).
TEST(MotorcycleMagicFormula, OnlyTheRby3TermTellsThePaperAxesApart) {
  const MotorcycleConventions down{MotorcyclePaperAxes::ZDown, MotorcycleSlipVariable::Angle};
  const MotorcycleConventions up{MotorcyclePaperAxes::ZUp, MotorcycleSlipVariable::Angle};
  auto symmetric = kFront120;
  symmetric["RBY3"] = 0;
  const auto lawDown = makeMotorcycleMagicFormula(*makeMapSource(kFront120, nullptr), down);
  const auto lawUp = makeMotorcycleMagicFormula(*makeMapSource(kFront120, nullptr), up);
  const auto symDown = makeMotorcycleMagicFormula(*makeMapSource(symmetric, nullptr), down);
  const auto symUp = makeMotorcycleMagicFormula(*makeMapSource(symmetric, nullptr), up);
  PortableRandom rng(7341);
  for (int i = 0; i < 100; ++i) {
    const double Fz = rng.drawUniform(300, 3000), alpha = rng.drawUniform(-0.3, 0.3), gamma = rng.drawUniform(-1, 1);
    const double kappa = rng.drawUniform(-0.2, 0.2);
    const TyreForces d0 = lawDown->calcForces({Fz, 0, alpha, gamma, 20}), u0 = lawUp->calcForces({Fz, 0, alpha, gamma, 20});
    EXPECT_NEAR(d0.Fy, u0.Fy, 1e-10 * Fz) << i;
    EXPECT_NEAR(d0.Mz, u0.Mz, 1e-11 * Fz) << i;
    const TyreForces ds = symDown->calcForces({Fz, kappa, alpha, gamma, 20}), us = symUp->calcForces({Fz, kappa, alpha, gamma, 20});
    EXPECT_NEAR(ds.Fx, us.Fx, 1e-10 * Fz) << i;
    EXPECT_NEAR(ds.Fy, us.Fy, 1e-10 * Fz) << i;
    EXPECT_NEAR(ds.Mz, us.Mz, 1e-11 * Fz) << i;
  }
  // Front tyre at 1500 N, slip ratio 0.1, zero camber, +/-5 degrees: with RBY3 = -0.059 < 0 the factor
  // Byk(a) = RBY1 cos(atan(RBY2 (a - RBY3))) is larger at a = -5 deg than at +5 deg, so the side force is
  // cut more where the paper's a is negative: at alpha_ISO = -5 deg for z_down, +5 deg for z_up.
  const SharpTyre ref{kFront120, {}, kFront120.at("CROWN_RADIUS")};
  const double Fz = 1500, kappa = 0.1, deg5 = 5 * M_PI / 180;
  ASSERT_GT(ref.Byk(-deg5), ref.Byk(deg5));
  const double downPlus = lawDown->calcForces({Fz, kappa, deg5, 0, 20}).Fy, downMinus = lawDown->calcForces({Fz, kappa, -deg5, 0, 20}).Fy;
  const double upPlus = lawUp->calcForces({Fz, kappa, deg5, 0, 20}).Fy, upMinus = lawUp->calcForces({Fz, kappa, -deg5, 0, 20}).Fy;
  EXPECT_LT(downPlus, 0);
  EXPECT_GT(downMinus, 0);
  EXPECT_GT(std::abs(downPlus), std::abs(downMinus) + 100) << downPlus << " " << downMinus;
  EXPECT_NEAR(upPlus, -downMinus, 1e-9 * Fz);
  EXPECT_NEAR(upMinus, -downPlus, 1e-9 * Fz);
  // The sizes from the independent evaluation: |Fy| = Dy sin(Cy atan(...)) Gyk at a = +/-5 deg.
  EXPECT_NEAR(downPlus, -ref.Fy0(Fz, deg5, 0) * ref.Gyk(kappa, deg5), 1e-9 * Fz);
  EXPECT_NEAR(downMinus, -ref.Fy0(Fz, -deg5, 0) * ref.Gyk(kappa, -deg5), 1e-9 * Fz);
}

// The physical signs of the law with the published front set, at its nominal load (Cossalter 2006,
// Motorcycle Dynamics, ch. 2), whatever the convention: camber thrust pushes the tyre towards the lean
// and the camber (twisting) moment turns it towards the lean; the self-aligning moment of a slip turns it
// towards its velocity. ISO-W: a wheel leaning right has gamma_ISO > 0, a wheel sliding left
// alpha_ISO > 0. The twisting slope per unit load, Rc QDZ8 = 0.022 m/rad, is of the order of the seed
// paper's Table 6 linear front tyre (0.032 m/rad); with the unloaded radius in its place it would be
// 0.116 m/rad.
TEST(MotorcycleMagicFormula, CamberTwistsTowardsTheLeanAndSlipAlignsTowardsTheVelocity) {
  for (const auto& cv : kAllConventions) {
    const auto law = makeMotorcycleMagicFormula(*makeMapSource(kFront120, nullptr), cv);
    const double Fz = kFront120.at("FNOMIN");
    for (double gamma : {0.2, 0.4, 0.8, 1.0}) {
      const TyreForces right = law->calcForces({Fz, 0, 0, gamma, 25});
      const TyreForces left = law->calcForces({Fz, 0, 0, -gamma, 25});
      EXPECT_LT(right.Fy, 0) << gamma;
      EXPECT_LT(right.Mz, 0) << gamma;
      EXPECT_NEAR(left.Fy, -right.Fy, 1e-9 * Fz) << gamma;
      EXPECT_NEAR(left.Mz, -right.Mz, 1e-9 * Fz) << gamma;
    }
    const double h = 1e-6;
    const double twisting = -(law->calcForces({Fz, 0, 0, h, 25}).Mz - law->calcForces({Fz, 0, 0, -h, 25}).Mz) / (2 * h) / Fz;
    EXPECT_NEAR(twisting, kFront120.at("CROWN_RADIUS") * kFront120.at("QDZ8"), 1e-6);
    EXPECT_GT(twisting, 0.032 / 3);
    EXPECT_LT(twisting, 0.032 * 3);
    const TyreForces slipping = law->calcForces({Fz, 0, 0.01, 0, 25});
    EXPECT_LT(slipping.Fy, 0);
    EXPECT_GT(slipping.Mz, 0);
  }
}

// Where the slip variable matters: the paper's equations at the angle or at its tangent. At 10 degrees
// the two differ by tan(0.1745) - 0.1745 = 0.0018 rad of slip, a fraction of a per cent of the force.
TEST(MotorcycleMagicFormula, SlipVariableIsTheAngleOrItsTangent) {
  const SharpTyre ref{kFront120, {}, kFront120.at("CROWN_RADIUS")};
  const double Fz = 1100, alpha = 10 * M_PI / 180;
  const auto angle = makeMotorcycleMagicFormula(*makeMapSource(kFront120, nullptr), {MotorcyclePaperAxes::ZDown, MotorcycleSlipVariable::Angle});
  const auto tangent = makeMotorcycleMagicFormula(*makeMapSource(kFront120, nullptr), {MotorcyclePaperAxes::ZDown, MotorcycleSlipVariable::Tangent});
  EXPECT_NEAR(angle->calcForces({Fz, 0, alpha, 0, 20}).Fy, -ref.Fy0(Fz, alpha, 0), 1e-9 * Fz);
  EXPECT_NEAR(tangent->calcForces({Fz, 0, alpha, 0, 20}).Fy, -ref.Fy0(Fz, std::tan(alpha), 0), 1e-9 * Fz);
  EXPECT_NE(angle->calcForces({Fz, 0, alpha, 0, 20}).Fy, tangent->calcForces({Fz, 0, alpha, 0, 20}).Fy);
}

TEST(MotorcycleMagicFormula, RelaxationCoefficientsAllOrNone) {
  auto m = kFront120;
  m.erase("RELAX_C2");
  EXPECT_THROW(makeMotorcycleMagicFormula(*makeMapSource(m, nullptr)), InputError);
  m.erase("RELAX_C1");
  m.erase("RELAX_C3");
  EXPECT_TRUE(std::isnan(makeMotorcycleMagicFormula(*makeMapSource(m, nullptr))->calcRelaxationLength(1100, 0, 20)));
}

// A relaxation length that is zero or negative at some speed (unstable "relaxation" roots) is refused,
// naming the coefficient: c1 > 0, c3 >= 0 and, for c2 < 0, c2^2 < 4 c1 c3 (Evangelou's rear set has
// c2 < 0 and passes: 1.78e-16 < 7.36e-14).
TEST(MotorcycleMagicFormula, RelaxationLengthPositiveAtEverySpeed) {
  auto refuses = [](std::map<std::string, double> m, const std::string& key) {
    const InputError e = test::catchInputError([&] { makeMotorcycleMagicFormula(*makeMapSource(m, nullptr)); });
    EXPECT_EQ(e.getLocation().key, key) << e.what();
  };
  for (double c1 : {-8.633e-6, 0.0}) {
    auto m = kFront120;
    m["RELAX_C1"] = c1;
    refuses(m, "RELAX_C1");
  }
  auto m = kFront120;
  m["RELAX_C3"] = -1e-12;
  refuses(m, "RELAX_C3");
  m = kFront120;
  m["RELAX_C2"] = -2 * std::sqrt(m["RELAX_C1"] * m["RELAX_C3"]) * 1.01;  // a double root just below zero
  refuses(m, "RELAX_C2");
  m = kFront120;
  m["RELAX_C2"] = -1.333e-8;  // the rear set's sign
  const auto law = makeMotorcycleMagicFormula(*makeMapSource(m, nullptr));
  for (double V = 0; V <= 200; V += 5) EXPECT_GT(law->calcRelaxationLength(1100, 0, V), 0) << V;
}

// The motorcycle coefficients' signs, and laws that are degenerate or not finite in their range.
TEST(MotorcycleMagicFormula, MeaninglessCoefficientsAreRefused) {
  for (const auto& [key, value] : std::vector<std::pair<std::string, double>>{
           {"PCY1", 0}, {"PCY2", -0.8}, {"PKY1", -22.8}, {"PKX1", 0}, {"PDX1", -1}, {"PDY3", -1}, {"CROWN_RADIUS", 0},
           // PKY3 + PKY4 g^2 and 1 + PKY5 g^2 divide in K_ya: zero at 0, and at 90 deg for PKY4 = -PKY3 4/pi^2,
           // PKY5 = -4/pi^2 (the set's PKY3 is 2.5058).
           {"PKY3", 0}, {"PKY4", -1.1}, {"PKY5", -0.41}}) {
    auto m = kFront120;
    m[key] = value;
    const InputError e = test::catchInputError([&] { makeMotorcycleMagicFormula(*makeMapSource(m, nullptr)); });
    EXPECT_EQ(e.getLocation().key, key) << e.what();
  }
  const std::map<std::string, double> scaling{{"LTR", -1.0}};
  EXPECT_EQ(test::catchInputError([&] { makeMotorcycleMagicFormula(*makeMapSource(kFront120, &scaling)); }).getLocation().key, "LTR");
  // PDY2 = 1000: exp(1000 dfz) overflows above about 1.7 FNOMIN; PKY2 = 5: sin(5 atan(Fz/(PKY3 Fz0))) < 0
  // above 0.73 PKY3 Fz0 = 2000 N. Both pass the sign checks; the range check refuses them at the set ("").
  auto overflow = kFront120;
  overflow["PDY2"] = 1000;
  const InputError inf = test::catchInputError([&] { makeTyreForceLaw(MagicFormulaVariant::Motorcycle, *makeMapSource(overflow, nullptr)); });
  EXPECT_EQ(inf.getLocation().key, "");
  EXPECT_NE(inf.getReason().find("not finite at Fz 2200 N"), std::string::npos) << inf.what();
  auto turning = kFront120;
  turning["PKY2"] = 5;
  const InputError flip = test::catchInputError([&] { makeTyreForceLaw(MagicFormulaVariant::Motorcycle, *makeMapSource(turning, nullptr)); });
  EXPECT_NE(flip.getReason().find("cornering stiffness"), std::string::npos) << flip.what();
  // The published sets load, in every convention.
  for (const auto& cv : kAllConventions)
    EXPECT_NO_THROW(makeTyreForceLaw(MagicFormulaVariant::Motorcycle, *makeMapSource(kFront120, nullptr), std::nullopt, cv));
}

}  // namespace
}  // namespace motostab::tyres
