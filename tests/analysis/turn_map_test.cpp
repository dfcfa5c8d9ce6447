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
// each labelled upright one (weave, capsize, castor) carries the same label. Scrambled labels away from
// upright are restored.
TEST(TurnMap, LabelsFollowTheModesAcrossRoll) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/whipple-benchmark.yaml"));
  TurnMapOptions opt;
  opt.sweep.start = 3, opt.sweep.stop = 7, opt.sweep.step = 0.5;
  opt.rolls = {0.0, 2 * M_PI / 180, 4 * M_PI / 180};
  TurnMapResult map = runTurnMap(model, opt);
  ASSERT_EQ(map.sweeps.size(), 3u);
  // The label of the branch of `s` nearest to `near` at speed k.
  auto findNearestLabel = [](const SweepResult& s, std::complex<double> near, size_t k) {
    double best = INFINITY;
    std::string label;
    for (const auto& b : s.branches)
      if (std::abs(b.eigenvalue[k] - near) < best) best = std::abs(b.eigenvalue[k] - near), label = b.label;
    return label;
  };
  std::vector<std::vector<std::string>> labels;
  for (const auto& s : map.sweeps) {
    labels.emplace_back();
    for (const auto& b : s.branches) labels.back().push_back(b.label);
  }
  for (const auto& b : map.sweeps[0].branches) {
    if (b.label != "weave" && b.label != "capsize" && b.label != "castor") continue;
    for (size_t j = 1; j < 3; ++j)
      for (size_t k = 0; k < b.eigenvalue.size(); ++k) {
        if (std::abs(b.eigenvalue[k]) < 0.1) continue;  // too near the neutral (zero) forward-speed mode to tell
        EXPECT_EQ(findNearestLabel(map.sweeps[j], b.eigenvalue[k], k), b.label) << "roll " << j << " speed " << k;
      }
  }
  for (size_t j = 1; j < 3; ++j)
    for (auto& b : map.sweeps[j].branches) b.label = "other";
  trackModesAcrossRoll(map);
  for (size_t j = 0; j < 3; ++j)
    for (size_t i = 0; i < map.sweeps[j].branches.size(); ++i) EXPECT_EQ(map.sweeps[j].branches[i].label, labels[j][i]);
}

}  // namespace
}  // namespace motostab::analysis
