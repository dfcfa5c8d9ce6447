// Mass properties (seed section 2.4): tilting rig and trifilar pendulum against known truth.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "io/input_error.h"
#include "output/virtual_rig_output.h"
#include "swingarm/identification/mass_properties.h"
#include "swingarm/identification/virtual_rig.h"
#include "tests/support/temp_dir.h"

namespace {

using motostab::output::writeCogTestFiles;
using motostab::output::writeInertiaTestFiles;

using namespace motostab::swingarm::identification;

TEST(Cog, NoiseFreeTiltingRigGivesTheTruth) {
  const VirtualPart part;  // seed Table 1, swingarm 1: 6.96 kg, CoG (0.299, 0, 0.027) m
  const auto dir = makeTempDir("cog_exact");
  writeCogTestFiles(dir, simulateCogReadings(part, {0.05, 0.0, 0.04}, 0.0, 1));
  const CogResult r = identifyCog(readCogTest(dir / "cog.yaml"));
  EXPECT_NEAR(r.mass, part.mass, 1e-5);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.cog[i], part.cog[i], 1e-5) << i;
}

// 30 noisy repetitions (0.05 N cell noise; the part weighs 68 N): errors small, and consistent with the
// stated standard errors (RMS z-score near 1).
TEST(Cog, NoisyTiltingRigWithinStatedUncertainty) {
  const VirtualPart part;
  const int n = 30;
  double zx = 0, zz = 0, worstX = 0, worstZ = 0, worstM = 0;
  const auto dir = makeTempDir("cog_noisy");
  for (int seed = 0; seed < n; ++seed) {
    writeCogTestFiles(dir, simulateCogReadings(part, {0.05, 0.0, 0.04}, 0.05, 500 + seed));
    const CogResult r = identifyCog(readCogTest(dir / "cog.yaml"));
    worstM = std::max(worstM, std::abs(r.mass - part.mass));
    worstX = std::max(worstX, std::abs(r.cog[0] - part.cog[0]));
    worstZ = std::max(worstZ, std::abs(r.cog[2] - part.cog[2]));
    zx += std::pow((r.cog[0] - part.cog[0]) / r.cogStderr[0], 2) / n;
    zz += std::pow((r.cog[2] - part.cog[2]) / r.cogStderr[2], 2) / n;
  }
  EXPECT_LT(worstM, 0.03);   // kg
  EXPECT_LT(worstX, 2.5e-3);  // m
  EXPECT_LT(worstZ, 7e-3);    // m (z comes from the tilt: 0..30 deg only)
  for (double z : {zx, zz}) {
    EXPECT_GT(std::sqrt(z), 0.6);
    EXPECT_LT(std::sqrt(z), 1.6);
  }
}

TEST(Inertia, TrifilarFormulaMatchesUniformDisc) {
  // A uniform disc (I = m r^2/2) hung at its rim radius r swings with T = 2 pi sqrt(L / (2 g)).
  const double m = 3.0, r = 0.3, L = 1.2, g = 9.81;
  const double period = 2 * M_PI * std::sqrt(L / (2 * g));
  EXPECT_NEAR(calcTrifilarInertia(m, g, r, L, period), m * r * r / 2, 1e-12);
}

TEST(Inertia, SixSetUpsGiveTheTensorAboutTheCog) {
  VirtualPart part;
  part.inertia(0, 2) = part.inertia(2, 0) = 0.02;  // a product of inertia too
  for (const double noise : {0.0, 1e-3}) {
    const auto dir = makeTempDir("inertia" + std::to_string(noise > 0));
    writeInertiaTestFiles(dir, simulateTrifilarTest(part, noise, 9));
    const InertiaResult r = identifyInertia(readInertiaTest(dir / "inertia.yaml"));
    EXPECT_TRUE(r.fullTensor);
    const double tol = noise > 0 ? 0.01 : 1e-5;  // kg m^2
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.tensor(i, j), part.inertia(i, j), tol) << i << j;
    if (noise > 0)
      for (int i = 0; i < 3; ++i) {
        EXPECT_GT(r.tensorStderr(i, i), 0.0);
        EXPECT_LT(std::abs(r.tensor(i, i) - part.inertia(i, i)), 4 * r.tensorStderr(i, i));
      }
  }
}

TEST(MassPropertiesInput, BadTiltAngleAndCollinearCellsAreInputErrors) {
  const auto dir = makeTempDir("cog_bad");
  writeCogTestFiles(dir, simulateCogReadings(VirtualPart(), {0.05, 0.0, 0.04}, 0.0, 1));
  {
    std::ofstream(dir / "bad.csv") << "tilt_deg,N1_N,N2_N,N3_N,N4_N\n0,1,1,1,1\n75,1,1,1,1\n";
    std::ofstream(dir / "bad.yaml") << "test: cog\nload_cells:\n  - {name: N1, x: -0.3, y: -0.2}\n"
                                       "  - {name: N2, x: 0.3, y: -0.2}\n  - {name: N3, x: 0.3, y: 0.2}\n"
                                       "  - {name: N4, x: -0.3, y: 0.2}\nreadings: bad.csv\n";
    try {
      readCogTest(dir / "bad.yaml");
      FAIL() << "no error";
    } catch (const motostab::io::InputError& e) {
      EXPECT_EQ(e.getLocation().line, 3);
      EXPECT_EQ(e.getLocation().key, "tilt_deg");
    }
  }
  std::ofstream(dir / "line.yaml") << "test: cog\nload_cells:\n  - {name: N1, x: 0, y: 0}\n  - {name: N2, x: 0.1, y: 0}\n"
                                      "  - {name: N3, x: 0.2, y: 0}\nreadings: cog.csv\n";
  EXPECT_THROW(readCogTest(dir / "line.yaml"), motostab::io::InputError);
}

}  // namespace
