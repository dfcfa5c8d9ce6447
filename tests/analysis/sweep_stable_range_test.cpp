// calcStableSpeedRanges on sweeps drawn here: a weave pair that stabilises at a and a capsize mode that
// destabilises at b (both straight lines in speed), so the stable range is [a, b] whenever a grid
// speed lies inside it (Meijaard et al. 2007, sec. 6: the benchmark bicycle is stable between its
// weave and capsize speeds), clipped to the sweep's ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <complex>

#include "analysis/sweep.h"
#include "core/portable_random.h"

namespace motostab::analysis {

using core::PortableRandom;
namespace {

using cd = std::complex<double>;

struct DrawnSweep {
  SweepResult sweep;
  double a = 0, b = 0;  // weave and capsize crossings, m/s
};

DrawnSweep drawSweep(PortableRandom& rng, bool unstableOther) {
  DrawnSweep d;
  const int n = 5 + static_cast<int>(rng.drawIndex(30));
  const double start = rng.drawUniform(0, 2), step = rng.drawUniform(0.05, 0.5);
  for (int k = 0; k < n; ++k) d.sweep.speeds.push_back(start + k * step);
  const double stop = d.sweep.speeds.back();
  d.a = rng.drawUniform(start - 2 * step, stop);
  d.b = rng.drawUniform(d.a, stop + 2 * step);
  const double s1 = rng.drawUniform(0.2, 3), s2 = rng.drawUniform(0.05, 1), w = rng.drawUniform(1, 6);
  auto branch = [&](ModeLabel l) { return ModeBranch{l, std::vector<ModeLabel>(n, l), {}, {}}; };
  ModeBranch weave1 = branch(ModeLabel::Weave), weave2 = branch(ModeLabel::Weave), capsize = branch(ModeLabel::Capsize),
             castor = branch(ModeLabel::Castor), neutral = branch(ModeLabel::Neutral), other = branch(ModeLabel::Other);
  for (double v : d.sweep.speeds) {
    weave1.eigenvalue.push_back(cd(s1 * (d.a - v), w + v));
    weave2.eigenvalue.push_back(cd(s1 * (d.a - v), -w - v));
    capsize.eigenvalue.push_back(cd(s2 * (v - d.b), 0));
    castor.eigenvalue.push_back(cd(-3 - 2 * v, 0));
    neutral.eigenvalue.push_back(cd(rng.drawUniform(-1e-12, 1e-12), 0));  // either sign: never counts
    other.eigenvalue.push_back(cd(unstableOther ? 0.5 : -50, 0));
  }
  d.sweep.branches = {castor, weave1, neutral, capsize, weave2, other};
  if (d.a > start && d.a < stop) d.sweep.criticalSpeeds.push_back({ModeLabel::Weave, d.a, true});
  if (d.b > start && d.b < stop) d.sweep.criticalSpeeds.push_back({ModeLabel::Capsize, d.b, false});
  return d;
}

TEST(SweepStableRange, BoundedByTheCriticalSpeedsAndTheSweepEnds) {
  PortableRandom rng(4292);
  int found = 0, none = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const DrawnSweep d = drawSweep(rng, false);
    const auto& v = d.sweep.speeds;
    const bool gridSpeedInside = std::any_of(v.begin(), v.end(), [&](double s) { return s > d.a && s < d.b; });
    const auto ranges = calcStableSpeedRanges(d.sweep);
    if (!gridSpeedInside) {
      EXPECT_TRUE(ranges.empty()) << "trial " << trial;
      ++none;
      continue;
    }
    ++found;
    ASSERT_EQ(ranges.size(), 1u) << "trial " << trial;
    EXPECT_EQ(ranges[0].start, std::max(d.a, v.front())) << "trial " << trial;
    EXPECT_EQ(ranges[0].stop, std::min(d.b, v.back())) << "trial " << trial;
  }
  EXPECT_GT(found, 50);
  EXPECT_GT(none, 5);
}

TEST(SweepStableRange, WithoutCriticalSpeedsTheGridSpeedsBoundIt) {
  PortableRandom rng(6024);
  for (int trial = 0; trial < 100; ++trial) {
    DrawnSweep d = drawSweep(rng, false);
    d.sweep.criticalSpeeds.clear();  // e.g. a sweep run with findCriticalSpeeds = false
    std::vector<double> inside;
    for (double s : d.sweep.speeds)
      if (s > d.a && s < d.b) inside.push_back(s);
    const auto ranges = calcStableSpeedRanges(d.sweep);
    if (inside.empty()) {
      EXPECT_TRUE(ranges.empty());
      continue;
    }
    ASSERT_EQ(ranges.size(), 1u);
    EXPECT_EQ(ranges[0].start, inside.front());
    EXPECT_EQ(ranges[0].stop, inside.back());
  }
}

TEST(SweepStableRange, AnUnstableUnlabelledModeLeavesNoStableRange) {
  PortableRandom rng(1955);
  for (int trial = 0; trial < 20; ++trial) EXPECT_TRUE(calcStableSpeedRanges(drawSweep(rng, true).sweep).empty());
}

}  // namespace
}  // namespace motostab::analysis
