// The hammer-test command on the real pyFRF records with default settings (no processing section: band
// and model orders from the data). Reference: tests/data/measured-data/pyFRF-impact/ORIGIN.md
// (resonances near 900, 2640, 3669/3690, 4093-4164, 4392 Hz; coherence >= 0.998 at the peaks).
// One response channel: modes only, no modal axes.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/apps/cli_support.h"
#include "tests/support/temp_dir.h"

namespace {

TEST(PyFrfPipeline, DefaultsFindTheReferenceModesThroughTheCommandLine) {
  const auto dir = makeTempDir("pyfrf");
  const std::string data = std::string(MOTOSTAB_TEST_DATA_DIR) + "/measured-data/pyFRF-impact/";
  std::ofstream(dir / "frf.yaml") << "test: frf\nframe: \"undocumented structure\"\nforce_point: {x: 0, z: 0}\n"
                                  << "channels:\n  - {name: R, x: 0, z: 0, column: response}\nhits: ["
                                  << data << "impact_1.csv, " << data << "impact_2.csv, " << data << "impact_3.csv, "
                                  << data << "impact_4.csv, " << data << "impact_5.csv]\n"
                                  << "time_column: t_s\nforce_column: force\n";
  std::string output;
  const int code = motostab::test::runMotostab({"identify", "frf", (dir / "frf.yaml").string(), "--out", (dir / "out").string()},
                                               dir.string(), output);
  ASSERT_EQ(code, 0) << output;
  EXPECT_NE(output.find("5 hits averaged, 0 rejected"), std::string::npos) << output;
  nlohmann::json j;
  std::ifstream(dir / "out" / "frf.json") >> j;
  EXPECT_TRUE(j["band"]["automatic"].get<bool>());
  auto findNear = [&](double f, double tol) -> const nlohmann::json* {
    for (const auto& m : j["modes"])
      if (std::abs(m["frequency_hz"].get<double>() - f) < tol) return &m;
    return nullptr;
  };
  for (double target : {900.0, 2640.0, 3669.0, 3690.0, 4093.0, 4128.0, 4164.0, 4392.0}) {
    const nlohmann::json* m = findNear(target, 8);
    ASSERT_NE(m, nullptr) << target << "\n" << output;
    const double zeta = (*m)["damping_ratio"].get<double>(), zetaErr = (*m)["damping_ratio_stderr"].get<double>();
    EXPECT_FALSE(m->contains("modal_axis"));
    EXPECT_GT(zeta, 0.0);
    EXPECT_LT(zeta, 0.005);  // ORIGIN.md: half-power 0.0002-0.0015, resolution-limited
    EXPECT_GT(zetaErr, 0.0);
    EXPECT_LT(zetaErr, zeta);
    EXPECT_LT((*m)["frequency_hz_stderr"].get<double>(), 1.0);
    EXPECT_GT((*m)["coherence_at_resonance"].get<double>(), 0.99) << target;
    EXPECT_DOUBLE_EQ((*m)["loss_factor"].get<double>(), 2 * zeta);
  }
  EXPECT_NE(findNear(3669, 8), findNear(3690, 8));  // the close pair is two modes
  int group = 0;                                     // the 4093-4164 group: as many as are stable
  for (double f : {4093.0, 4128.0, 4164.0}) group += findNear(f, 6) != nullptr;
  EXPECT_EQ(group, 3) << output;
  for (const char* f : {"frf.csv", "modes.csv", "frf.json", "frf_magnitude_phase.png", "coherence.png", "stabilisation.png"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "modal_axes.png"));
  std::printf("%s", output.c_str());
}

}  // namespace
