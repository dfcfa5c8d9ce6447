#pragma once
// Test helper: the linearised Whipple bicycle of Meijaard, Papadopoulos, Ruina & Schwab (2007),
// "Linearized dynamics equations for the balance and steer of a bicycle: a benchmark and review",
// Proc. R. Soc. A 463:1955-1982, eq. (1): M q'' + v C1 q' + (g K0 + v^2 K2) q = f, q = (roll, steer),
// in the paper's frame (x forward, y right, z down; steer positive right). Two sources from the paper:
// the Appendix A formulas (A1-A27) from the parameters of any bicycle, and the published numeric
// matrices of the Table 1 benchmark bicycle. Written here from the paper, independent of motostab.
#include <Eigen/Dense>
#include <cmath>
#include <map>
#include <string>

#include "scenario/scenario.h"

namespace motostab::testing {

/// The Table 1 parameters in the paper's symbols and frame (SI units; z down).
struct BenchmarkParameters {
  double w, c, lam;                               ///< wheelbase, trail (m), steer axis tilt (rad)
  double rR, mR, IRxx, IRyy;                      ///< rear wheel
  double rF, mF, IFxx, IFyy;                      ///< front wheel
  double xB, zB, mB, IBxx, IBxz, IBzz;            ///< rear body and frame
  double xH, zH, mH, IHxx, IHxz, IHzz;            ///< front handlebar and fork assembly
};

/// M, C1, K0, K2 of eq. (1).
struct Benchmark {
  Eigen::Matrix2d M, C1, K0, K2;
};

/// Appendix A, eqs. (A1)-(A27): the matrices from the parameters.
inline Benchmark calcMeijaardMatrices(const BenchmarkParameters& p) {
  const double w = p.w, c = p.c, lam = p.lam, rR = p.rR, mR = p.mR, IRxx = p.IRxx, IRyy = p.IRyy;
  const double rF = p.rF, mF = p.mF, IFxx = p.IFxx, IFyy = p.IFyy;
  const double xB = p.xB, zB = p.zB, mB = p.mB, IBxx = p.IBxx, IBxz = p.IBxz, IBzz = p.IBzz;
  const double xH = p.xH, zH = p.zH, mH = p.mH, IHxx = p.IHxx, IHxz = p.IHxz, IHzz = p.IHzz;
  const double IRzz = IRxx, IFzz = IFxx;  // wheels are bodies of revolution
  const double mT = mR + mB + mH + mF;                                   // A1
  const double xT = (xB * mB + xH * mH + w * mF) / mT;                   // A2
  const double zT = (-rR * mR + zB * mB + zH * mH - rF * mF) / mT;       // A3
  const double ITxx = IRxx + IBxx + IHxx + IFxx + mR * rR * rR + mB * zB * zB + mH * zH * zH + mF * rF * rF;  // A4
  const double ITxz = IBxz + IHxz - mB * xB * zB - mH * xH * zH + mF * w * rF;                                // A5
  const double ITzz = IRzz + IBzz + IHzz + IFzz + mB * xB * xB + mH * xH * xH + mF * w * w;                  // A6, A7
  const double mA = mH + mF;                                                                                 // A8
  const double xA = (xH * mH + w * mF) / mA, zA = (zH * mH - rF * mF) / mA;                                  // A9
  const double IAxx = IHxx + IFxx + mH * (zH - zA) * (zH - zA) + mF * (rF + zA) * (rF + zA);                 // A10
  const double IAxz = IHxz - mH * (xH - xA) * (zH - zA) + mF * (w - xA) * (rF + zA);
  const double IAzz = IHzz + IFzz + mH * (xH - xA) * (xH - xA) + mF * (w - xA) * (w - xA);
  const double sl = std::sin(lam), cl = std::cos(lam);
  const double uA = (xA - w - c) * cl - zA * sl;                                                             // A11
  const double IAll = mA * uA * uA + IAxx * sl * sl + 2 * IAxz * sl * cl + IAzz * cl * cl;                   // A12
  const double IAlx = -mA * uA * zA + IAxx * sl + IAxz * cl;
  const double IAlz = mA * uA * xA + IAxz * sl + IAzz * cl;
  const double mu = c / w * cl;                                                                              // A13
  const double SR = IRyy / rR, SF = IFyy / rF, ST = SR + SF;                                                 // A14
  const double SA = mA * uA + mu * mT * xT;                                                                  // A15
  Benchmark b;
  b.M << ITxx, IAlx + mu * ITxz, IAlx + mu * ITxz, IAll + 2 * mu * IAlz + mu * mu * ITzz;                    // A16
  b.K0 << mT * zT, -SA, -SA, -SA * sl;                                                                       // A17
  b.K2 << 0, (ST - mT * zT) / w * cl, 0, (SA + SF * sl) / w * cl;                                            // A18
  b.C1 << 0, mu * ST + SF * cl + ITxz / w * cl - mu * mT * zT,                                               // A19-A23
      -(mu * ST + SF * cl), IAlz / w * cl + mu * (SA + ITzz / w * cl);
  return b;
}

/// The parameters of a scenario (design frame, z up: z and the xz products change sign).
inline BenchmarkParameters makeBenchmarkParameters(const scenario::Scenario& s) {
  const scenario::BodySpec &B = s.rearFrame, &H = s.frontFrame;
  return {s.geometry.wheelbase,          s.geometry.trail,
          s.geometry.steerAxisTilt,      s.rearWheel.radius,
          s.rearWheel.mass,              s.rearWheel.diametralInertia,
          s.rearWheel.axialInertia,      s.frontWheel.radius,
          s.frontWheel.mass,             s.frontWheel.diametralInertia,
          s.frontWheel.axialInertia,     B.com[0],
          -B.com[2],                     B.mass,
          B.inertia.xx,                  -B.inertia.xz,
          B.inertia.zz,                  H.com[0],
          -H.com[2],                     H.mass,
          H.inertia.xx,                  -H.inertia.xz,
          H.inertia.zz};
}

/// The parameters of a BicycleParameters "Benchmark" file (its keys are the paper's symbols).
inline BenchmarkParameters makeBenchmarkParameters(const std::map<std::string, double>& p) {
  auto g = [&](const char* k) { return p.at(k); };
  return {g("w"),  g("c"),    g("lam"),  g("rR"),   g("mR"),   g("IRxx"), g("IRyy"), g("rF"),
          g("mF"), g("IFxx"), g("IFyy"), g("xB"),   g("zB"),   g("mB"),   g("IBxx"), g("IBxz"),
          g("IBzz"), g("xH"), g("zH"),   g("mH"),   g("IHxx"), g("IHxz"), g("IHzz")};
}

inline Benchmark calcMeijaardMatrices(const scenario::Scenario& s) {
  return calcMeijaardMatrices(makeBenchmarkParameters(s));
}

/// The published matrices of the Table 1 benchmark bicycle (the paper's numeric values of eq. (1), 14
/// significant digits), a check on the formulas and on any model of that bicycle.
inline Benchmark getTable1Matrices() {
  Benchmark b;
  b.M << 80.81722, 2.31941332208709, 2.31941332208709, 0.29784188199686;
  b.C1 << 0, 33.86641391492494, -0.85035641456978, 1.68540397397560;
  b.K0 << -80.95, -2.59951685249872, -2.59951685249872, -0.80329488458618;
  b.K2 << 0, 76.59734589573222, 0, 2.65431523794604;
  return b;
}

/// The first-order state matrix at speed v (m/s) and gravity g (m/s^2), states (roll, steer, roll
/// rate, steer rate); with a steer spring k (N m/rad) and damper c (N m s/rad) between the frames in
/// the steer entries of K and C (as Meijaard et al. 2007 sec. 4 add a steering damper):
/// M q'' + (v C1 + diag(0, c)) q' + (g K0 + v^2 K2 + diag(0, k)) q = 0.
inline Eigen::Matrix4d calcBenchmarkStateMatrix(const Benchmark& b, double g, double v, double steerStiffness = 0,
                                                double steerDamping = 0) {
  const Eigen::Matrix2d K = g * b.K0 + v * v * b.K2 + Eigen::Vector2d(0, steerStiffness).asDiagonal().toDenseMatrix();
  const Eigen::Matrix2d C = v * b.C1 + Eigen::Vector2d(0, steerDamping).asDiagonal().toDenseMatrix();
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  A.topRightCorner<2, 2>().setIdentity();
  A.bottomLeftCorner<2, 2>() = -b.M.inverse() * K;
  A.bottomRightCorner<2, 2>() = -b.M.inverse() * C;
  return A;
}

/// The Table 1 bicycle's state matrix at speed v (m/s), g = 9.81 m/s^2.
inline Eigen::Matrix4d calcBenchmarkStateMatrix(double v) { return calcBenchmarkStateMatrix(getTable1Matrices(), 9.81, v); }

}  // namespace motostab::testing
