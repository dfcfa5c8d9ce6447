// The one number parser of user input (io/number.h): finite decimal numbers only.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/portable_random.h"
#include "io/number.h"

namespace motostab::io {

using core::PortableRandom;

namespace {

// Random finite doubles over many magnitudes (portable: raw mt19937_64 bits reinterpreted).
double drawFinite(PortableRandom& rng) {
  for (;;) {
    const std::uint64_t bits = rng.drawBits();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (std::isfinite(v)) return v;
  }
}

TEST(Number, RoundTripsRandomFiniteValues) {
  PortableRandom rng(20261124);
  for (int i = 0; i < 2000; ++i) {
    const double v = drawFinite(rng);
    char text[64];
    std::snprintf(text, sizeof text, i % 2 ? "%.17g" : "  %.17e\t", v);  // both notations, with blanks
    const auto parsed = parseFiniteNumber(text);
    ASSERT_TRUE(parsed) << text;
    EXPECT_EQ(*parsed, v) << text;  // %.17g is exact for doubles (IEEE 754 round trip)
  }
}

TEST(Number, AcceptsPlainForms) {
  EXPECT_EQ(parseFiniteNumber("0"), 0.0);
  EXPECT_EQ(parseFiniteNumber("-1.5"), -1.5);
  EXPECT_EQ(parseFiniteNumber("+.25"), 0.25);
  EXPECT_EQ(parseFiniteNumber("1e3"), 1000.0);
  EXPECT_EQ(parseFiniteNumber("2E-2"), 0.02);
}

TEST(Number, RejectsEverythingElse) {
  for (const char* bad : {"", " ", "nan", "NaN", "-nan", ".nan", "inf", "-inf", "+Infinity", ".inf", "1e999", "-1e400",
                          "0x10", "0x1p3", "1.5.2", "1,5", "12abc", "abc", "1 2", "--1", "e5", "1e", "."})
    EXPECT_FALSE(parseFiniteNumber(bad)) << "'" << bad << "'";
}

}  // namespace
}  // namespace motostab::io
