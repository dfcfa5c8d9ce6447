// False causes with every default candidate (a long test, ctest label "long"): noise-only eigenvalue
// rows (hidden_effect.h, nothing hidden, 1 % + 0.01 1/s noise) on two bicycles and the enduro, 20 seeds
// each; at most 1 false cause in 20 per vehicle. The Browser bicycle with rider Jason adds rider_lean
// and the enduro its swingarm variants to the candidate list; the data give a steer-rate amplitude, so
// steer_friction is among the candidates.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <ctime>

#include "run_hidden.h"

namespace motostab::diagnosis {
namespace {

const std::string kDir = MOTOSTAB_SOURCE_DIR;

int countFalseCauses(const std::string& scenario, double start, double stop, double step, std::vector<std::string> modes,
                     uint64_t seed0) {
  int named = 0;
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    testing::HiddenEffect h;
    h.scenario = scenario;
    h.seed = seed0 + seed;
    h.modes = modes;
    h.start = start, h.stop = stop, h.step = step;
    h.steerRateAmplitude = 0.5;  // rad/s: steer_friction is offered too (beside steer_damper where the scenario has none)
    const auto t0 = std::chrono::steady_clock::now();
    // One thread: the test runs beside other work; every default candidate, up to 2 causes (so that the
    // pair search runs when no single qualifies); no CV of candidates failing a cheaper criterion (the
    // report's table only: the causes are the same).
    const DiagnosisResult r = testing::runHidden(h, "wide-null-" + std::to_string(seed0 + seed), true, {}, "", 2, 0.002, 1, false);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s seed %d: %zu candidates, %s, %.1f s\n", scenario.c_str(), static_cast<int>(seed), r.candidates.size(),
                r.causes.empty() ? "no cause" : r.causes[0].fit.name.c_str(), s);
    std::fflush(stdout);
    named += !r.causes.empty();
  }
  std::printf("%s: %d false causes in 20; wall %.0f s, CPU %.0f s\n", scenario.c_str(), named,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count(),
              static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC);
  return named;
}

TEST(WideNull, BenchmarkBicycle) {
  EXPECT_LE(countFalseCauses(kDir + "/scenarios/whipple-benchmark.yaml", 2, 8, 0.5, {"weave", "capsize"}, 11000), 1);
}

TEST(WideNull, BrowserWithRider) {
  EXPECT_LE(countFalseCauses(kDir + "/scenarios/browser-jason-rider.yaml", 3, 8, 0.5, {"weave", "capsize"}, 12000), 1);
}

TEST(WideNull, Enduro) {
  EXPECT_LE(countFalseCauses(kDir + "/scenarios/enduro.yaml", 10, 40, 3, {"weave", "wobble"}, 13000), 1);
}

}  // namespace
}  // namespace motostab::diagnosis
