#include "core/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

using namespace ncvm;

// roundHalfAway replaces std::llround on the hot path; it must give the same integer for
// every double llround defines.
TEST(Units, RoundHalfAwayIsLlround) {
  const double fixed[] = {0.0,
                          -0.0,
                          0.5,
                          -0.5,
                          1.5,
                          -1.5,
                          2.5,
                          -2.5,
                          0.49999999999999994,
                          -0.49999999999999994,
                          4503599627370495.5,
                          -4503599627370495.5,
                          4503599627370497.0,
                          9007199254740993.0,
                          1e17,
                          -1e17,
                          8.9e18,
                          -8.9e18,
                          123456.4999999,
                          123456.5000001,
                          std::nextafter(0.5, 0.0),
                          std::nextafter(0.5, 1.0)};
  for (double x : fixed) EXPECT_EQ(roundHalfAway(x), std::llround(x)) << x;
  uint64_t k = 99;
  for (int i = 0; i < 200000; ++i) {
    k = k * 6364136223846793005ULL + 1442695040888963407ULL;
    const double scale = std::ldexp(1.0, static_cast<int>((k >> 58) % 62) - 2);  // 0.25 .. 2^59
    double x = (static_cast<double>(k >> 11) / 9007199254740992.0 - 0.5) * scale;
    if (i % 4 == 0) x = std::round(x) + ((k & 1) ? 0.5 : -0.5);  // exact halves
    EXPECT_EQ(roundHalfAway(x), std::llround(x)) << x;
  }
}

// At and just below 9e18, where the fast path hands over to llround (both in int64 range).
TEST(Units, RoundHalfAwayAtTheFallbackBoundary) {
  EXPECT_EQ(roundHalfAway(9.0e18), INT64_C(9000000000000000000));
  EXPECT_EQ(roundHalfAway(-9.0e18), -INT64_C(9000000000000000000));
  const double below = std::nextafter(9.0e18, 0.0);
  EXPECT_EQ(roundHalfAway(below), std::llround(below));
  EXPECT_EQ(roundHalfAway(-below), std::llround(-below));
}
