// when the hammer test yields no mode, or only one of bending and torsion, the
// command says so (exit 3) with what was tried, what to set and, for a missing mode, which one, why and
// where to hit; `--verbose` prints the stabilisation summary.
#include <gtest/gtest.h>

#include <cstdint>

#include "core/portable_random.h"
#include "output/virtual_rig_output.h"
#include "tests/apps/cli_support.h"
#include "swingarm/identification/frf_diagnosis.h"
#include "swingarm/identification/virtual_rig.h"
#include "tests/support/temp_dir.h"

namespace {

using motostab::output::writeFrfTestFiles;
using motostab::output::writeStaticTestFiles;

using namespace motostab::swingarm::identification;

std::vector<double> getLoads() {
  std::vector<double> loads;
  for (int i = 0; i <= 32; ++i) loads.push_back(250.0 * (i <= 16 ? i : 32 - i));
  return loads;
}

TEST(NeverSilent, NoModeIsExit3WithWhatWasTriedAndWhatToSet) {
  const auto dir = makeTempDir("no_mode");
  const VirtualSwingarm rig;
  auto hits = simulateHammerHits(rig, {}, RigNoise(), 3);
  motostab::core::PortableRandom rng(99);
  for (auto& h : hits)
    for (auto& ch : h.responses)
      for (auto& v : ch) v = rng.drawUniform(-1.0, 1.0);  // the accelerometers saw nothing but noise
  writeFrfTestFiles(dir, rig, hits);
  std::string output;
  const int code = motostab::test::runMotostab(
      {"identify", "frf", (dir / "frf.yaml").string(), "--out", (dir / "out").string(), "--verbose"}, dir.string(), output);
  EXPECT_EQ(code, 3) << output;
  for (const char* s : {"no mode identified", "Tried:", "band", "model orders", "indicator peaks", "What to set",
                        "band_hz", "model_order", "stabilisation (band"})
    EXPECT_NE(output.find(s), std::string::npos) << s << "\n" << output;
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "frf.csv"));  // the evidence is written for inspection
}

// A hit (almost) on the torsion axis: the torsion mode is not excited. The diagnosis names it, says why
// and suggests moving the hit along z; `identify swingarm` exits 3 with it.
TEST(NeverSilent, MissingTorsionSaysWhichWhyAndWhereToHit) {
  const auto dir = makeTempDir("no_torsion");
  VirtualSwingarm rig;
  rig.armT = 1e-5;  // m: the torsion lever of the hit
  const RigNoise noise;
  writeStaticTestFiles(dir, rig, simulateStaticReadings(rig, getLoads(), noise, 4), noise.laserResolution);
  writeFrfTestFiles(dir, rig, simulateHammerHits(rig, {}, noise, 5));
  const FrfTest t = readFrfTest(dir / "frf.yaml");
  const FrfResult r = identifyFrf(t, readHits(t));
  ASSERT_GE(r.bendingIndex, 0);
  EXPECT_NEAR(r.modes[r.bendingIndex].frequencyHz, rig.fB, 0.005 * rig.fB);
  EXPECT_LT(r.torsionIndex, 0);
  std::string all;
  for (const auto& d : r.diagnostics) all += d + "\n";
  for (const char* s : {"torsion mode not found", "too close to the torsion axis", "move along z", "near channel A3"})
    EXPECT_NE(all.find(s), std::string::npos) << s << "\n" << all;  // A3 at z = -0.05: the farthest from the hit in z
  std::string output;
  const int code = motostab::test::runMotostab({"identify", "swingarm", (dir / "static.yaml").string(),
                                                (dir / "frf.yaml").string(), "--out", (dir / "out").string()},
                                               dir.string(), output);
  EXPECT_EQ(code, 3) << output;
  EXPECT_NE(output.find("torsion mode not found"), std::string::npos) << output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "swingarm.yaml"));
}

TEST(NeverSilent, MissingBendingSaysWhichAndWhereToHit) {
  const auto dir = makeTempDir("no_bending");
  VirtualSwingarm rig;
  rig.armB = 1e-5;
  rig.armT = 0.2;
  writeFrfTestFiles(dir, rig, simulateHammerHits(rig, {}, RigNoise(), 6));
  const FrfTest t = readFrfTest(dir / "frf.yaml");
  const FrfResult r = identifyFrf(t, readHits(t));
  ASSERT_GE(r.torsionIndex, 0);
  EXPECT_LT(r.bendingIndex, 0);
  std::string all;
  for (const auto& d : r.diagnostics) all += d + "\n";
  for (const char* s : {"bending mode not found", "move along x"})
    EXPECT_NE(all.find(s), std::string::npos) << s << "\n" << all;
}

}  // namespace
