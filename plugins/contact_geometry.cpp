#include "plugins/contact_geometry.h"

namespace motostab::plugins {

using SimTK::Real;
using SimTK::Vec3;

ContactPoint calcTorusContact(const SimTK::Rotation& R_GW, const Vec3& w_GW_G, double R, double rho) {
  const Vec3 n(0, 0, 1);
  const Vec3 a = R_GW.y().asVec3();
  const Vec3 aDot = w_GW_G % a;
  const Vec3 m = n - (~n * a) * a;
  const Vec3 mDot = -(~n * aDot) * a - (~n * a) * aDot;
  const Real len = m.norm();
  const Vec3 d = -m / len;
  const Vec3 dDot = -(mDot / len - m * ((~m * mDot) / (len * len * len)));
  return {(R - rho) * d - rho * n, (R - rho) * dDot};
}

}  // namespace motostab::plugins
