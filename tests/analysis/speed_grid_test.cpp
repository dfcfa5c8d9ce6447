// makeSpeedGrid: the grid's points against start + i * step computed here, with start, stop and step
// drawn; degenerate and oversized ranges throw instead of overflowing or exhausting memory.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/sweep.h"
#include "core/portable_random.h"

namespace motostab::analysis {
namespace {

TEST(SpeedGrid, PointsAndEndpointForDrawnRanges) {
  core::PortableRandom rng(20261125);
  for (int trial = 0; trial < 50; ++trial) {
    const double start = rng.drawUniform(0, 5), step = rng.drawUniform(0.05, 1.0);
    const int steps = 1 + static_cast<int>(rng.drawIndex(60));
    // stop on the grid (up to rounding), and stop half a step past the last point
    for (const double stop : {start + steps * step, start + (steps + 0.5) * step}) {
      const std::vector<double> v = makeSpeedGrid(start, stop, step);
      ASSERT_EQ(v.size(), static_cast<size_t>(steps + 1)) << start << ":" << stop << ":" << step;
      for (int i = 0; i <= steps; ++i) EXPECT_DOUBLE_EQ(v[i], start + i * step);
      EXPECT_LE(v.back(), stop + 1e-9 * step);
    }
  }
}

TEST(SpeedGrid, RejectsDegenerateAndOversizedRanges) {
  EXPECT_THROW(makeSpeedGrid(0, 1e300, 1e-300), std::logic_error);
  EXPECT_THROW(makeSpeedGrid(0, 1e9, 1e-3), std::logic_error);
  EXPECT_THROW(makeSpeedGrid(5, 4, 0.1), std::logic_error);
  EXPECT_THROW(makeSpeedGrid(0, 1, 0), std::logic_error);
  EXPECT_THROW(makeSpeedGrid(0, 1, std::nan("")), std::logic_error);
  EXPECT_EQ(makeSpeedGrid(3, 3, 0.1).size(), 1u);
  // At most 10000 speeds, counted as speeds (0:1e6:1 held 1e6 steps, 1e6 + 1 speeds, and was accepted),
  // each at most 150 m/s; counts drawn around the bound.
  core::PortableRandom rng(10000);
  for (int trial = 0; trial < 20; ++trial) {
    const long n = 9990 + static_cast<long>(rng.drawIndex(20));
    const double start = rng.drawUniform(0, 50), step = rng.drawUniform(1e-3, 9e-3);
    const double stop = start + (n - 1) * step;
    if (n <= 10000) EXPECT_EQ(makeSpeedGrid(start, stop, step).size(), static_cast<size_t>(n));
    else EXPECT_THROW(makeSpeedGrid(start, stop, step), std::logic_error) << n;
  }
  EXPECT_EQ(makeSpeedGrid(140, 150, 1).size(), 11u);
  EXPECT_THROW(makeSpeedGrid(140, 150.01, 1), std::logic_error);
  EXPECT_THROW(makeSpeedGrid(1e11, 1e11, 1), std::logic_error);
}

}  // namespace
}  // namespace motostab::analysis
