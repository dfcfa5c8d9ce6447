// The standard machine of R. S. Sharp (1971), "The stability and control of motorcycles", J. Mech.
// Eng. Sci. 13(5):316-329, built from its Appendix 3 parameters (scenarios/sharp1971.yaml,
// docs/motorcycle-parameters.md), against the eigenvalues of his Tables 1-3 (model 1, the full tyre
// treatment) at his eight speeds, 10-160 ft/s: the capsize root, the weave and the wobble pair, each
// as printed (1/s and rad/s). Sharp names each root, so the table also checks the labels: the root
// nearest each printed one must carry Sharp's name.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/sweep.h"
#include "scenario/scenario.h"

namespace motostab::analysis {

using scenario::loadScenario;
using vehicle::VehicleModel;

namespace {

struct SharpRow {
  double speedFtPerS;
  double capsize;
  std::complex<double> weave, wobble;
};

// Sharp (1971), Tables 1-3, model 1 (standard machine): capsize real part; weave and wobble real
// part and frequency (rad/s).
const SharpRow kTables[] = {
    {10, -3.56, {2.01, 1.63}, {-5.20, 55.7}},    {20, -2.83, {-0.18, 2.09}, {-5.91, 55.8}},
    {30, -0.13, {-3.36, 4.56}, {-6.42, 55.5}},   {50, 0.08, {-6.59, 11.4}, {-6.52, 54.6}},
    {70, 0.08, {-3.97, 16.8}, {-5.70, 54.0}},    {100, 0.07, {-1.82, 19.2}, {-3.94, 54.3}},
    {130, 0.05, {-1.13, 20.4}, {-2.24, 55.6}},   {160, 0.04, {-0.96, 21.2}, {-0.82, 57.5}},
};

// The eigenvalue of `lin` nearest `target` (1/s), and its index.
int findNearest(const LinearModel& lin, std::complex<double> target) {
  int best = 0;
  for (int k = 1; k < lin.eigenvalues.size(); ++k)
    if (std::abs(lin.eigenvalues[k] - target) < std::abs(lin.eigenvalues[best] - target)) best = k;
  return best;
}

// Each printed value to 0.02 (1/s or rad/s; 0.1, one unit of the last digit, for the frequencies printed to
// three figures: the wobble at 130 ft/s is 55.549 against 55.6): within two units of the last printed digit. The differences left (capsize at 20-30 ft/s by 0.015,
// the slow weave by 0.02) are those of a linearisation of the full multibody model against Sharp's
// hand-derived, linearised equations (docs/motorcycle-parameters.md). The labels must be Sharp's.
TEST(Sharp1971, EigenvaluesAndLabelsMatchTables1To3) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/sharp1971.yaml"));
  double worst = 0;
  for (const SharpRow& row : kTables) {
    const double v = row.speedFtPerS * 0.3048;
    const LinearModel lin = linearize(model, calcTrim(model, v));
    struct Expected {
      std::complex<double> value;
      ModeLabel label;
      double tolerance;
    };
    const Expected expected[] = {{{row.capsize, 0}, ModeLabel::Capsize, 0.02},
                                 {row.weave, ModeLabel::Weave, row.weave.imag() < 10 ? 0.02 : 0.1},
                                 {row.wobble, ModeLabel::Wobble, 0.1}};
    for (const Expected& e : expected) {
      const int k = findNearest(lin, e.value);
      const std::complex<double> l = lin.eigenvalues[k];
      EXPECT_NEAR(l.real(), e.value.real(), 0.02) << toString(e.label) << " at " << row.speedFtPerS << " ft/s: " << l;
      EXPECT_NEAR(l.imag(), e.value.imag(), e.tolerance) << toString(e.label) << " at " << row.speedFtPerS << " ft/s: " << l;
      EXPECT_EQ(lin.labels[k], e.label) << "at " << row.speedFtPerS << " ft/s: " << l << " is " << toString(lin.labels[k]);
      worst = std::max(worst, std::abs(l.real() - e.value.real()));
    }
  }
  std::cout << "Sharp (1971) Tables 1-3: largest real-part difference " << worst << " 1/s\n";
}

// Sharp's capsize is a slow divergence above about 35 ft/s (his text): the sweep finds its critical
// speed between 30 and 50 ft/s, names it capsize, and every stable range ends at a critical speed.
TEST(Sharp1971, CapsizeCriticalSpeedIsNamed) {
  const VehicleModel model(loadScenario(std::string(MOTOSTAB_SOURCE_DIR) + "/scenarios/sharp1971.yaml"));
  SweepOptions opt;
  opt.start = 2, opt.stop = 50, opt.step = 2;
  const SweepResult s = runSweep(model, opt);
  int capsize = 0;
  for (const CriticalSpeed& c : s.criticalSpeeds)
    if (c.mode == ModeLabel::Capsize) {
      ++capsize;
      EXPECT_GT(c.speed, 30 * 0.3048);
      EXPECT_LT(c.speed, 50 * 0.3048);
      EXPECT_FALSE(c.stabilising);
    }
  EXPECT_EQ(capsize, 1);
  for (const StableRange& r : calcStableSpeedRanges(s))
    for (double end : {r.start, r.stop}) {
      if (end == s.speeds.front() || end == s.speeds.back()) continue;
      EXPECT_TRUE(std::any_of(s.criticalSpeeds.begin(), s.criticalSpeeds.end(),
                              [&](const CriticalSpeed& c) { return c.speed == end; }))
          << "stable range end " << end << " m/s is no critical speed";
    }
}

}  // namespace
}  // namespace motostab::analysis
