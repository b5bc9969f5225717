// Cutter compensation C (src/motion/cutter_comp.hpp). Every expected point is worked out by
// hand in the comments; r is the cutter radius, "left"/"right" the side of the direction of
// travel. s = sqrt(2)/2 below.
#include "motion/cutter_comp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace ncvm;
using namespace ncvm::crc;

namespace {

constexpr double kTol = 1e-6;
const double kS = std::sqrt(2.0) / 2;             // sin 45
const double kT = std::tan(std::acos(-1.0) / 8);  // tan 22.5 = sqrt(2) - 1

// Collects what the compensator emits.
struct Sink {
  std::vector<OutSeg> segs;
  Compensator comp;
  explicit Sink(Options o = {}) : comp(o, [this](const OutSeg& s) { segs.push_back(s); }) {}
  Sink(const Sink&) = delete;
  Sink& operator=(const Sink&) = delete;
};

InSeg line(P2 a, P2 b, Side side, double r, int tag, bool rapid = false) {
  InSeg s;
  s.kind = Kind::Line;
  s.start = a;
  s.end = b;
  s.side = side;
  s.radius = r;
  s.tag = tag;
  s.rapid = rapid;
  return s;
}

InSeg arc(Kind k, P2 a, P2 b, P2 c, Side side, double r, int tag) {
  InSeg s = line(a, b, side, r, tag);
  s.kind = k;
  s.center = c;
  return s;
}

void expectPt(P2 got, P2 want, const char* what) {
  EXPECT_NEAR(got.u, want.u, kTol) << what;
  EXPECT_NEAR(got.v, want.v, kTol) << what;
}

void expectSeg(const OutSeg& s, int tag, P2 a, P2 b, Kind k = Kind::Line, bool inserted = false) {
  SCOPED_TRACE("segment of tag " + std::to_string(tag));
  EXPECT_EQ(s.tag, tag);
  EXPECT_EQ(s.kind, k);
  EXPECT_EQ(s.inserted, inserted);
  expectPt(s.start, a, "start");
  expectPt(s.end, b, "end");
}

AlarmId alarmOf(const std::function<void()>& f, int* tag = nullptr) {
  try {
    f();
  } catch (const CrcError& e) {
    if (tag) *tag = e.tag;
    return e.id;
  }
  ADD_FAILURE() << "no CrcError";
  return AlarmId::BlockLimit;
}

}  // namespace

// Outside of the square (0,0)-(100,100) clockwise with G41 r=5 (climb milling). The start-up
// (-20,0)->(0,0) meets the first side (+Y) at an inner corner, so it ends perpendicular to
// it at (-5,0). Every corner of the square is an outer 90-degree corner: intersections at
// (-5,105), (105,105), (105,-5), (-5,-5). The G40 block turns left from +Y (inner corner),
// so the block before it ends perpendicular at (-5,50).
TEST(CrcSquare, G41ClimbEverySegment) {
  Sink r;
  const Side L = Side::Left;
  r.comp.push(line({-50, 0}, {-20, 0}, Side::Off, 0, 1, true));
  r.comp.push(line({-20, 0}, {0, 0}, L, 5, 2));
  EXPECT_TRUE(r.comp.active());
  r.comp.push(line({0, 0}, {0, 100}, L, 5, 3));
  r.comp.push(line({0, 100}, {100, 100}, L, 5, 4));
  r.comp.push(line({100, 100}, {100, 0}, L, 5, 5));
  r.comp.push(line({100, 0}, {0, 0}, L, 5, 6));
  r.comp.push(line({0, 0}, {0, 50}, L, 5, 7));
  r.comp.push(line({0, 50}, {-20, 50}, Side::Off, 5, 8));
  EXPECT_FALSE(r.comp.active());
  ASSERT_EQ(r.segs.size(), 8u);
  expectSeg(r.segs[0], 1, {-50, 0}, {-20, 0});
  EXPECT_TRUE(r.segs[0].rapid);
  // Start-up into an inner corner: the intersection of the two offset paths.
  expectSeg(r.segs[1], 2, {-20, 0}, {-5, 5});
  expectSeg(r.segs[2], 3, {-5, 5}, {-5, 105});
  expectSeg(r.segs[3], 4, {-5, 105}, {105, 105});
  expectSeg(r.segs[4], 5, {105, 105}, {105, -5});
  expectSeg(r.segs[5], 6, {105, -5}, {-5, -5});
  expectSeg(r.segs[6], 7, {-5, -5}, {-5, 50});
  expectSeg(r.segs[7], 8, {-5, 50}, {-20, 50});
}

// The same square counter-clockwise with G42 r=5 (conventional milling). The start-up runs
// straight into the first side (tangent): it ends at (0,-5). The G40 block turns right from
// +X, an inner corner for G42: the previous block ends perpendicular at (50,-5).
void g42Square(Sink& r, Side side, double radius) {
  r.comp.push(line({-50, 0}, {-20, 0}, Side::Off, 0, 1, true));
  r.comp.push(line({-20, 0}, {0, 0}, side, radius, 2));
  r.comp.push(line({0, 0}, {100, 0}, side, radius, 3));
  r.comp.push(line({100, 0}, {100, 100}, side, radius, 4));
  r.comp.push(line({100, 100}, {0, 100}, side, radius, 5));
  r.comp.push(line({0, 100}, {0, 0}, side, radius, 6));
  r.comp.push(line({0, 0}, {50, 0}, side, radius, 7));
  r.comp.push(line({50, 0}, {50, -20}, Side::Off, radius, 8));
}

TEST(CrcSquare, G42ConventionalEverySegment) {
  Sink r;
  g42Square(r, Side::Right, 5);
  ASSERT_EQ(r.segs.size(), 8u);
  expectSeg(r.segs[1], 2, {-20, 0}, {0, -5});
  expectSeg(r.segs[2], 3, {0, -5}, {105, -5});
  expectSeg(r.segs[3], 4, {105, -5}, {105, 105});
  expectSeg(r.segs[4], 5, {105, 105}, {-5, 105});
  expectSeg(r.segs[5], 6, {-5, 105}, {-5, -5});
  expectSeg(r.segs[6], 7, {-5, -5}, {50, -5});
  expectSeg(r.segs[7], 8, {50, -5}, {50, -20});
}

// A negative D swaps G41 and G42: G41 with r=-5 cuts exactly the G42 r=5 path.
TEST(CrcSquare, NegativeRadiusSwapsSides) {
  Sink pos, neg;
  g42Square(pos, Side::Right, 5);
  g42Square(neg, Side::Left, -5);
  ASSERT_EQ(pos.segs.size(), neg.segs.size());
  for (size_t i = 0; i < pos.segs.size(); ++i)
    expectSeg(neg.segs[i], pos.segs[i].tag, pos.segs[i].start, pos.segs[i].end);
}

// Pocket 60x30 counter-clockwise with G41 r=3: the tool is inside, every corner is inner and
// cut at the intersection: (57,3), (57,27), (3,27), (3,3). Start-up from the centre down to
// (30,0), then +X: a left turn, inner, so it ends at the intersection (33,3).
TEST(CrcSquare, RectanglePocketInnerCorners) {
  Sink r;
  const Side L = Side::Left;
  r.comp.push(line({30, 15}, {30, 0}, L, 3, 1));
  r.comp.push(line({30, 0}, {60, 0}, L, 3, 2));
  r.comp.push(line({60, 0}, {60, 30}, L, 3, 3));
  r.comp.push(line({60, 30}, {0, 30}, L, 3, 4));
  r.comp.push(line({0, 30}, {0, 0}, L, 3, 5));
  r.comp.push(line({0, 0}, {30, 0}, L, 3, 6));
  r.comp.push(line({30, 0}, {30, 15}, Side::Off, 3, 7));
  ASSERT_EQ(r.segs.size(), 7u);
  expectSeg(r.segs[0], 1, {30, 15}, {33, 3});
  expectSeg(r.segs[1], 2, {33, 3}, {57, 3});
  expectSeg(r.segs[2], 3, {57, 3}, {57, 27});
  expectSeg(r.segs[3], 4, {57, 27}, {3, 27});
  expectSeg(r.segs[4], 5, {3, 27}, {3, 3});
  expectSeg(r.segs[5], 6, {3, 3}, {30, 3});  // inner corner with the G40 block: perpendicular
  expectSeg(r.segs[6], 7, {30, 3}, {30, 15});
}

// Circular pocket: start-up to (20,0), a full G03 circle R20 around the origin with G41
// r=5, G40 back to the centre. Both corners are inner: the start-up ends where its offset
// line y=5 meets the offset circle R15, (sqrt(200), 5); the arc on radius 15 ends
// perpendicular at (15,0) before the cancel block, so 19.47 degrees of the circle stay
// uncut, which is why pockets are entered with a lead-in arc.
TEST(CrcArc, FullCirclePocket) {
  Sink r;
  r.comp.push(line({0, 0}, {20, 0}, Side::Left, 5, 1));
  r.comp.push(arc(Kind::Ccw, {20, 0}, {20, 0}, {0, 0}, Side::Left, 5, 2));
  r.comp.push(line({20, 0}, {0, 0}, Side::Off, 5, 3));
  ASSERT_EQ(r.segs.size(), 3u);
  const double x = std::sqrt(200.0);
  expectSeg(r.segs[0], 1, {0, 0}, {x, 5});
  expectSeg(r.segs[1], 2, {x, 5}, {15, 0}, Kind::Ccw);
  expectSeg(r.segs[2], 3, {15, 0}, {0, 0});
}

// The control holds a block until the next move is read: nothing comes out of the start-up
// until the first contour block arrives, and flush() releases the last one.
TEST(CrcLookahead, BlockWaitsForTheNextMove) {
  Sink r;
  r.comp.push(line({-20, 0}, {0, 0}, Side::Left, 5, 1));
  EXPECT_TRUE(r.segs.empty());
  r.comp.push(line({0, 0}, {50, 0}, Side::Left, 5, 2));
  ASSERT_EQ(r.segs.size(), 1u);
  r.comp.flush();
  ASSERT_EQ(r.segs.size(), 2u);
  expectSeg(r.segs[1], 2, {0, 5}, {50, 5});  // no next block: perpendicular at the end
  EXPECT_TRUE(r.comp.active());              // flush keeps the vector
}

// Helper: G41 r=5, start-up (-20,0)->(0,0) and a first block (0,0)->(50,0) (tangent, so it
// starts at (0,5)); then the block under test from (50,0).
void straightIn(Sink& r, double radius = 5) {
  r.comp.push(line({-20, 0}, {0, 0}, Side::Left, radius, 1));
  r.comp.push(line({0, 0}, {50, 0}, Side::Left, radius, 2));
}

// Outer corner of 135 degrees on the workpiece side (path turns right by 45 with G41): the
// intersection of y=5 with the offset of the second line is at x = 50 + r*tan(22.5).
TEST(CrcCorner, ObtuseOuter135IsTheIntersection) {
  Sink r;
  straightIn(r);
  r.comp.push(line({50, 0}, {60, -10}, Side::Left, 5, 3));
  r.comp.flush();
  ASSERT_EQ(r.segs.size(), 3u);
  expectSeg(r.segs[0], 1, {-20, 0}, {0, 5});
  expectSeg(r.segs[1], 2, {0, 5}, {50 + 5 * kT, 5});
  // end of block 3: perpendicular (flush), left normal of (1,-1) is (s,s)
  expectSeg(r.segs[2], 3, {50 + 5 * kT, 5}, {60 + 5 * kS, -10 + 5 * kS});
}

// Outer corner of 45 degrees (path turns right by 135): block 2 is extended by r to (55,5);
// an extra move goes to the point r before the start of block 3's offset path:
// pB = (50,0) + 5*(s,-s), minus 5*(-s,-s) = (50 + 10s, 0).
TEST(CrcCorner, AcuteOuter45InsertsTwoVectors) {
  Sink r;
  straightIn(r);
  r.comp.push(line({50, 0}, {40, -10}, Side::Left, 5, 3));
  r.comp.flush();
  ASSERT_EQ(r.segs.size(), 4u);
  expectSeg(r.segs[1], 2, {0, 5}, {55, 5});
  expectSeg(r.segs[2], 2, {55, 5}, {50 + 10 * kS, 0}, Kind::Line, true);
  expectSeg(r.segs[3], 3, {50 + 10 * kS, 0}, {40 + 5 * kS, -10 - 5 * kS});
}

// Inner corner (path turns left by 45 with G41): intersection at x = 50 - r*tan(22.5).
TEST(CrcCorner, InnerCornerIsTheIntersection) {
  Sink r;
  straightIn(r);
  r.comp.push(line({50, 0}, {60, 10}, Side::Left, 5, 3));
  r.comp.flush();
  ASSERT_EQ(r.segs.size(), 3u);
  expectSeg(r.segs[1], 2, {0, 5}, {50 - 5 * kT, 5});
  expectSeg(r.segs[2], 3, {50 - 5 * kT, 5}, {60 - 5 * kS, 10 + 5 * kS});
}

// Line -> tangent G03 (R10, centre (50,10)) -> tangent line up. Left of a G03 arc is towards
// its centre: the tool runs on radius 10-5 = 5, from (50,5) to (55,10), then up x = 55.
TEST(CrcArc, TangentLineArcLine) {
  Sink r;
  straightIn(r);
  r.comp.push(arc(Kind::Ccw, {50, 0}, {60, 10}, {50, 10}, Side::Left, 5, 3));
  r.comp.push(line({60, 10}, {60, 50}, Side::Left, 5, 4));
  r.comp.flush();
  ASSERT_EQ(r.segs.size(), 4u);
  expectSeg(r.segs[1], 2, {0, 5}, {50, 5});
  expectSeg(r.segs[2], 3, {50, 5}, {55, 10}, Kind::Ccw);
  expectPt(r.segs[2].center, {50, 10}, "centre");
  expectSeg(r.segs[3], 4, {55, 10}, {55, 50});
}

// Line +X -> G02 half circle (50,0)->(70,0) around (60,0), which starts going +Y and ends
// going -Y -> line +X. Both corners turn left: inner for G41. Left of a G02 arc is away from
// the centre: radius 10+5 = 15. y=5 meets it at x = 60 -+ sqrt(225-25) = 60 -+ 10*sqrt(2).
TEST(CrcArc, NonTangentLineArcLine) {
  Sink r;
  straightIn(r);
  r.comp.push(arc(Kind::Cw, {50, 0}, {70, 0}, {60, 0}, Side::Left, 5, 3));
  r.comp.push(line({70, 0}, {100, 0}, Side::Left, 5, 4));
  r.comp.flush();
  const double h = 10 * std::sqrt(2.0);
  ASSERT_EQ(r.segs.size(), 4u);
  expectSeg(r.segs[1], 2, {0, 5}, {60 - h, 5});
  expectSeg(r.segs[2], 3, {60 - h, 5}, {60 + h, 5}, Kind::Cw);
  expectSeg(r.segs[3], 4, {60 + h, 5}, {100, 5});
}

// Line -> G03 (10,0)->(30,0) around (20,0) (starts going -Y: outer 90 for G41, so the line
// is extended to where y=2 meets the offset circle of radius 10-2 = 8: x = 20 - sqrt(60))
// -> G02 (30,0)->(30,20) around (30,10), starting -X after arriving +Y: inner corner of two
// arcs. Circles (20,0) r8 and (30,10) r12 meet at (23,3) -+ sqrt(46)*(-s,s); the one near
// the corner is (23 + sqrt(23), 3 - sqrt(23)).
TEST(CrcArc, ArcToArcIntersection) {
  Sink r;
  const Side L = Side::Left;
  r.comp.push(line({-10, 0}, {0, 0}, L, 2, 1));
  r.comp.push(line({0, 0}, {10, 0}, L, 2, 2));
  r.comp.push(arc(Kind::Ccw, {10, 0}, {30, 0}, {20, 0}, L, 2, 3));
  r.comp.push(arc(Kind::Cw, {30, 0}, {30, 20}, {30, 10}, L, 2, 4));
  r.comp.flush();
  const P2 x1{20 - std::sqrt(60.0), 2};
  const P2 x2{23 + std::sqrt(23.0), 3 - std::sqrt(23.0)};
  ASSERT_EQ(r.segs.size(), 4u);
  expectSeg(r.segs[1], 2, {0, 2}, x1);
  expectSeg(r.segs[2], 3, x1, x2, Kind::Ccw);
  expectSeg(r.segs[3], 4, x2, {30, 22}, Kind::Cw);  // flush: perpendicular, radius 12
  expectPt(r.segs[3].center, {30, 10}, "centre");
}

// Two arcs meeting tangentially (an S curve): the corner is the common perpendicular point.
TEST(CrcArc, TangentArcToArc) {
  Sink r;
  const Side L = Side::Left;
  r.comp.push(line({10, 10}, {10, 0}, L, 2, 1));
  r.comp.push(arc(Kind::Ccw, {10, 0}, {30, 0}, {20, 0}, L, 2, 2));
  r.comp.push(arc(Kind::Cw, {30, 0}, {50, 0}, {40, 0}, L, 2, 3));
  r.comp.flush();
  ASSERT_EQ(r.segs.size(), 3u);
  expectSeg(r.segs[0], 1, {10, 10}, {12, 0});  // tangent start-up: perpendicular
  expectSeg(r.segs[1], 2, {12, 0}, {28, 0}, Kind::Ccw);
  expectSeg(r.segs[2], 3, {28, 0}, {52, 0}, Kind::Cw);
}

// Start-up (0,0)->(50,0) with G41 r=5, then a 45-degree right turn (outer, 135 on the
// workpiece side). Type A ends the start-up perpendicular to the NEXT block:
// (50,0) + 5*(s,s). Type B ends it at the intersection, as in offset mode: (50+5*tan22.5, 5).
TEST(CrcStartup, TypeAVersusTypeBObtuse) {
  for (bool typeB : {false, true}) {
    Options o;
    o.startupTypeB = typeB;
    Sink r(o);
    r.comp.push(line({0, 0}, {50, 0}, Side::Left, 5, 1));
    r.comp.push(line({50, 0}, {60, -10}, Side::Left, 5, 2));
    ASSERT_EQ(r.segs.size(), 1u);
    P2 want = typeB ? P2{50 + 5 * kT, 5} : P2{50 + 5 * kS, 5 * kS};
    expectSeg(r.segs[0], 1, {0, 0}, want);
  }
}

// Acute outer start-up (turn right by 135): type A again perpendicular to the next block,
// type B with the two extra vectors of an offset-mode corner.
TEST(CrcStartup, TypeAVersusTypeBAcute) {
  Options a, b;
  b.startupTypeB = true;
  Sink ra(a), rb(b);
  for (Sink* r : {&ra, &rb}) {
    r->comp.push(line({0, 0}, {50, 0}, Side::Left, 5, 1));
    r->comp.push(line({50, 0}, {40, -10}, Side::Left, 5, 2));
  }
  ASSERT_EQ(ra.segs.size(), 1u);
  expectSeg(ra.segs[0], 1, {0, 0}, {50 + 5 * kS, -5 * kS});
  ASSERT_EQ(rb.segs.size(), 2u);
  expectSeg(rb.segs[0], 1, {0, 0}, {55, 5});
  expectSeg(rb.segs[1], 1, {55, 5}, {50 + 10 * kS, 0}, Kind::Line, true);
}

// G40 (50,0)->(60,-10) after a block along +X (outer 135). Type A: the previous block ends
// perpendicular to its end (50,5); type B: at the intersection with the offset of the
// cancel block. The cancel block always ends at the programmed point.
TEST(CrcCancel, TypeAAndTypeBWithoutIJ) {
  for (bool typeB : {false, true}) {
    Options o;
    o.startupTypeB = typeB;
    Sink r(o);
    straightIn(r);
    r.comp.push(line({50, 0}, {60, -10}, Side::Off, 5, 3));
    EXPECT_FALSE(r.comp.active());
    ASSERT_EQ(r.segs.size(), 3u);
    P2 corner = typeB ? P2{50 + 5 * kT, 5} : P2{50, 5};
    expectSeg(r.segs[1], 2, {0, 5}, corner);
    expectSeg(r.segs[2], 3, corner, {60, -10});
  }
}

// G40 X50 Y-20 I10 J-10: the previous block ends where its offset meets the offset of a
// virtual path in the I/J direction (1,-1) from (50,0): (50+5*tan22.5, 5), even with type A;
// the G40 block then goes straight down to (50,-20).
TEST(CrcCancel, WithIJPointsTheCancelDirection) {
  Sink r;
  straightIn(r);
  InSeg c = line({50, 0}, {50, -20}, Side::Off, 5, 3);
  c.hasIJK = true;
  c.ijk = {10, -10};
  r.comp.push(c);
  ASSERT_EQ(r.segs.size(), 3u);
  expectSeg(r.segs[1], 2, {0, 5}, {50 + 5 * kT, 5});
  expectSeg(r.segs[2], 3, {50 + 5 * kT, 5}, {50, -20});
}

// D5 -> D10 in block 3: its start corner uses the old radius (y=5 meets x=45), its end the
// new one (x=40 meets y=40); block 4 then runs on y=40.
TEST(CrcOffsetChange, NewDAppliesFromTheEndOfItsBlock) {
  Sink r;
  straightIn(r);
  r.comp.push(line({50, 0}, {50, 50}, Side::Left, 10, 3));
  r.comp.push(line({50, 50}, {0, 50}, Side::Left, 10, 4));
  r.comp.flush();
  ASSERT_EQ(r.segs.size(), 4u);
  expectSeg(r.segs[1], 2, {0, 5}, {45, 5});
  expectSeg(r.segs[2], 3, {45, 5}, {40, 40});
  expectSeg(r.segs[3], 4, {40, 40}, {0, 40});
}

// G41 -> G42 at (50,0), going up: the old-side path y=5 meets the new-side path x=55.
TEST(CrcSideChange, G41ToG42AtTheIntersection) {
  Sink r;
  straightIn(r);
  r.comp.push(line({50, 0}, {50, 50}, Side::Right, 5, 3));
  r.comp.push(line({50, 50}, {100, 50}, Side::Right, 5, 4));
  r.comp.flush();
  ASSERT_EQ(r.segs.size(), 4u);
  expectSeg(r.segs[1], 2, {0, 5}, {55, 5});
  expectSeg(r.segs[2], 3, {55, 5}, {55, 45});  // then an inner corner on the right side
  expectSeg(r.segs[3], 4, {55, 45}, {100, 45});
}

// G41 -> G42 on a straight line: the offset paths are parallel, there is no intersection.
// Block 2 ends perpendicular (50,5), an extra move crosses to (50,-5), block 3 runs y=-5.
TEST(CrcSideChange, NoIntersectionCrossesWithPerpendicularVectors) {
  Sink r;
  straightIn(r);
  r.comp.push(line({50, 0}, {100, 0}, Side::Right, 5, 3));
  r.comp.flush();
  ASSERT_EQ(r.segs.size(), 4u);
  expectSeg(r.segs[1], 2, {0, 5}, {50, 5});
  expectSeg(r.segs[2], 2, {50, 5}, {50, -5}, Kind::Line, true);
  expectSeg(r.segs[3], 3, {50, -5}, {100, -5});
}

// With lookahead 3 the control can skip one non-moving block; with two in a row it cannot
// see the next move and ends the block perpendicular: (50,5) instead of the inner-corner
// intersection (45,5). The next block then starts from there (an overcut on the real machine).
TEST(CrcLookahead, TwoNonMovingBlocksGivePerpendicularVector) {
  Sink one, two;
  straightIn(one);
  one.comp.pushNonMoving(3);
  one.comp.push(line({50, 0}, {50, 50}, Side::Left, 5, 5));
  ASSERT_EQ(one.segs.size(), 2u);
  expectSeg(one.segs[1], 2, {0, 5}, {45, 5});

  straightIn(two);
  two.comp.pushNonMoving(3);
  EXPECT_EQ(two.segs.size(), 1u);
  two.comp.pushNonMoving(4);
  ASSERT_EQ(two.segs.size(), 2u);  // executed as soon as the buffer is full
  expectSeg(two.segs[1], 2, {0, 5}, {50, 5});
  two.comp.push(line({50, 0}, {50, 50}, Side::Left, 5, 5));
  two.comp.flush();
  ASSERT_EQ(two.segs.size(), 3u);
  expectSeg(two.segs[2], 5, {50, 5}, {45, 50});
}

TEST(CrcLookahead, DeeperBufferToleratesMoreNonMovingBlocks) {
  Options o;
  o.lookahead = 5;  // N-2 >= M: three non-moving blocks still allow the intersection
  Sink r(o);
  straightIn(r);
  for (int t = 3; t < 6; ++t) r.comp.pushNonMoving(t);
  r.comp.push(line({50, 0}, {50, 50}, Side::Left, 5, 6));
  ASSERT_EQ(r.segs.size(), 2u);
  expectSeg(r.segs[1], 2, {0, 5}, {45, 5});
}

// G39 on the block after a corner: the previous block ends perpendicular (-5,50), a
// clockwise (G41) arc of radius r around the corner (0,50) brings the tool to (0,55).
TEST(CrcCornerArc, G39InsertsArcAroundTheCorner) {
  Sink r;
  r.comp.push(line({0, -20}, {0, 0}, Side::Left, 5, 1));
  r.comp.push(line({0, 0}, {0, 50}, Side::Left, 5, 2));
  InSeg b = line({0, 50}, {50, 50}, Side::Left, 5, 3);
  b.cornerArc = true;
  r.comp.push(b);
  r.comp.flush();
  ASSERT_EQ(r.segs.size(), 4u);
  expectSeg(r.segs[1], 2, {-5, 0}, {-5, 50});
  expectSeg(r.segs[2], 3, {-5, 50}, {0, 55}, Kind::Cw, true);
  expectPt(r.segs[2].center, {0, 50}, "centre");
  expectSeg(r.segs[3], 3, {0, 55}, {50, 55});
}

TEST(CrcErrors, ArcStartupOrCancelIsPS0034) {
  Sink r;
  int tag = 0;
  EXPECT_EQ(alarmOf(
                [&] {
                  r.comp.push(arc(Kind::Cw, {0, 0}, {20, 0}, {10, 0}, Side::Left, 5, 7));
                },
                &tag),
            AlarmId::NoCircInStartupCancel);
  EXPECT_EQ(tag, 7);
  Sink c;
  straightIn(c);
  EXPECT_EQ(alarmOf(
                [&] {
                  c.comp.push(arc(Kind::Cw, {50, 0}, {70, 0}, {60, 0}, Side::Off, 5, 3));
                },
                &tag),
            AlarmId::NoCircInStartupCancel);
  EXPECT_EQ(tag, 3);
}

// G03 of radius 4 on the tool side with r=5: offset radius 4-5 < 0.
TEST(CrcErrors, InnerArcSmallerThanCutterIsPS0033) {
  Sink r;
  straightIn(r);
  int tag = 0;
  EXPECT_EQ(alarmOf(
                [&] {
                  r.comp.push(arc(Kind::Ccw, {50, 0}, {54, 4}, {50, 4}, Side::Left, 5, 3));
                },
                &tag),
            AlarmId::NoIntersectionCrc);
  EXPECT_EQ(tag, 3);
}

// Inner corner line +X -> G03 (centre (42,0), R8) starting +Y: the offset circle (radius 3)
// never reaches the offset line y=5.
TEST(CrcErrors, InnerCornerWithoutIntersectionIsPS0033) {
  Sink r;
  straightIn(r);
  EXPECT_EQ(alarmOf([&] {
              r.comp.push(arc(Kind::Ccw, {50, 0}, {34, 0}, {42, 0}, Side::Left, 5, 3));
            }),
            AlarmId::NoIntersectionCrc);
}

// G03 of radius exactly r on the tool side: its start point would sit on its centre.
TEST(CrcErrors, ArcEndOnCentreIsPS0038) {
  Sink r;
  straightIn(r);
  EXPECT_EQ(alarmOf([&] {
              r.comp.push(arc(Kind::Ccw, {50, 0}, {55, 5}, {50, 5}, Side::Left, 5, 3));
            }),
            AlarmId::InterferenceInCircular);
}

// A 3 mm wide, 3 mm deep groove with r=5: the bottom (50,-3)->(53,-3) compensates to
// (55,2)->(48,2), against its programmed direction.
TEST(CrcErrors, GrooveNarrowerThanCutterIsPS0041) {
  Sink r;
  straightIn(r);
  const Side L = Side::Left;
  r.comp.push(line({50, 0}, {50, -3}, L, 5, 3));
  r.comp.push(line({50, -3}, {53, -3}, L, 5, 4));
  int tag = 0;
  EXPECT_EQ(alarmOf(
                [&] {
                  r.comp.push(line({53, -3}, {53, 0}, L, 5, 5));
                },
                &tag),
            AlarmId::InterferenceInCrc);
  EXPECT_EQ(tag, 4);
}

// Seed 002 (Gribov & Milovzorov, face milling a 150x200 plane on a Fanuc 0i-MC): G42 with
// D = 25, passes along X 50 mm apart, the program in absolute coordinates:
//   N060 X-45 (Y50); N070 G1 G42 X80 D52; N080 Y0; N090 X0; N100 Y-50; N110 X150;
//   N120 Y-100; N130 X0; N140 Y-150; N150 X150; N160 Y-200; N170 X-50; N180 G0 Z200;
//   N190 G40 X0 Y110.
// The tool stays right of the direction of travel, so when the feed reverses along X the
// centre changes side of the programmed pass: N090 (Y0, -X) runs at Y25, N110 (Y-50, +X)
// and N130 (Y-100, -X) both at Y-75, N150 and N170 both at Y-175. The 50 mm steps N080,
// N120, N160 shrink to nothing (inner corners at both ends, 2r = 50), and the band
// -50 < Y < 0 between the passes at 25 and -75 stays uncut, as the paper says for a
// physical radius of Y/2. The start-up N070 meets N080 at an inner corner, so (type A or
// B) it ends perpendicular to N080 at (55,50): that pass keeps the programmed Y50.
TEST(CrcFaceMilling, Seed002PassesComeInPairs) {
  Sink r;
  const Side R = Side::Right;
  const double d = 25;
  r.comp.push(line({-50, 50}, {-45, 50}, Side::Off, 0, 60, true));
  r.comp.push(line({-45, 50}, {80, 50}, R, d, 70));
  r.comp.push(line({80, 50}, {80, 0}, R, d, 80));
  r.comp.push(line({80, 0}, {0, 0}, R, d, 90));
  r.comp.push(line({0, 0}, {0, -50}, R, d, 100));
  r.comp.push(line({0, -50}, {150, -50}, R, d, 110));
  r.comp.push(line({150, -50}, {150, -100}, R, d, 120));
  r.comp.push(line({150, -100}, {0, -100}, R, d, 130));
  r.comp.push(line({0, -100}, {0, -150}, R, d, 140));
  r.comp.push(line({0, -150}, {150, -150}, R, d, 150));
  r.comp.push(line({150, -150}, {150, -200}, R, d, 160));
  r.comp.push(line({150, -200}, {-50, -200}, R, d, 170));
  r.comp.pushNonMoving(180);  // G0 Z200: one non-moving block, the corner is still found
  r.comp.push(line({-50, -200}, {0, 110}, Side::Off, d, 190, true));
  ASSERT_EQ(r.segs.size(), 13u);
  // The start-up block meets N080 at an inner corner: it ends at the intersection, so the
  // first pass already runs at Y 25 (the paper's pair 25, 25 with N090).
  expectSeg(r.segs[1], 70, {-45, 50}, {55, 25});
  expectSeg(r.segs[2], 80, {55, 25}, {55, 25});
  expectSeg(r.segs[3], 90, {55, 25}, {-25, 25});
  expectSeg(r.segs[4], 100, {-25, 25}, {-25, -75});
  expectSeg(r.segs[5], 110, {-25, -75}, {125, -75});
  expectSeg(r.segs[6], 120, {125, -75}, {125, -75});
  expectSeg(r.segs[7], 130, {125, -75}, {-25, -75});
  expectSeg(r.segs[8], 140, {-25, -75}, {-25, -175});
  expectSeg(r.segs[9], 150, {-25, -175}, {125, -175});
  expectSeg(r.segs[10], 160, {125, -175}, {125, -175});
  expectSeg(r.segs[11], 170, {125, -175}, {-50, -175});  // inner corner with the G40 block
  expectSeg(r.segs[12], 190, {-50, -175}, {0, 110});
  // The X passes in offset mode, in pairs at the same compensated Y.
  std::vector<double> passY;
  for (size_t i : {3u, 5u, 7u, 9u, 11u}) {
    EXPECT_NEAR(r.segs[i].start.v, r.segs[i].end.v, kTol);
    passY.push_back(r.segs[i].end.v);
  }
  EXPECT_NEAR(r.segs[1].end.v, passY[0], kTol);  // N070 and N090: Y 25, 25
  EXPECT_NEAR(passY[1], passY[2], kTol);         // N110 and N130: Y -75, -75
  EXPECT_NEAR(passY[3], passY[4], kTol);         // N150 and N170: Y -175, -175
  EXPECT_NEAR(passY[0] - passY[1], 100, kTol);   // a 2*25 band between 0 and -50 stays uncut
}

// suspend() (lathe cycles start from their programmed start point): the held start-up block
// ends on its programmed point with no vector, and the next compensated block starts up again.
TEST(CrcSuspend, HeldStartupEndsOnItsProgrammedPoint) {
  Sink k;
  k.comp.push(line({50, 30}, {2, 20}, Side::Right, 0.8, 1, true));
  EXPECT_TRUE(k.segs.empty());  // held: the corner needs the next block
  k.comp.suspend();
  ASSERT_EQ(k.segs.size(), 1u);
  expectSeg(k.segs[0], 1, {50, 30}, {2, 20});
  EXPECT_FALSE(k.segs[0].vectorAtEnd);
  EXPECT_FALSE(k.comp.active());
  // A new start-up from the programmed point: (2,20) -> (0,20) along -u, then -u again, G42
  // r = 0.8: the vector at its end is perpendicular to the next block, (0, 20.8).
  k.comp.push(line({2, 20}, {0, 20}, Side::Right, 0.8, 2));
  k.comp.push(line({0, 20}, {-10, 20}, Side::Right, 0.8, 3));
  ASSERT_EQ(k.segs.size(), 2u);
  expectSeg(k.segs[1], 2, {2, 20}, {0, 20.8});
  EXPECT_TRUE(k.segs[1].vectorAtEnd);
}

// A held arc keeps its radius: it ends perpendicular, then a straight move removes the vector.
TEST(CrcSuspend, HeldArcEndsPerpendicularThenDropsTheVector) {
  Sink k;
  k.comp.push(line({0, -10}, {0, 0}, Side::Left, 1, 1));
  // G02 around (10,0) from (0,0) over (10,10) to (20,0): it starts along +v like the
  // start-up (tangent, so the start-up ends perpendicular at (-1,0)); left of the travel is
  // away from the centre: radius 10 + 1.
  k.comp.push(arc(Kind::Cw, {0, 0}, {20, 0}, {10, 0}, Side::Left, 1, 2));
  k.comp.suspend();
  ASSERT_EQ(k.segs.size(), 3u);
  // The arc ends on radius 11 at (21, 0), then the tool moves to (20, 0).
  expectSeg(k.segs[0], 1, {0, -10}, {-1, 0});
  expectSeg(k.segs[1], 2, {-1, 0}, {21, 0}, Kind::Cw);
  expectSeg(k.segs[2], 2, {21, 0}, {20, 0});
  EXPECT_FALSE(k.segs[2].vectorAtEnd);
}
