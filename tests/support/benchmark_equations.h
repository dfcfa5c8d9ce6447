#pragma once
// Test helper: the benchmark bicycle's linear equations, transcribed from Meijaard, Papadopoulos, Ruina
// & Schwab (2007), Proc. R. Soc. A 463:1955, eq. (1) with the Appendix A matrices of the Table 1 bicycle:
// M q'' + v C1 q' + (g K0 + v^2 K2) q = 0, q = (roll, steer), g = 9.81 m/s^2. Independent of the code
// under test.
#include <Eigen/Dense>

namespace motostab::testing {

/// The first-order state matrix at speed v (m/s), states (roll, steer, roll rate, steer rate).
inline Eigen::Matrix4d calcBenchmarkStateMatrix(double v) {
  Eigen::Matrix2d M, C1, K0, K2;
  M << 80.81722, 2.31941332208709, 2.31941332208709, 0.29784188199686;
  C1 << 0, 33.86641391492494, -0.85035641456978, 1.68540397397560;
  K0 << -80.95, -2.59951685249872, -2.59951685249872, -0.80329488458618;
  K2 << 0, 76.59734589573222, 0, 2.65431523794604;
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  A.topRightCorner<2, 2>().setIdentity();
  A.bottomLeftCorner<2, 2>() = -M.inverse() * (9.81 * K0 + v * v * K2);
  A.bottomRightCorner<2, 2>() = -M.inverse() * (v * C1);
  return A;
}

}  // namespace motostab::testing
