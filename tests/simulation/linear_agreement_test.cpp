// Nonlinear simulation against the linearisation (analysis/linearize.h), which is computed independently
// of the integration path: small-perturbation histories against exp(A t) x0, weave identified from the
// simulated response against the linear eigenvalue, and capsize growth against the unstable eigenvalue.
// The linear Whipple model itself is checked against Meijaard et al. (2007) in tests/analysis.
#include <gtest/gtest.h>

#include <unsupported/Eigen/MatrixFunctions>

#include <complex>
#include <iostream>

#include "analysis/linearize.h"
#include "simulation/simulation.h"
#include "tests/simulation/linear_reference.h"
#include "apps/simulate_identify.h"

namespace motostab::simulation {

using analysis::LinearModel;
using scenario::Scenario;
using scenario::loadScenario;

namespace {

const Scenario& getWhipple() {
  static const Scenario s = loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml");
  return s;
}

LinearModel linearizeAt(double speed) { return linearizeScenarioAt(getWhipple(), speed); }

// (a) For a small initial roll- and steer-rate offset, roll and steer follow exp(A t) x0 over 2 s.
// x0 is read from the simulation's first sample by state name (roll, steer, roll_rate, vx, steer_rate).
TEST(SimulationLinear, SmallPerturbationFollowsMatrixExponential) {
  for (double v : {3.0, 5.0, 7.0}) {
    const LinearModel lin = linearizeAt(v);
    const SimulationOptions o = makeSmallRateKick(v, 1e-11);
    const SimulationResult r = runSimulation(getWhipple(), o);
    ASSERT_EQ(r.status, SimulationStatus::Completed) << r.message;
    ASSERT_EQ(r.rows.size(), 201u);

    const Eigen::VectorXd x0 = readInitialDeviation(r, lin);
    ASSERT_NEAR(x0[lin.findState("roll_rate")], 1e-4, 1e-15);
    ASSERT_NEAR(x0[lin.findState("steer_rate")], -2e-4, 1e-15);
    for (const std::string name : {"roll", "steer"}) {
      double maxRef = 0;
      const double maxErr = calcRelativeDeviationFromLinear(r, lin, x0, name, maxRef) * maxRef;
      std::cout << "v = " << v << " m/s, " << name << ": max |nonlinear - linear| / max |linear| = " << maxErr / maxRef
                << " (max |linear| " << maxRef << ")\n";
      EXPECT_LT(maxErr / maxRef, 1e-4) << "v = " << v << ", " << name;
    }
  }
}

std::complex<double> findWeave(const LinearModel& lin) {
  std::complex<double> best(0, 0);
  for (int k = 0; k < lin.eigenvalues.size(); ++k)
    if (lin.eigenvalues[k].imag() > 1e-3 && lin.eigenvalues[k].imag() > best.imag()) best = lin.eigenvalues[k];
  return best;
}

double dampingRatio(std::complex<double> l) { return -l.real() / std::abs(l); }

// (b) Weave frequency and damping ratio identified (response/) from simulated roll and steer rates after a
// small steer-rate kick, against the linear eigenvalue at 5 speeds.
TEST(SimulationLinear, IdentifiedWeaveMatchesLinearEigenvalue) {
  for (double v : {3.0, 4.0, 5.0, 6.0, 8.0}) {
    const std::complex<double> weave = findWeave(linearizeAt(v));
    ASSERT_GT(weave.imag(), 0) << "no oscillatory weave at " << v << " m/s";
    SimulationOptions o;
    o.speed = v;
    o.duration = 4;
    o.outputStep = 0.005;
    o.speedControl = SpeedControl::None;
    o.accuracy = 1e-10;
    o.perturbations = {parsePerturbation("steer-rate:1e-4")};
    const SimulationResult r = runSimulation(getWhipple(), o);
    ASSERT_EQ(r.status, SimulationStatus::Completed) << r.message;
    const auto id = cli::identifySimulatedModes(r, 0.0);
    const response::IdentifiedMode* found = nullptr;
    for (const auto& m : id.modes)
      if (m.imag > 0 && (!found || std::abs(std::complex<double>(m.real, m.imag) - weave) <
                                       std::abs(std::complex<double>(found->real, found->imag) - weave)))
        found = &m;
    ASSERT_NE(found, nullptr) << "no oscillatory mode identified at " << v << " m/s";
    const double fLin = weave.imag() / (2 * M_PI);
    std::cout << "v = " << v << " m/s: weave identified " << found->real << " +- " << found->imag << "i ("
              << found->frequencyHz << " Hz, zeta " << found->dampingRatio << "), linear " << weave.real() << " +- "
              << weave.imag() << "i (" << fLin << " Hz, zeta " << dampingRatio(weave) << "), order " << id.order
              << "\n";
    EXPECT_LT(std::abs(found->frequencyHz - fLin) / fLin, 0.005) << "v = " << v;
    EXPECT_LT(std::abs(found->dampingRatio - dampingRatio(weave)), 0.01) << "v = " << v;
  }
}

// (d, unstable) At 8 m/s the benchmark's capsize mode is unstable (Meijaard et al. 2007, Table 2:
// +0.14327879765713 1/s). After the weave has died out, the roll angle of a small perturbation grows at the
// rate of the linear capsize eigenvalue.
TEST(SimulationLinear, CapsizeGrowsAtTheUnstableEigenvalue) {
  const double v = 8;
  const LinearModel lin = linearizeAt(v);
  double capsize = -1;
  for (int k = 0; k < lin.eigenvalues.size(); ++k)
    if (std::abs(lin.eigenvalues[k].imag()) < 1e-9 && lin.eigenvalues[k].real() > 1e-3)
      capsize = lin.eigenvalues[k].real();
  ASSERT_NEAR(capsize, 0.14327879765713, 1e-6);  // published value, as a sanity check of the reference

  SimulationOptions o;
  o.speed = v;
  o.duration = 30;
  o.outputStep = 0.05;
  o.speedControl = SpeedControl::None;
  o.perturbations = {parsePerturbation("roll-rate:1e-4")};
  const SimulationResult r = runSimulation(getWhipple(), o);
  ASSERT_EQ(r.status, SimulationStatus::Completed) << r.message;
  // Least-squares slope of ln|roll| over 10..30 s.
  double sT = 0, sY = 0, sTT = 0, sTY = 0;
  int n = 0;
  for (size_t k = 0; k < r.rows.size(); ++k) {
    const double t = r.rows[k][0];
    if (t < 10) continue;
    const double y = std::log(std::abs(getDeviation(r, k, "roll")));
    sT += t, sY += y, sTT += t * t, sTY += t * y, ++n;
  }
  const double growth = (n * sTY - sT * sY) / (n * sTT - sT * sT);
  std::cout << "v = 8 m/s: simulated roll growth rate " << growth << " 1/s, linear capsize eigenvalue " << capsize
            << " 1/s, final roll " << getDeviation(r, r.rows.size() - 1, "roll") << " rad\n";
  EXPECT_NEAR(growth, capsize, 0.02 * capsize);
}

}  // namespace
}  // namespace motostab::simulation
