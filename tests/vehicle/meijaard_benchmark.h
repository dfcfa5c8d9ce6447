#pragma once
// The linearised Whipple bicycle of Meijaard, Papadopoulos, Ruina, Schwab (2007), written in the
// tests from the paper (independent of motostab's Simbody model), shared by the extension tests.
#include <Eigen/Dense>
#include <cmath>

#include "scenario/scenario.h"

namespace motostab::testing {

using scenario::BodySpec;
using scenario::Scenario;


// Meijaard, Papadopoulos, Ruina, Schwab (2007), Proc. R. Soc. A 463:1955-1982, Appendix A
// (eqs. A1-A27): M, C1, K0, K2 of the linearised Whipple bicycle from its Table 1 parameters, in the
// paper's frame (z down, steer positive right). Written here from the paper, not from motostab.
struct Benchmark {
  Eigen::Matrix2d M, C1, K0, K2;
};

inline Benchmark calcMeijaardMatrices(const Scenario& s) {
  const double w = s.geometry.wheelbase, c = s.geometry.trail, lam = s.geometry.steerAxisTilt;
  const double rR = s.rearWheel.radius, mR = s.rearWheel.mass, IRxx = s.rearWheel.diametralInertia,
               IRyy = s.rearWheel.axialInertia;
  const double rF = s.frontWheel.radius, mF = s.frontWheel.mass, IFxx = s.frontWheel.diametralInertia,
               IFyy = s.frontWheel.axialInertia;
  // Design frame (z up) to the paper's (z down): z and the xz products change sign.
  const BodySpec &B = s.rearFrame, &H = s.frontFrame;
  const double xB = B.com[0], zB = -B.com[2], mB = B.mass;
  const double IBxx = B.inertia.xx, IBzz = B.inertia.zz, IBxz = -B.inertia.xz;
  const double xH = H.com[0], zH = -H.com[2], mH = H.mass;
  const double IHxx = H.inertia.xx, IHzz = H.inertia.zz, IHxz = -H.inertia.xz;
  const double IRzz = IRxx, IFzz = IFxx;
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
  const double uA = (xA - w - c) * std::cos(lam) - zA * std::sin(lam);                                       // A11
  const double sl = std::sin(lam), cl = std::cos(lam);
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

}  // namespace motostab::testing
