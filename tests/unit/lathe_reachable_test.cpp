// The reachable-part builder ([target] reachable = "nose", sim/lathe_reachable.hpp): the
// target part closed by a disc of the nose radius. Areas are hand-computed: a right-angle
// concave corner leaves a fillet of r^2 (1 - pi/4), convex corners stay sharp.
#include "sim/lathe_reachable.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace ncvm;
using lsim::Pt;

namespace {

constexpr double kScale = 1e6;     // integer units per mm, as LatheStock
constexpr double kArcTol = 50;     // integer units: 0.05 um chords on the round joins
constexpr double kAreaTol = 2e-4;  // mm^2: the polygonal arcs and the 4-unit band
const double kFillet = 1 - std::numbers::pi / 4;  // a right-angle fillet of radius 1

ClipperLib::IntPoint at(double r, double z) {
  return {static_cast<ClipperLib::cInt>(std::llround(z * kScale)),
          static_cast<ClipperLib::cInt>(std::llround(r * kScale))};
}

// The raw bar: z from -40 to 0, r from 0 to 30 (counter-clockwise in (z, r)).
ClipperLib::Path rawBar() {
  return {at(0, -40), at(0, 0), at(30, 0), at(30, -40)};
}

double area(const ClipperLib::Paths& ps) {
  double a = 0;
  for (const auto& p : ps) a += ClipperLib::Area(p);
  return a / (kScale * kScale);
}

// Whether (r, z) lies inside the region (even-odd over its rings; on the boundary counts).
bool inside(const ClipperLib::Paths& ps, double r, double z) {
  int crossings = 0;
  for (const auto& p : ps) {
    int w = ClipperLib::PointInPolygon(at(r, z), p);
    if (w < 0) return true;
    crossings += w;
  }
  return crossings % 2 == 1;
}

// A stepped shaft, as a G70 contour runs it: D30 for z 0..-10, a face up to D44, D44 to z-25,
// a face up past the raw D60 (the rest of the bar stays whole). Two concave corners, at
// (r 15, z -10) and (r 22, z -25); two convex ones, at (15, 0) and (22, -10).
std::vector<Pt> steppedContour() {
  return {{15, 2}, {15, -10}, {22, -10}, {22, -25}, {32, -25}};
}
// Its sharp part: 10 x 15 + 15 x 22 + 15 x 30 = 930 mm^2.
ClipperLib::Paths steppedPart() {
  return {{at(0, -40), at(0, 0), at(15, 0), at(15, -10), at(22, -10), at(22, -25), at(30, -25),
           at(30, -40)}};
}

}  // namespace

TEST(LatheReachable, ConcaveCornersAreClosedByTheNoseRadius) {
  const double r = 1.0;
  ReachablePart p =
      reachablePart(steppedContour(), steppedPart(), rawBar(), r, kArcTol, 1e-4, kScale);
  ASSERT_TRUE(p.found);
  // Two right-angle fillets of r = 1: 2 (1 - pi/4) = 0.429204 mm^2.
  EXPECT_NEAR(p.unreachableArea, 2 * r * r * kFillet, kAreaTol);
  EXPECT_EQ(p.corners, 2);
  EXPECT_NEAR(area(p.part), 930 + 2 * r * r * kFillet, kAreaTol);
  // The fillet at (15, -10): material where the nose disc (centre (16, -9)) cannot go, air
  // inside the disc.
  EXPECT_TRUE(inside(p.part, 15.05, -9.95));   // 1.34 from the disc centre
  EXPECT_FALSE(inside(p.part, 15.5, -9.5));    // 0.71 from it
  EXPECT_TRUE(inside(p.part, 22.05, -24.95));  // the other fillet, centre (23, -24)
  EXPECT_FALSE(inside(p.part, 22.5, -24.5));
}

TEST(LatheReachable, ConvexCornersStaySharp) {
  ReachablePart p =
      reachablePart(steppedContour(), steppedPart(), rawBar(), 1.0, kArcTol, 1e-4, kScale);
  ASSERT_TRUE(p.found);
  // Right at the convex corners (15, 0) and (22, -10): material inside, air outside, a
  // hundredth of a millimetre either side (a rounded corner of r 1 would cut 0.29 mm off).
  EXPECT_TRUE(inside(p.part, 14.99, -0.01));
  EXPECT_FALSE(inside(p.part, 15.01, -0.01));
  EXPECT_TRUE(inside(p.part, 21.99, -10.01));
  EXPECT_FALSE(inside(p.part, 22.01, -9.99));
  // Away from the concave corners the part is the sharp one: along the D30 and the faces.
  EXPECT_TRUE(inside(p.part, 14.999, -5));
  EXPECT_FALSE(inside(p.part, 15.001, -5));
  EXPECT_TRUE(inside(p.part, 18, -10.001));
  EXPECT_FALSE(inside(p.part, 18, -9.999));
}

TEST(LatheReachable, AGrooveNarrowerThanTheNoseIsUnreachable) {
  // A D50 bar with a groove 2 wide and 5 deep (z -10..-12, down to r 20); nose r 1.5, so
  // 2r = 3 > 2: the nose cannot enter. The closing fills the groove but for the cap the
  // lowest disc that still fits the mouth dips in: its centre sits where the chord at r 25
  // is the groove's width, r = 25 + sqrt(1.5^2 - 1^2) = 26.118, so the cap is the circular
  // segment of height h = 1.5 - 1.118 = 0.382: r^2 acos((r - h) / r) - (r - h) sqrt(2rh -
  // h^2) = 2.25 acos(0.745356) - 1.118034 x 1 = 2.25 x 0.729728 - 1.118034 = 0.523853.
  // Unreachable: 10 - 0.523853.
  const double r = 1.5;
  std::vector<Pt> contour{{25, 2}, {25, -10}, {20, -10}, {20, -12}, {25, -12}, {25, -30}};
  ClipperLib::Paths part{{at(0, -40), at(0, 0), at(25, 0), at(25, -10), at(20, -10), at(20, -12),
                          at(25, -12), at(25, -40)}};
  ReachablePart p = reachablePart(contour, part, rawBar(), r, kArcTol, 1e-4, kScale);
  ASSERT_TRUE(p.found);
  const double h = r - std::sqrt(r * r - 1);
  const double cap = r * r * std::acos((r - h) / r) - (r - h) * std::sqrt(2 * r * h - h * h);
  EXPECT_NEAR(cap, 0.523853, 1e-6);
  EXPECT_NEAR(p.unreachableArea, 10 - cap, kAreaTol);
  EXPECT_EQ(p.corners, 1);                   // the whole groove is one piece
  EXPECT_TRUE(inside(p.part, 20.01, -11));   // its bottom is material the nose leaves
  EXPECT_TRUE(inside(p.part, 24.6, -11));    // just below the cap (it reaches 24.618)
  EXPECT_FALSE(inside(p.part, 24.7, -11));   // inside the cap
  EXPECT_FALSE(inside(p.part, 25.01, -11));  // above the bar
}

TEST(LatheReachable, ZeroNoseRadiusIsTheSharpPart) {
  ReachablePart p =
      reachablePart(steppedContour(), steppedPart(), rawBar(), 0.0, kArcTol, 1e-4, kScale);
  ASSERT_TRUE(p.found);
  EXPECT_NEAR(p.unreachableArea, 0, 1e-6);
  EXPECT_EQ(p.corners, 0);
  EXPECT_NEAR(area(p.part), 930, kAreaTol);
  EXPECT_FALSE(inside(p.part, 15.001, -9.999));  // the concave corner stays sharp
  EXPECT_TRUE(inside(p.part, 14.999, -10.001));
}

TEST(LatheReachable, AContourThatDoesNotSplitTheBarIsNotFound) {
  // The final stock kept every piece: no air side to tell the part from.
  ClipperLib::Paths whole{rawBar()};
  ReachablePart p = reachablePart(steppedContour(), whole, rawBar(), 1.0, kArcTol, 1e-4, kScale);
  EXPECT_FALSE(p.found);
}
