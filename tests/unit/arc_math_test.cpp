// The shared arc arithmetic (exec/arc_math.hpp): the sweep in (0, 2π] in both directions, the
// full circle, the half circle whichever sign the zero cross product has, and agreement with
// the difference of two angles that it replaced.
#include "exec/arc_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using ncvm::arcSweep;
using ncvm::planeDistance;

namespace {
constexpr double kPi = std::numbers::pi;

// The old formula: atan2 of each radius vector, the difference brought into (0, 2π].
double sweepByAngles(double su, double sv, double eu, double ev, double cu, double cv, bool cw) {
  if (eu == su && ev == sv) return 2 * kPi;
  const double as = std::atan2(sv - cv, su - cu), ae = std::atan2(ev - cv, eu - cu);
  double s = cw ? as - ae : ae - as;
  while (s <= 0) s += 2 * kPi;
  while (s > 2 * kPi) s -= 2 * kPi;
  return s;
}
}  // namespace

TEST(ArcMath, QuarterHalfAndFullCircles) {
  // Centre at the origin, start on +X.
  EXPECT_DOUBLE_EQ(arcSweep(1e6, 0, 0, 1e6, 0, 0, false), kPi / 2);     // G03 quarter
  EXPECT_DOUBLE_EQ(arcSweep(1e6, 0, 0, 1e6, 0, 0, true), 3 * kPi / 2);  // G02 the long way
  EXPECT_DOUBLE_EQ(arcSweep(1e6, 0, 0, -1e6, 0, 0, true), kPi / 2);     // G02 quarter
  EXPECT_DOUBLE_EQ(arcSweep(1e6, 0, -1e6, 0, 0, 0, false), kPi);        // half, cross = +0
  EXPECT_DOUBLE_EQ(arcSweep(1e6, 0, -1e6, 0, 0, 0, true), kPi);
  EXPECT_DOUBLE_EQ(arcSweep(0, -1e6, 0, 1e6, 0, 0, false), kPi);  // half, cross = -0
  EXPECT_DOUBLE_EQ(arcSweep(0, -1e6, 0, 1e6, 0, 0, true), kPi);
  EXPECT_DOUBLE_EQ(arcSweep(5e5, 7e5, 5e5, 7e5, 1e5, 2e5, false), 2 * kPi);  // full circle
  EXPECT_DOUBLE_EQ(arcSweep(5e5, 7e5, 5e5, 7e5, 1e5, 2e5, true), 2 * kPi);
  // The end in the start's direction, farther out (within the radius tolerance): a full turn,
  // as the difference of two equal angles gave.
  EXPECT_DOUBLE_EQ(arcSweep(1e6, 0, 1e6 + 3, 0, 0, 0, false), 2 * kPi);
  EXPECT_DOUBLE_EQ(planeDistance(3e6, -4e6), 5e6);
}

TEST(ArcMath, AgreesWithTheDifferenceOfAngles) {
  std::mt19937_64 rng(20261202);
  std::uniform_int_distribution<int64_t> coord(-50'000'000, 50'000'000);
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    const auto su = static_cast<double>(coord(rng)), sv = static_cast<double>(coord(rng));
    const auto eu = static_cast<double>(coord(rng)), ev = static_cast<double>(coord(rng));
    const auto cu = static_cast<double>(coord(rng)), cv = static_cast<double>(coord(rng));
    for (bool cw : {false, true}) {
      const double a = arcSweep(su, sv, eu, ev, cu, cv, cw);
      ASSERT_GT(a, 0);
      ASSERT_LE(a, 2 * kPi);
      double d = std::fabs(a - sweepByAngles(su, sv, eu, ev, cu, cv, cw));
      d = std::min(d, std::fabs(d - 2 * kPi));  // an angle near 0 may land on either side
      worst = std::max(worst, d);
    }
    EXPECT_NEAR(planeDistance(su - cu, sv - cv), std::hypot(su - cu, sv - cv), 1e-6);
  }
  EXPECT_LT(worst, 1e-12);
}
