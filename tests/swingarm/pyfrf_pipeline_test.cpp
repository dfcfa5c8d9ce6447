// The hammer-test pipeline (YAML with the optional column keys) on the real pyFRF records
// (tests/data/measured-data/pyFRF-impact/ORIGIN.md: resonances near 900, 2640, 3669/3690, 4093-4164, 4392 Hz;
// coherence >= 0.998 at the peaks). One response channel: modes only, no modal axes.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "swingarm/identification/hammer_frf.h"
#include "temp_dir.h"

namespace {

using namespace motostab::identification;

TEST(PyFrfPipeline, FindsTheReferenceModesWithUncertainties) {
  const auto dir = makeTempDir("pyfrf");
  const std::string data = std::string(MOTOSTAB_TEST_DATA_DIR) + "/measured-data/pyFRF-impact/";
  std::ofstream(dir / "frf.yaml") << "test: frf\nframe: \"undocumented structure\"\nforce_point: {x: 0, z: 0}\n"
                                  << "channels:\n  - {name: R, x: 0, z: 0, column: response}\nhits: ["
                                  << data << "impact_1.csv, " << data << "impact_2.csv, " << data << "impact_3.csv, "
                                  << data << "impact_4.csv, " << data << "impact_5.csv]\n"
                                  << "time_column: t_s\nforce_column: force\n"
                                  << "processing:\n  band_hz: [500, 5000]\n  model_order: [20, 60]\n";
  const FrfTest t = readFrfTest(dir / "frf.yaml");
  const FrfResult r = identifyFrf(t, readHits(t));
  EXPECT_TRUE(r.rejectedHits.empty());
  EXPECT_EQ(r.frf.averages, 5);
  auto findNear = [&](double f, double tol) -> const ModeResult* {
    for (const auto& m : r.modes)
      if (std::abs(m.frequencyHz - f) < tol) return &m;
    return nullptr;
  };
  for (double target : {900.0, 2640.0, 3669.0, 3690.0, 4392.0}) {
    const ModeResult* m = findNear(target, 8);
    ASSERT_NE(m, nullptr) << target;
    EXPECT_FALSE(m->hasAxis);
    EXPECT_GT(m->dampingRatio, 0.0);
    EXPECT_LT(m->dampingRatio, 0.005);
    EXPECT_GT(m->dampingStderr, 0.0);
    EXPECT_LT(m->dampingStderr, m->dampingRatio);
    EXPECT_LT(m->frequencyStderrHz, 1.0);
    EXPECT_DOUBLE_EQ(m->lossFactor, 2 * m->dampingRatio);
    const size_t bin = static_cast<size_t>(std::lround(m->frequencyHz / r.frf.df));
    double best = 0;  // coherence at the peak bin (or its neighbour: the peak sits between bins)
    for (size_t k = bin - 1; k <= bin + 1; ++k) best = std::max(best, r.frf.coherence[0][k]);
    EXPECT_GT(best, 0.99) << target;
  }
  EXPECT_NE(findNear(3669, 8), findNear(3690, 8));
  EXPECT_TRUE(findNear(4093, 10) || findNear(4128, 10) || findNear(4164, 10));
  writeFrfOutputs(t, r, dir / "out");
  for (const char* f : {"frf.csv", "modes.csv", "frf.json", "frf_magnitude_phase.png", "coherence.png", "stabilisation.png"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "modal_axes.png"));
}

}  // namespace
