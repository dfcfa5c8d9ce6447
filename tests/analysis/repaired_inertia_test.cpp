// the BicycleParameters bicycles whose measured frame inertia breaks the triangle
// inequality (Browser rear frame, Yellow and Yellowrev front frames), imported with --repair-inertia,
// give the eigenvalues of the linearised Whipple model of Meijaard et al. (2007), Appendix A
// (tests/support/benchmark_equations.h), evaluated on the file's unrepaired values. The formulas do not
// contain the frames' I_yy, which is what the repair lowers.
#include <gtest/gtest.h>

#include <complex>
#include <filesystem>

#include <Eigen/Dense>

#include "tests/support/benchmark_equations.h"
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

using testing::calcMeijaardMatrices;
using testing::makeBenchmarkParameters;

// Roots of det(M s^2 + v C1 s + g K0 + v^2 K2) from the first-order form.
Eigen::VectorXcd calcWhippleEigenvalues(const testing::Benchmark& m, double gravity, double v) {
  return Eigen::EigenSolver<Eigen::Matrix4d>(testing::calcBenchmarkStateMatrix(m, gravity, v)).eigenvalues();
}

// The formulas themselves against Meijaard et al. (2007) Table 2 (benchmark bicycle, v = 5 m/s).
TEST(RepairedInertia, FormulasReproduceMeijaardTable2) {
  const auto p = readBicycleParameters(kBicycles + "Benchmark/Parameters/BenchmarkBenchmark.txt");
  const auto e = calcWhippleEigenvalues(calcMeijaardMatrices(makeBenchmarkParameters(p)), p.at("g"), 5.0);
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
    const testing::Benchmark m = calcMeijaardMatrices(makeBenchmarkParameters(p));
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
