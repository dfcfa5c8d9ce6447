// the BicycleParameters bicycles whose measured frame inertia breaks the triangle
// inequality (Browser rear frame, Yellow and Yellowrev front frames), imported with --repair-inertia,
// give the eigenvalues of the linearised Whipple model of Meijaard, Papadopoulos, Ruina, Schwab (2007),
// Proc. R. Soc. A 463:1955-1982, Appendix A (M, C1, K0, K2), evaluated here on the file's unrepaired
// values. The formulas do not contain the frames' I_yy, which is what the repair lowers.
#include <gtest/gtest.h>

#include <complex>
#include <filesystem>

#include <Eigen/Dense>

#include "tests/support/temp_dir.h"
#include "analysis/sweep.h"
#include "io/atomic_file.h"
#include "scenario/bicycle_parameters.h"

namespace motostab::analysis {

using io::writeFileAtomically;
using scenario::convertBicycleParametersToScenario;
using scenario::loadScenario;
using scenario::readBicycleParameters;
using vehicle::VehicleModel;

namespace {

const std::string kBicycles = std::string(MOTOSTAB_TEST_DATA_DIR) + "/measured-data/BicycleParameters/data/bicycles/";

struct WhippleMatrices {
  Eigen::Matrix2d M, C1, K0, K2;
};

// Meijaard et al. (2007) Appendix A, benchmark frame (x forward, y right, z down), from the parameter map.
WhippleMatrices calcMeijaardMatrices(const std::map<std::string, double>& p) {
  auto g = [&](const char* k) { return p.at(k); };
  const double w = g("w"), c = g("c"), lam = g("lam"), rR = g("rR"), rF = g("rF");
  const double mR = g("mR"), mB = g("mB"), mH = g("mH"), mF = g("mF");
  const double xB = g("xB"), zB = g("zB"), xH = g("xH"), zH = g("zH");
  const double IRxx = g("IRxx"), IRyy = g("IRyy"), IFxx = g("IFxx"), IFyy = g("IFyy");
  const double IBxx = g("IBxx"), IBxz = g("IBxz"), IBzz = g("IBzz");
  const double IHxx = g("IHxx"), IHxz = g("IHxz"), IHzz = g("IHzz");
  const double IRzz = IRxx, IFzz = IFxx;  // wheels are bodies of revolution
  const double mT = mR + mB + mH + mF;
  const double xT = (xB * mB + xH * mH + w * mF) / mT;
  const double zT = (-rR * mR + zB * mB + zH * mH - rF * mF) / mT;
  const double ITxx = IRxx + IBxx + IHxx + IFxx + mR * rR * rR + mB * zB * zB + mH * zH * zH + mF * rF * rF;
  const double ITxz = IBxz + IHxz - mB * xB * zB - mH * xH * zH + mF * w * rF;
  const double ITzz = IRzz + IBzz + IHzz + IFzz + mB * xB * xB + mH * xH * xH + mF * w * w;
  const double mA = mH + mF;
  const double xA = (xH * mH + w * mF) / mA, zA = (zH * mH - rF * mF) / mA;
  const double IAxx = IHxx + IFxx + mH * (zH - zA) * (zH - zA) + mF * (rF + zA) * (rF + zA);
  const double IAxz = IHxz - mH * (xH - xA) * (zH - zA) + mF * (w - xA) * (rF + zA);
  const double IAzz = IHzz + IFzz + mH * (xH - xA) * (xH - xA) + mF * (w - xA) * (w - xA);
  const double sl = std::sin(lam), cl = std::cos(lam);
  const double uA = (xA - w - c) * cl - zA * sl;
  const double IAll = mA * uA * uA + IAxx * sl * sl + 2 * IAxz * sl * cl + IAzz * cl * cl;
  const double IAlx = -mA * uA * zA + IAxx * sl + IAxz * cl;
  const double IAlz = mA * uA * xA + IAxz * sl + IAzz * cl;
  const double mu = c / w * cl;
  const double SR = IRyy / rR, SF = IFyy / rF, ST = SR + SF;
  const double SA = mA * uA + mu * mT * xT;
  WhippleMatrices m;
  m.M << ITxx, IAlx + mu * ITxz, IAlx + mu * ITxz, IAll + 2 * mu * IAlz + mu * mu * ITzz;
  m.K0 << mT * zT, -SA, -SA, -SA * sl;
  m.K2 << 0, (ST - mT * zT) * cl / w, 0, (SA + SF * sl) * cl / w;
  m.C1 << 0, mu * ST + SF * cl + ITxz * cl / w - mu * mT * zT, -(mu * ST + SF * cl),
      IAlz * cl / w + mu * (SA + ITzz * cl / w);
  return m;
}

// Roots of det(M s^2 + v C1 s + g K0 + v^2 K2) from the first-order form.
Eigen::VectorXcd calcWhippleEigenvalues(const WhippleMatrices& m, double gravity, double v) {
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  A.topRightCorner(2, 2).setIdentity();
  const Eigen::Matrix2d Minv = m.M.inverse();
  A.bottomLeftCorner(2, 2) = -Minv * (gravity * m.K0 + v * v * m.K2);
  A.bottomRightCorner(2, 2) = -Minv * (v * m.C1);
  return Eigen::EigenSolver<Eigen::Matrix4d>(A).eigenvalues();
}

// The formulas themselves against Meijaard et al. (2007) Table 2 (benchmark bicycle, v = 5 m/s).
TEST(RepairedInertia, FormulasReproduceMeijaardTable2) {
  const auto p = readBicycleParameters(kBicycles + "Benchmark/Parameters/BenchmarkBenchmark.txt");
  const auto e = calcWhippleEigenvalues(calcMeijaardMatrices(p), p.at("g"), 5.0);
  const std::complex<double> table2[] = {{-0.77534188219585, 4.46486771378823}, {-0.77534188219585, -4.46486771378823},
                                         {-0.32286642900409, 0}, {-14.07838969279820, 0}};
  for (const auto& t : table2) {
    double best = INFINITY;
    for (int k = 0; k < 4; ++k) best = std::min(best, std::abs(e[k] - t));
    EXPECT_LT(best, 1e-10) << t;
  }
}

TEST(RepairedInertia, EigenvaluesEqualMeijaardFormulasOnTheFileValues) {
  for (const char* bike : {"Browser", "Yellow", "Yellowrev"}) {
    const std::string file = kBicycles + bike + "/Parameters/" + bike + "Benchmark.txt";
    const auto p = readBicycleParameters(file);  // unrepaired
    const WhippleMatrices m = calcMeijaardMatrices(p);
    const auto tmp = makeTempDir("repaired") / ("motostab_repaired_" + std::string(bike) + ".yaml");
    writeFileAtomically(tmp, convertBicycleParametersToScenario(file, bike, {true}));
    const VehicleModel model(loadScenario(tmp.string()));
    double worst = 0;
    for (double v : {0.7, 3.0, 5.5, 9.0}) {
      const LinearModel lin = linearize(model, calcTrim(model, v));
      const Eigen::VectorXcd ref = calcWhippleEigenvalues(m, p.at("g"), v);
      std::vector<bool> used(lin.eigenvalues.size(), false);  // one-to-one matching
      for (int k = 0; k < 4; ++k) {
        int best = -1;
        for (int j = 0; j < lin.eigenvalues.size(); ++j)
          if (!used[j] && (best < 0 || std::abs(lin.eigenvalues[j] - ref[k]) < std::abs(lin.eigenvalues[best] - ref[k]))) best = j;
        ASSERT_GE(best, 0);
        used[best] = true;
        EXPECT_LT(std::abs(lin.eigenvalues[best] - ref[k]), 1e-8) << bike << " v=" << v << " ref " << ref[k];
        worst = std::max(worst, std::abs(lin.eigenvalues[best] - ref[k]));
      }
    }
    std::printf("[%s] worst |lambda - Meijaard 2007| = %.3g 1/s\n", bike, worst);
  }
}

}  // namespace
}  // namespace motostab::analysis
