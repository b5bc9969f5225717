// Mirror, scaling and rotation (src/motion/transform.hpp) and the chamfer/corner geometry
// (src/motion/corner_round.hpp). Expected values are worked out by hand in the comments.
#include "motion/transform.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "motion/corner_round.hpp"

using namespace ncvm;

namespace {
constexpr double kTol = 1e-9;

void expectNear(const xform::P3& got, const xform::P3& want) {
  for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], kTol) << "axis " << k;
}
}  // namespace

TEST(Transform, RotationTurnsCounterClockwiseAboutTheCentre) {
  xform::Transform t;
  t.setRotation(17, 10, 10, 90);
  // (20,10): 10 to the right of the centre -> 10 above it.
  expectNear(t.apply({20, 10, 5}), {10, 20, 5});
  expectNear(t.invert({10, 20, 5}), {20, 10, 5});
  EXPECT_FALSE(t.flips(17));
}

TEST(Transform, RotationInG18TurnsZTowardsX) {
  xform::Transform t;
  t.setRotation(18, 0, 0, 90);  // the G18 plane is (u, v) = (Z, X)
  expectNear(t.apply({0, 0, 10}), {10, 0, 0});
}

TEST(Transform, OrderIsMirrorThenScalingThenRotation) {
  xform::Transform t;
  t.mirror[0] = true;  // G51.1 X0
  t.scaling = true;    // G51 X0 Y0 P2
  t.scale = {2, 2, 2};
  t.setRotation(17, 0, 0, 90);  // a mirrored plane turns the other way
  // (10,5): mirror (-10,5), scale (-20,10), rotate -90 -> (10,20) = mirror(scale(rotate(p))).
  expectNear(t.apply({10, 5, 0}), {10, 20, 0});
  expectNear(t.invert({10, 20, 0}), {10, 5, 0});
  EXPECT_TRUE(t.flips(17));
  EXPECT_TRUE(t.flips(18));   // X is in G18 too
  EXPECT_FALSE(t.flips(19));  // Y Z untouched
}

TEST(Transform, RotationCentreIsScaled) {
  xform::Transform t;
  t.scaling = true;
  t.scale = {2, 2, 1};
  t.setRotation(17, 5, 0, 180);  // the centre (5,0) becomes (10,0)
  // (10,0) scaled (20,0), turned 180 about (10,0) -> (0,0).
  expectNear(t.apply({10, 0, 0}), {0, 0, 0});
}

TEST(Transform, NegativeScaleFactorReflects) {
  xform::Transform t;
  t.scaling = true;
  t.scale = {-1, 1, 1};
  t.scaleAt = {10, 0, 0};
  expectNear(t.apply({15, 3, 0}), {5, 3, 0});
  EXPECT_TRUE(t.flips(17));
  xform::Transform both = t;
  both.mirror[1] = true;  // two reflections in the plane keep the sense of turning
  EXPECT_FALSE(both.flips(17));
}

TEST(Transform, VectorsIgnoreCentres) {
  xform::Transform t;
  t.setRotation(17, 100, 100, 90);
  expectNear(t.applyVector({1, 0, 0}), {0, 1, 0});
}

TEST(CornerRound, ChamferBetweenLines) {
  cornerw::Seg a{cornerw::Kind::Line, {0, 0}, {50, 0}, {}};
  cornerw::Seg b{cornerw::Kind::Line, {50, 0}, {50, 50}, {}};
  cornerw::Corner c = cornerw::place(a, b, true, 5);
  EXPECT_NEAR(c.endA.u, 45, kTol);
  EXPECT_NEAR(c.endA.v, 0, kTol);
  EXPECT_NEAR(c.startB.u, 50, kTol);
  EXPECT_NEAR(c.startB.v, 5, kTol);
  EXPECT_FALSE(c.arc);
}

TEST(CornerRound, RoundingARightTurnIsClockwise) {
  // +Y then +X turns right: the arc centre is 4 to the right of both lines, at (4,6).
  cornerw::Seg a{cornerw::Kind::Line, {0, 0}, {0, 10}, {}};
  cornerw::Seg b{cornerw::Kind::Line, {0, 10}, {20, 10}, {}};
  cornerw::Corner c = cornerw::place(a, b, false, 4);
  EXPECT_TRUE(c.arc);
  EXPECT_EQ(c.kind, cornerw::Kind::Cw);
  EXPECT_NEAR(c.center.u, 4, kTol);
  EXPECT_NEAR(c.center.v, 6, kTol);
  EXPECT_NEAR(c.endA.v, 6, kTol);
  EXPECT_NEAR(c.startB.u, 4, kTol);
}

TEST(CornerRound, ChamferOnAnArcIsAChordDistance) {
  // Line +X to (10,0), then a G03 quarter circle about (10,10) from (10,0) to (20,10):
  // tangent, so nothing to insert.
  cornerw::Seg a{cornerw::Kind::Line, {0, 0}, {10, 0}, {}};
  cornerw::Seg b{cornerw::Kind::Ccw, {10, 0}, {20, 10}, {10, 10}};
  EXPECT_TRUE(cornerw::place(a, b, true, 2).none);
  // A CW arc about (10,-10) leaves (10,0) along +X as well: tangent too.
  cornerw::Seg a2{cornerw::Kind::Line, {0, 0}, {10, 0}, {}};
  cornerw::Seg b2{cornerw::Kind::Cw, {10, 0}, {20, -10}, {10, -10}};
  cornerw::Corner c = cornerw::place(a2, b2, true, 2);
  EXPECT_TRUE(c.none);
  // Line +Y from (10,-10) to (10,0), then the G03 arc: a right-angle corner. The chamfer
  // point on the arc is 2 from (10,0) and 10 from (10,10): v = 0.2, u = 10 + sqrt(3.96).
  cornerw::Seg a3{cornerw::Kind::Line, {10, -10}, {10, 0}, {}};
  c = cornerw::place(a3, b, true, 2);
  EXPECT_NEAR(c.endA.u, 10, kTol);
  EXPECT_NEAR(c.endA.v, -2, kTol);
  EXPECT_NEAR(c.startB.v, 0.2, kTol);
  EXPECT_NEAR(c.startB.u, 10 + std::sqrt(3.96), kTol);
}

TEST(CornerRound, TooLargeIsPs0055) {
  cornerw::Seg a{cornerw::Kind::Line, {0, 0}, {10, 0}, {}};
  cornerw::Seg b{cornerw::Kind::Line, {10, 0}, {10, 50}, {}};
  try {
    cornerw::place(a, b, true, 15);
    FAIL() << "no alarm";
  } catch (const cornerw::CornerError& e) {
    EXPECT_EQ(e.id, AlarmId::ChamferMoveTooShort);
  }
  EXPECT_THROW(cornerw::place(a, b, false, 12), cornerw::CornerError);  // needs 12 on each leg
}
