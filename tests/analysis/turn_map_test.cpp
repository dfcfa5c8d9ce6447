// Stability maps over speed x roll (analysis/turn_map.h): mode labels follow the modes across roll.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/turn_map.h"
#include "scenario/scenario.h"

namespace motostab::analysis {

using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

// Nearby roll angles have nearby eigenvalues: at 2 and 4 deg, at every speed, the eigenvalue nearest to
// each labelled upright one (weave, capsize, castor) carries the same label (labels come from each
// point's own modes, so they follow the modes across roll without being carried over).
TEST(TurnMap, LabelsFollowTheModesAcrossRoll) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml"));
  TurnMapOptions opt;
  opt.sweep.start = 3, opt.sweep.stop = 7, opt.sweep.step = 0.5;
  opt.rolls = {0.0, 2 * M_PI / 180, 4 * M_PI / 180};
  const TurnMapResult map = runTurnMap(model, opt);
  ASSERT_EQ(map.sweeps.size(), 3u);
  EXPECT_EQ(map.countFailedPoints(), 0u);
  // The label at speed k of the branch of `s` nearest to `near`.
  auto findNearestLabel = [](const SweepResult& s, std::complex<double> near, size_t k) {
    double best = INFINITY;
    ModeLabel label = ModeLabel::Other;
    for (const auto& b : s.branches)
      if (std::abs(b.eigenvalue[k] - near) < best) best = std::abs(b.eigenvalue[k] - near), label = b.labels[k];
    return label;
  };
  int checked = 0;
  for (const auto& b : map.sweeps[0].branches)
    for (size_t k = 0; k < b.eigenvalue.size(); ++k) {
      const ModeLabel l = b.labels[k];
      if (l != ModeLabel::Weave && l != ModeLabel::Capsize && l != ModeLabel::Castor) continue;
      if (std::abs(b.eigenvalue[k]) < 0.1) continue;  // too near the neutral (zero) forward-speed mode to tell
      for (size_t j = 1; j < 3; ++j, ++checked)
        EXPECT_EQ(findNearestLabel(map.sweeps[j], b.eigenvalue[k], k), l) << "roll " << j << " speed " << k;
    }
  EXPECT_GT(checked, 40);
}

}  // namespace
}  // namespace motostab::analysis
