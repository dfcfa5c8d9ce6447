// Seed eq. 7-25 against the paper's Tables 2-5 (Taraborrelli, Favaron, Doria).
#include <gtest/gtest.h>

#include <cmath>

#include "io/result_error.h"
#include "swingarm/identification/decomposition.h"

using motostab::swingarm::identification::calcBendingTorsionStiffness;
using motostab::swingarm::identification::calcModalDamping;
using motostab::swingarm::identification::calcReducedStiffness;
using motostab::swingarm::identification::calcSeriesStiffness;
using motostab::swingarm::identification::calcTwistDamping;


namespace {

using namespace motostab::swingarm::identification;

struct PaperSwingarm {
  double kTw, aTw, aB, kB, aT, kT;  // Table 2/3: Nm/rad, m
  double fB, etaB, fT, etaT;        // Hz, hysteretic loss factor
  double kbReduced, ktReduced;      // Table 4, Nm/rad
  double cB, cT, cTw;               // Table 5, Nms/rad
};
const PaperSwingarm kSwingarm1{246.4e3, 0.477, 0.451, 222.4e3, 0.026, 77.4e3, 134, 0.0074, 208, 0.0097,
                               248.8e3, 26050e3, 1.97, 0.58, 2.18};
const PaperSwingarm kSwingarm2{87.6e3, 0.375, 0.388, 94.2e3, 0.014, 55.2e3, 115, 0.0173, 184, 0.0102,
                               88.0e3, 39600e3, 2.25, 0.49, 2.09};

void checkTables(const PaperSwingarm& p) {
  // Table 4: k' = (a_tw/a)^2 k (eq. 14, 15), to 0.5 %.
  const double kb = calcReducedStiffness(p.kB, p.aB, p.aTw), kt = calcReducedStiffness(p.kT, p.aT, p.aTw);
  EXPECT_NEAR(kb, p.kbReduced, 0.005 * p.kbReduced);
  EXPECT_NEAR(kt, p.ktReduced, 0.005 * p.ktReduced);
  // Eq. 16-17: the series of the reduced stiffnesses is the twist stiffness (Table 2/3 input rounding: 0.5 %).
  EXPECT_NEAR(calcSeriesStiffness(kb, kt), p.kTw, 0.005 * p.kTw);
  // Eq. 7 with the tabulated arms and stiffnesses.
  EXPECT_NEAR(p.aTw * p.aTw / p.kTw, p.aB * p.aB / p.kB + p.aT * p.aT / p.kT, 0.005 * p.aTw * p.aTw / p.kTw);
  // Table 5: eq. 20 with viscous zeta = hysteretic / 2, eq. 25; +/- 0.02 Nms/rad.
  const double cB = calcModalDamping(p.kB, p.etaB / 2, p.fB), cT = calcModalDamping(p.kT, p.etaT / 2, p.fT);
  EXPECT_NEAR(cB, p.cB, 0.02);
  EXPECT_NEAR(cT, p.cT, 0.02);
  EXPECT_NEAR(calcTwistDamping(cB, cT, p.aB, p.kB, p.aT, p.kT, p.aTw, p.kTw), p.cTw, 0.02);
}

TEST(PaperTables, Swingarm1ReducedStiffnessAndDamping) { checkTables(kSwingarm1); }
TEST(PaperTables, Swingarm2ReducedStiffnessAndDamping) { checkTables(kSwingarm2); }

TEST(PaperTables, Table4BendingValueOfSwingarm1) {
  // The seed paper's worked example: eq. 17 (14) with Table 2 gives k'_b = 248.8 kNm/rad.
  EXPECT_NEAR(calcReducedStiffness(222.4e3, 0.451, 0.477) / 1e3, 248.8, 0.1);
}

// Eq. 7 and 10 solved for k_b, k_t: build the static axis angle by the vector sum of eq. 8-9 (independent
// forward calculation) from the paper's swingarm-1 stiffnesses and assumed modal axis angles, then solve back.
TEST(Decomposition, SolvesEquations7And10) {
  const PaperSwingarm& p = kSwingarm1;
  for (const auto& [betaB, betaT] : std::vector<std::pair<double, double>>{{95, 3}, {88, -4}, {100, 10}}) {
    const double ub = p.aB / p.kB, ut = p.aT / p.kT, d = M_PI / 180;
    const double cx = ub * std::cos(betaB * d) + ut * std::cos(betaT * d);
    const double cz = ub * std::sin(betaB * d) + ut * std::sin(betaT * d);
    const double beta = std::atan2(cz, cx) / d;
    const double aTwSq = p.aB * ub + p.aT * ut;  // a_tw^2 / k_tw (eq. 7), any a_tw
    const double aTw = 0.45, kTw = aTw * aTw / aTwSq;
    const auto k = calcBendingTorsionStiffness(aTw, kTw, beta, p.aB, betaB, p.aT, betaT);
    EXPECT_NEAR(k.kB, p.kB, 1e-9 * p.kB);
    EXPECT_NEAR(k.kT, p.kT, 1e-9 * p.kT);
  }
}

TEST(Decomposition, RejectsAStaticAxisOutsideTheModalAxes) {
  // Static axis not between the two modal axes -> a negative compliance, not a silent result.
  EXPECT_THROW(calcBendingTorsionStiffness(0.45, 2e5, 120, 0.45, 95, 0.026, 3), motostab::io::ResultError);
  EXPECT_THROW(calcBendingTorsionStiffness(0.45, 2e5, 90, 0.45, 95, 0.026, 95), motostab::io::ResultError);
}

}  // namespace
