// PortableRandom (core/portable_random.h): the engine against the value the C++ standard fixes, and the
// uniform and normal transforms against their moments.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "core/portable_random.h"

namespace motostab::core {
namespace {

// C++17 [rand.predef]: the 10000th consecutive output of a default-constructed mt19937_64 (seed 5489)
// is 9981545732273789042; its uniform is the top 53 bits times 2^-53.
TEST(PortableRandom, EngineIsTheStandardMersenneTwister) {
  PortableRandom rng(5489);
  for (int i = 1; i < 10000; ++i) rng.drawUniform();
  EXPECT_EQ(rng.drawUniform(), static_cast<double>(9981545732273789042ULL >> 11) / 9007199254740992.0);
}

TEST(PortableRandom, SameSeedSameDrawsOtherSeedOtherDraws) {
  PortableRandom a(42), b(42), c(43);
  int differ = 0;
  for (int i = 0; i < 100; ++i) {
    const double x = a.drawNormal(), y = b.drawNormal(), z = c.drawNormal();
    EXPECT_EQ(x, y);
    differ += x != z;
  }
  EXPECT_EQ(differ, 100);
}

// Moments of n draws: mean within 5 standard errors, variance and the share inside one sigma likewise.
TEST(PortableRandom, UniformAndNormalMoments) {
  const int n = 200000;
  for (std::uint64_t seed : {1u, 977u, 123456789u}) {
    PortableRandom rng(seed);
    double su = 0, su2 = 0, sn = 0, sn2 = 0, sn4 = 0;
    int inside = 0;
    for (int i = 0; i < n; ++i) {
      const double u = rng.drawUniform(-2.0, 3.0);
      ASSERT_GE(u, -2.0);
      ASSERT_LT(u, 3.0);
      su += u, su2 += u * u;
      const double z = rng.drawNormal(1.5, 2.0);
      sn += z, sn2 += z * z, sn4 += std::pow((z - 1.5) / 2.0, 4);
      inside += std::abs(z - 1.5) < 2.0;
    }
    const double mu = su / n, vu = su2 / n - mu * mu;  // uniform on [-2, 3): mean 0.5, variance 25/12
    EXPECT_NEAR(mu, 0.5, 5 * std::sqrt(25.0 / 12 / n)) << seed;
    EXPECT_NEAR(vu, 25.0 / 12, 5 * std::sqrt(0.8 * 25.0 * 25.0 / 144 / n)) << seed;
    const double mn = sn / n, vn = sn2 / n - mn * mn;
    EXPECT_NEAR(mn, 1.5, 5 * 2.0 / std::sqrt(n)) << seed;
    EXPECT_NEAR(vn, 4.0, 5 * 4.0 * std::sqrt(2.0 / n)) << seed;
    EXPECT_NEAR(sn4 / n, 3.0, 5 * std::sqrt(96.0 / n)) << seed;  // kurtosis of a normal: 3 (variance of z^4: 96)
    const double p = std::erf(1 / std::sqrt(2.0));             // 0.6827
    EXPECT_NEAR(static_cast<double>(inside) / n, p, 5 * std::sqrt(p * (1 - p) / n)) << seed;
  }
}

}  // namespace
}  // namespace motostab::core
