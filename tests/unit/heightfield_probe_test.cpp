#include "sim/heightfield_probe.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "app/session.hpp"
#include "sim/lathe_probe.hpp"

using namespace ncvm;

namespace {

// The reference: the distance from p to the nearest column, by visiting every cell.
double columnsDistance(const HeightField& f, const Vec3& p) {
  double best = 1e300;
  for (int j = 0; j < f.ny(); ++j) {
    for (int i = 0; i < f.nx(); ++i) {
      double lo[3] = {f.x0() + i * f.cell(), f.y0() + j * f.cell(), f.bottom()};
      double hi[3] = {lo[0] + f.cell(), lo[1] + f.cell(), f.at(i, j)};
      if (hi[2] <= lo[2]) continue;
      double s = 0;
      for (size_t k = 0; k < 3; ++k) {
        double d = std::max({lo[k] - p[k], 0.0, p[k] - hi[k]});
        s += d * d;
      }
      best = std::min(best, std::sqrt(s));
    }
  }
  return best;
}

Vec3 lerp(const Vec3& a, const Vec3& b, double t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

// A 60 x 60 mm block, top Z0, bottom Z-20, with a bore of radius R cut 10 deep around
// (cx, cy): every cell whose centre lies in the circle, as the mill simulation cuts them.
HeightField boreField(double cell, double cx, double cy, double R) {
  HeightField f = HeightField::covering(-30, -30, 30, 30, cell, 0.0f);
  f.setBottom(-20);
  for (int j = 0; j < f.ny(); ++j)
    for (int i = 0; i < f.nx(); ++i)
      if (std::hypot(f.cellX(i) - cx, f.cellY(j) - cy) <= R) f.at(i, j) = -10;
  return f;
}

}  // namespace

TEST(HeightFieldProbe, DropsOntoTheTopFace) {
  HeightField f(0, 0, 0.05, 200, 200, 0.0f);
  f.setBottom(-20);
  // The ball centre stops 2 above the top: Z10 -> Z2 of Z10 -> Z-10.
  auto t = heightFieldFirstContact(f, {5.01, 4.99, 10}, {5.01, 4.99, -10}, 2);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 0.4, 1e-12);
}

TEST(HeightFieldProbe, MissesWhatIsNotThere) {
  HeightField f(0, 0, 0.05, 200, 200, 0.0f);
  f.setBottom(-20);
  EXPECT_FALSE(heightFieldFirstContact(f, {1, 1, 2.5}, {9, 9, 2.5}, 2));      // above the top
  EXPECT_FALSE(heightFieldFirstContact(f, {-5, 1, -5}, {-5, 9, -5}, 2));      // beside the block
  EXPECT_FALSE(heightFieldFirstContact(f, {1, 1, -25}, {9, 9, -25}, 2));      // under it
  EXPECT_FALSE(heightFieldFirstContact(f, {-2.5, 5, -1}, {-2.5, 5, -1}, 2));  // no motion
}

TEST(HeightFieldProbe, StartInContactIsZero) {
  HeightField f(0, 0, 0.05, 200, 200, 0.0f);
  f.setBottom(-20);
  auto t = heightFieldFirstContact(f, {5, 5, 1.5}, {5, 5, 10}, 2);
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, 0.0);
}

TEST(HeightFieldProbe, CutMaterialIsGone) {
  // Down the middle of a cut bore the ball reaches the floor, not the old top.
  HeightField f = boreField(0.05, 0.37, -0.21, 15);
  auto t = heightFieldFirstContact(f, {0.37, -0.21, 5}, {0.37, -0.21, -15}, 2);
  ASSERT_TRUE(t);
  EXPECT_NEAR(5 - 20 * *t, -8.0, 1e-6);  // floor -10 plus the radius
}

TEST(HeightFieldProbe, BoreWallWithinHalfACell) {
  // Along X and Y, both ways, at mid-depth: the contact is within half a cell of the true
  // wall (R - r from the axis) and the centre from opposite contacts is within half a cell.
  for (double cell : {0.05, 0.2}) {
    const double cx = 0.37, cy = -0.21, R = 15, r = 2;
    HeightField f = boreField(cell, cx, cy, R);
    double contact[4];
    const double dir[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (int k = 0; k < 4; ++k) {
      Vec3 a{cx, cy, -5}, b{cx + 20 * dir[k][0], cy + 20 * dir[k][1], -5};
      auto t = heightFieldFirstContact(f, a, b, r);
      ASSERT_TRUE(t);
      contact[k] = 20 * *t;  // distance from the axis
      EXPECT_NEAR(contact[k], R - r, cell / 2 + 1e-9) << "cell " << cell << " direction " << k;
    }
    EXPECT_NEAR((contact[0] - contact[1]) / 2, 0, cell / 2 + 1e-9);
    EXPECT_NEAR((contact[2] - contact[3]) / 2, 0, cell / 2 + 1e-9);
  }
}

TEST(HeightFieldProbe, ExactAgainstTheColumns) {
  // Random heights and random segments (any direction, edges and corners included): at the
  // contact the ball is r from the nearest column, and nowhere before it closer.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> height(-3, 0), xy(-1, 5), z(-4, 2), radius(0, 1.2);
  HeightField f(0, 0, 0.25, 16, 16, 0.0f);
  f.setBottom(-3.5);
  for (int j = 0; j < f.ny(); ++j)
    for (int i = 0; i < f.nx(); ++i) f.at(i, j) = static_cast<float>(height(rng));
  int hits = 0, checked = 0;
  for (int n = 0; n < 120; ++n) {
    Vec3 a{xy(rng), xy(rng), z(rng) + 3}, b{xy(rng), xy(rng), z(rng)};
    double r = radius(rng);
    if (columnsDistance(f, a) <= r) continue;  // starts in contact: covered above
    ++checked;
    auto t = heightFieldFirstContact(f, a, b, r);
    double end = t ? *t : 1.0;
    if (t) {
      ++hits;
      EXPECT_NEAR(columnsDistance(f, lerp(a, b, *t)), r, 1e-9) << "segment " << n;
    }
    for (int s = 0; s < 100; ++s) {
      double u = end * s / 100.0;
      ASSERT_GT(columnsDistance(f, lerp(a, b, u)), r - 1e-9) << "segment " << n << " at " << u;
    }
    if (!t) {
      EXPECT_GT(columnsDistance(f, b), r) << "segment " << n;
    }
  }
  EXPECT_GT(hits, 30);
  EXPECT_GT(checked - hits, 5);
}

// ---- probe.use_stock in a run -------------------------------------------------------------

namespace {
Session::Result runWith(const std::string& setupText, const std::string& program) {
  Session s(parseSetup(setupText, "setup.toml"));
  s.addProgramText(program, "t.nc");
  return s.run(nullptr);
}
}  // namespace

TEST(ProbeUseStock, MissingStockIsASetupError) {
  const std::string prog = "O1\nG31 X10. F100.\nM30\n";
  EXPECT_THROW(runWith("[machine]\nkind = \"mill\"\n[probe]\nuse_stock = true\n", prog),
               SetupError);
  EXPECT_THROW(runWith("[machine]\nkind = \"lathe\"\n[probe]\nuse_stock = true\n", prog),
               SetupError);
}

TEST(ProbeUseStock, SolidsAndStockFirstContactWins) {
  // A box solid at X20 and the stock block from X10: the stock is met first; with the solid
  // nearer, the solid is.
  const std::string stock =
      "[machine]\nkind = \"mill\"\n[probe]\nball_diameter = 2.0\nuse_stock = true\n"
      "[stock]\nmin = [10.0, -5.0, -10.0]\nmax = [30.0, 5.0, 0.0]\ncell = 0.1\n";
  const std::string prog = "O1\nG90 G00 Z-5.\nG31 X40. F100.\n#100=#5061\nM30\n";
  auto far = runWith(
      stock + "[[solids]]\nkind = \"box\"\nmin = [20.0, -5.0, -10.0]\nmax = [30.0, 5.0, 0.0]\n",
      prog);
  EXPECT_NEAR(far.state["vars"]["#100"].get<double>(), 9.0, 1e-9);
  auto near = runWith(
      stock + "[[solids]]\nkind = \"box\"\nmin = [5.0, -5.0, -10.0]\nmax = [6.0, 5.0, 0.0]\n",
      prog);
  EXPECT_NEAR(near.state["vars"]["#100"].get<double>(), 4.0, 1e-9);
  // The stock analysis is there although simulateStock was not asked for.
  EXPECT_EQ(near.state["stock"]["kind"], "mill");
}

// ---- the lathe half-profile -------------------------------------------------------------

TEST(ProfileProbe, BarFaceAndDiameter) {
  // A bar of radius 25 from Z0 back to Z-80 with a step to radius 20 over Z0..Z-30, as the
  // lathe stock keeps it (X = z, Y = radius, 1e6 units per mm).
  const double k = 1e6;
  auto pt = [&](double z, double r) {
    return ClipperLib::IntPoint(static_cast<ClipperLib::cInt>(z * k),
                                static_cast<ClipperLib::cInt>(r * k));
  };
  ClipperLib::Paths paths{{pt(0, 0), pt(0, 20), pt(-30, 20), pt(-30, 25), pt(-80, 25), pt(-80, 0)}};
  ProfileProbe p(paths, k);
  EXPECT_NEAR(p.distance(10, 5), 5, 1e-12);
  EXPECT_NEAR(p.distance(10, -5), -5, 1e-12);
  // Radially in at Z-10: the ball (r 1) touches the Ø40 step at radius 21.
  auto t = p.firstContact({40, 0, -10}, {0, 0, -10}, 1);
  ASSERT_TRUE(t);
  EXPECT_NEAR(40 - 40 * *t, 21, 1e-6);
  // Off the axis plane (Y10): contact where hypot(x, 10) = 21.
  t = p.firstContact({40, 10, -10}, {0, 10, -10}, 1);
  ASSERT_TRUE(t);
  EXPECT_NEAR(40 - 40 * *t, std::sqrt(21.0 * 21 - 100), 1e-6);
  // Along Z at radius 22: past the step's front, onto the shoulder at Z-30.
  t = p.firstContact({22, 0, 10}, {22, 0, -50}, 1);
  ASSERT_TRUE(t);
  EXPECT_NEAR(10 - 60 * *t, -29, 1e-6);
  // At radius 27 nothing is in the way.
  EXPECT_FALSE(p.firstContact({27, 0, 10}, {27, 0, -90}, 1));
}
