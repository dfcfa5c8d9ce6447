// Modes from a simulated response of the linear Whipple benchmark bicycle, M q'' + v C1 q' + (g K0 + v^2 K2) q = 0,
// q = [roll, steer] (Meijaard, Papadopoulos, Ruina, Schwab 2007, Proc. R. Soc. A 463:1955-1982, eq. 3.8 matrices
// and Table 2 eigenvalues). The response x(t) = V exp(Lambda t) V^-1 x0 is computed here from the matrices;
// the identified eigenvalues are compared with the published Table 2 values.
#include <gtest/gtest.h>

#include <complex>
#include <iostream>

#include <Eigen/Dense>

#include "response/mode_identification.h"
#include "tests/support/benchmark_equations.h"

namespace {

struct BenchmarkPoint {
  double speed;                     // m/s
  std::complex<double> weave;       // 1/s (Table 2)
  double capsize, castor;           // 1/s (Table 2)
};

// Meijaard et al. (2007), Table 2.
const BenchmarkPoint kPoints[] = {
    {5.0, {-0.77534188219585, 4.46486771378823}, -0.32286642900409, -14.07838969279820},
    {4.0, {0.41325331521125, 3.07910818603206}, -1.42944427361326, -12.15861426576450},
    {8.0, {-2.69348683581097, 8.46037971396931}, 0.14327879765713, -20.27940894394569},
    {6.0, {-1.52644486584142, 5.87673060598709}, -0.00406690076970, -16.08537123098030},
};

// Roll rate and steer rate (rad/s) after a steer-rate kick of 0.5 rad/s, sampled at `step` s for `duration` s.
void simulateKick(double v, double duration, double step, std::vector<double>& t, std::vector<double>& rollRate,
                  std::vector<double>& steerRate) {
  const Eigen::Matrix4d a = motostab::testing::calcBenchmarkStateMatrix(v);
  Eigen::EigenSolver<Eigen::Matrix4d> eig(a);
  const Eigen::Matrix4cd vecs = eig.eigenvectors();
  const Eigen::Vector4cd coeff = vecs.inverse() * Eigen::Vector4cd(0, 0, 0, 0.5);
  for (int i = 0; i * step <= duration + 1e-12; ++i) {
    const double ti = i * step;
    Eigen::Vector4cd x = Eigen::Vector4cd::Zero();
    for (int j = 0; j < 4; ++j) x += vecs.col(j) * coeff(j) * std::exp(eig.eigenvalues()(j) * ti);
    t.push_back(ti);
    rollRate.push_back(x(2).real());
    steerRate.push_back(x(3).real());
  }
}

TEST(ResponseWhipple, KickResponseGivesTable2Eigenvalues) {
  for (const auto& p : kPoints) {
    std::vector<double> t, roll, steer;
    simulateKick(p.speed, 3.0, 0.005, t, roll, steer);
    const auto r = motostab::response::identifyModes(t, {roll, steer});
    std::cout << "v = " << p.speed << " m/s: order " << r.order << ", modes:";
    for (const auto& m : r.modes) std::cout << " " << m.real << (m.imag >= 0 ? "+" : "") << m.imag << "i";
    std::cout << "\n";
    EXPECT_EQ(r.order, 4) << "v = " << p.speed;
    bool weave = false, capsize = false, castor = false;
    for (const auto& m : r.modes) {
      if (m.imag > 0) {
        weave = true;
        EXPECT_NEAR(m.real, p.weave.real(), 1e-7) << "v = " << p.speed;
        EXPECT_NEAR(m.imag, p.weave.imag(), 1e-7) << "v = " << p.speed;
      } else if (std::abs(m.real - p.capsize) < 0.1) {
        capsize = true;
        EXPECT_NEAR(m.real, p.capsize, 1e-7) << "v = " << p.speed;
      } else {
        castor = true;
        EXPECT_NEAR(m.real, p.castor, 1e-6) << "v = " << p.speed;
      }
    }
    EXPECT_TRUE(weave && capsize && castor) << "v = " << p.speed;
    EXPECT_NEAR(r.offset[0], 0.0, 1e-9);
  }
}

}  // namespace
