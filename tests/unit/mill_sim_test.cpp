// The mill stock kernel: exact envelopes of the swept tools, threads, contacts, analysis.
#include "sim/mill_sim.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>

#include "report/mill_pictures.hpp"
#include "report/stl_writer.hpp"
#include "sim/mill_analysis.hpp"
#include "sim/mill_sweep.hpp"

namespace ncvm {
namespace {

MillTool tool(const char* type, double d, double corner = 0, double angle = 118) {
  ToolSpec s;
  s.type = type;
  s.diameter = d;
  s.cornerRadius = corner;
  s.pointAngle = angle;
  return millToolFromSpec(s, 1);
}

// The envelope by brute force: the tool placed at many points along the segment.
double bruteEnvelope(const MillTool& t, const Point3& a, const Point3& b, double x, double y,
                     int steps = 5000) {
  double best = 1e30;
  for (int k = 0; k <= steps; ++k) {
    double u = static_cast<double>(k) / steps;
    double px = a[0] + u * (b[0] - a[0]), py = a[1] + u * (b[1] - a[1]),
           pz = a[2] + u * (b[2] - a[2]);
    double r = std::hypot(x - px, y - py);
    if (r <= t.radius) best = std::min(best, pz + t.profile(r));
  }
  return best;
}

TEST(MillSweep, FlatFloorIsExactAndWallsWithinHalfACell) {
  HeightField f(0, 0, 0.05, 800, 400, 0.0f);  // 40 x 20 mm
  MillTool t = tool("flat", 6);
  sweepLine(f, t, {10, 10, -1.234}, {30, 10, -1.234});
  for (int j = 0; j < f.ny(); j += 3)
    for (int i = 0; i < f.nx(); i += 3) {
      double x = f.cellX(i), y = f.cellY(j);
      double dx = x < 10 ? 10 - x : (x > 30 ? x - 30 : 0), d = std::hypot(dx, y - 10);
      if (d <= 3 - 1e-6) {
        ASSERT_NEAR(f.at(i, j), -1.234, 1e-6) << x << " " << y;
      }
      if (d > 3 + 1e-6) {
        ASSERT_EQ(f.at(i, j), 0.0f) << x << " " << y;
      }
    }
  // The wall at y = 13 lies between the last cut and the first uncut cell centre.
  int i = 400;
  int jCut = -1;
  for (int j = 0; j < f.ny(); ++j)
    if (f.at(i, j) < 0) jCut = j;
  EXPECT_LE(f.cellY(jCut), 13.0);
  EXPECT_GT(f.cellY(jCut + 1), 13.0);
  EXPECT_LT(13.0 - f.cellY(jCut), f.cell());
}

TEST(MillSweep, BallOnAFlatMoveFollowsTheSphere) {
  HeightField f(0, 0, 0.05, 400, 400, 5.0f);
  MillTool t = tool("ball", 6);
  sweepLine(f, t, {5, 10, 0}, {15, 10, 0});
  for (int j = 0; j < f.ny(); j += 7) {
    double d = std::abs(f.cellY(j) - 10);
    double want = d <= 3 ? 3 - std::sqrt(9 - d * d) : 5.0;
    EXPECT_NEAR(f.at(200, j), std::min(want, 5.0), 2e-5) << d;
  }
}

void expectMatchesBrute(const MillTool& t, const Point3& a, const Point3& b, double tol) {
  HeightField f(-5, -5, 0.1, 200, 200, 10.0f);
  sweepLine(f, t, a, b);
  int checked = 0;
  for (int j = 0; j < f.ny(); j += 7)
    for (int i = 0; i < f.nx(); i += 7) {
      double want = std::min(10.0, bruteEnvelope(t, a, b, f.cellX(i), f.cellY(j)));
      ASSERT_NEAR(f.at(i, j), want, tol) << f.cellX(i) << " " << f.cellY(j);
      if (want < 10) ++checked;
    }
  EXPECT_GT(checked, 40);
}

TEST(MillSweep, SlopedMovesMatchTheToolPlacedAlongThePath) {
  const Point3 a{0, 0, 2}, b{8, 5, -1.5};
  expectMatchesBrute(tool("ball", 6), a, b, 2e-3);
  expectMatchesBrute(tool("flat", 6), a, b, 2e-3);
  expectMatchesBrute(tool("bull", 8, 1.5), a, b, 2e-3);
  expectMatchesBrute(tool("drill", 5, 0, 118), a, b, 2e-3);
  expectMatchesBrute(tool("ball", 6), b, a, 2e-3);  // climbing
  expectMatchesBrute(tool("flat", 6), b, a, 2e-3);
  expectMatchesBrute(tool("ball", 6), {3, 3, 4}, {3, 3, -2}, 1e-4);  // plunge
}

TEST(MillSweep, ArcMatchesAFineChainOfLines) {
  MillTool t = tool("ball", 4);
  HeightField arc(-20, -20, 0.1, 400, 400, 5.0f), chain = arc;
  const double cx = 1, cy = -2, ra = 10, a0 = 0.3, sweep = -4.0;
  sweepArcXY(arc, t, cx, cy, ra, a0, sweep, -0.5);
  int n = 4000;
  for (int k = 0; k < n; ++k) {
    double u0 = a0 + sweep * k / n, u1 = a0 + sweep * (k + 1) / n;
    sweepLine(chain, t, {cx + ra * std::cos(u0), cy + ra * std::sin(u0), -0.5},
              {cx + ra * std::cos(u1), cy + ra * std::sin(u1), -0.5});
  }
  double worst = 0;
  for (size_t k = 0; k < arc.data().size(); ++k)
    worst = std::max(worst, double(std::abs(arc.data()[k] - chain.data()[k])));
  EXPECT_LT(worst, 1e-3);
  // The arc's start (angle 0.3) is cut down to the tip; the centre is not.
  int i = static_cast<int>((cx + ra * std::cos(a0) + 20) / 0.1);
  int j = static_cast<int>((cy + ra * std::sin(a0) + 20) / 0.1);
  EXPECT_NEAR(arc.at(i, j), -0.5, 0.01);
  EXPECT_EQ(arc.at(210, 180), 5.0f);
}

// A large-radius arc (the centre 400 mm away, outside the stock): the kernel works relative
// to a point on the arc, so floors stay exact and the ball's surface matches the chain.
TEST(MillSweep, LargeRadiusArcKeepsMicrometres) {
  const double cx = 20, cy = -390, ra = 400, a0 = M_PI / 2 + 0.03, sweep = -0.06;
  MillTool ball = tool("ball", 6), flat = tool("flat", 6);
  HeightField arc(0, 0, 0.05, 800, 400, 5.0f), chain = arc, floor = arc;
  sweepArcXY(arc, ball, cx, cy, ra, a0, sweep, -0.5);
  sweepArcXY(floor, flat, cx, cy, ra, a0, sweep, -1.234);
  const int n = 2000;
  for (int k = 0; k < n; ++k) {
    double u0 = a0 + sweep * k / n, u1 = a0 + sweep * (k + 1) / n;
    sweepLine(chain, ball, {cx + ra * std::cos(u0), cy + ra * std::sin(u0), -0.5},
              {cx + ra * std::cos(u1), cy + ra * std::sin(u1), -0.5});
  }
  double worst = 0;
  int floorCells = 0;
  for (int j = 0; j < arc.ny(); ++j)
    for (int i = 0; i < arc.nx(); ++i) {
      worst = std::max(worst, double(std::abs(arc.at(i, j) - chain.at(i, j))));
      double x = arc.cellX(i) - cx, y = arc.cellY(j) - cy;
      double ang = std::atan2(y, x), dist = std::abs(std::hypot(x, y) - ra);
      if (ang > a0 + sweep + 1e-3 && ang < a0 - 1e-3 && dist < 2.9) {
        ASSERT_NEAR(floor.at(i, j), -1.234, 1e-6) << arc.cellX(i) << " " << arc.cellY(j);
        ++floorCells;
        // The ball's sphere in double: within a few float steps (a kernel in float relative
        // to the far centre would be off by ~5e-5 here).
        if (dist < 2.5) {
          ASSERT_NEAR(arc.at(i, j), -0.5 + 3 - std::sqrt(9 - dist * dist), 3e-6);
        }
      }
      if (dist > 3.01) {
        ASSERT_EQ(floor.at(i, j), 5.0f);
      }
    }
  EXPECT_GT(floorCells, 1000);
  EXPECT_LT(worst, 1e-3);  // the chain's sagitta (24 m / 2000 pieces: 0.7 um) and float
}

// startCut is a promise that the tool at the start point was cut already: the kernel then
// leaves out the cells where the start is the move's lowest point. On a fresh block those
// cells stay uncut, which shows the skip happens and where.
TEST(MillSweep, StartCutSkipsOnlyWhereTheStartIsLowest) {
  MillTool ball = tool("ball", 6);
  // Rising move along +X from (10, 10): behind x = 10 the start sphere is lowest.
  HeightField f(0, 0, 0.05, 400, 400, 5.0f);
  sweepLine(f, ball, {10, 10, 0}, {10.25, 10, 0.02}, {}, SweepMode::Cut, true);
  auto at = [&](double x, double y) {
    return f.at(static_cast<int>(x / 0.05), static_cast<int>(y / 0.05));
  };
  EXPECT_EQ(at(9.0, 10.0), 5.0f);   // behind the start: skipped
  EXPECT_LT(at(10.5, 10.0), 1.0f);  // ahead: cut
  // Descending ball, slope dz/L = -0.4: cells more than 0.4 r = 1.2 mm behind are skipped,
  // nearer ones are cut where the move goes lower than the start.
  HeightField g(0, 0, 0.05, 400, 400, 5.0f);
  sweepLine(g, ball, {10, 10, 0}, {10.25, 10, -0.1}, {}, SweepMode::Cut, true);
  EXPECT_EQ(g.at(static_cast<int>(8.5 / 0.05), 200), 5.0f);
  EXPECT_LT(g.at(static_cast<int>(9.6 / 0.05), 200), 5.0f);
  // A flat end mill going down: no cell behind is safe to skip.
  HeightField h(0, 0, 0.05, 400, 400, 5.0f);
  sweepLine(h, tool("flat", 6), {10, 10, 0}, {10.25, 10, -0.1}, {}, SweepMode::Cut, true);
  EXPECT_LT(h.at(static_cast<int>(7.5 / 0.05), 200), 0.0f);
}

// Chains of moves, each continuing the one before, cut the same stock with and without the
// skip, for every tool shape and for rising, level, falling and steep moves in all directions.
TEST(MillSweep, StartCutGivesTheSameStockOnChainsOfMoves) {
  const MillTool tools[] = {tool("ball", 6), tool("flat", 6), tool("bull", 8, 1.5),
                            tool("drill", 5, 0, 118)};
  for (const MillTool& t : tools) {
    HeightField plain(0, 0, 0.1, 250, 250, 2.0f), skip = plain;
    Point3 p{12.5, 12.5, 0};
    uint32_t seed = 12345;
    auto next = [&seed] {
      seed = seed * 1664525u + 1013904223u;
      return static_cast<double>(seed >> 8) / 16777216.0;  // [0, 1)
    };
    for (int k = 0; k < 100; ++k) {
      double ang = 6.283185307179586 * next(), len = 0.05 + 0.6 * next();
      double dz = (next() - 0.5) * (k % 7 == 0 ? 4.0 : 0.4) * len;  // some steep moves
      if (k % 11 == 0) dz = 0;
      Point3 q{std::clamp(p[0] + len * std::cos(ang), 3.0, 22.0),
               std::clamp(p[1] + len * std::sin(ang), 3.0, 22.0), std::clamp(p[2] + dz, -3.0, 1.0)};
      sweepLine(plain, t, p, q);
      sweepLine(skip, t, p, q, {}, SweepMode::Cut, k > 0);
      p = q;
    }
    double worst = 0;
    for (size_t k = 0; k < plain.data().size(); ++k)
      worst = std::max(worst, double(std::abs(plain.data()[k] - skip.data()[k])));
    // Float noise only: at the rim of a flat bottom both ways round the entry point of the
    // disc differently (1e-5 mm seen), far below the kernel's 1 um accuracy.
    EXPECT_LT(worst, 1e-4) << static_cast<int>(t.kind);
  }
}

// MillSim passes startCut only when a move starts where the one before ended with the same
// tool: its stock equals the kernel's without the skip.
TEST(MillSim, ContinuedMovesCutTheSameStockAsSeparateOnes) {
  MillTool t = tool("ball", 6), other = tool("ball", 2);
  HeightField base(0, 0, 0.1, 300, 300, 0.0f), plain = base;
  MillSim sim(base, 1);
  auto both = [&](const MillTool& tl, const Point3& a, const Point3& b) {
    sim.setTool(&tl);
    sim.line(a, b, false, 0);
    sweepLine(plain, tl, a, b);
  };
  Point3 p{5, 5, -0.2};
  for (int k = 0; k < 300; ++k) {
    Point3 q{p[0] + 0.3, p[1] + (k % 50 == 49 ? 0.4 : 0.0), -0.5 - 0.4 * std::sin(p[0])};
    // A tool change in the middle of the chain: the small ball does not continue the big one.
    both(k == 150 ? other : t, p, q);
    if (q[0] > 25) q[0] = 5;  // jump back: the next move does not continue this one
    p = q;
  }
  double worst = 0;
  for (size_t k = 0; k < plain.data().size(); ++k)
    worst = std::max(worst, double(std::abs(plain.data()[k] - sim.field().data()[k])));
  EXPECT_LT(worst, 1e-5);
}

TEST(MillSim, ThreadsGiveTheSameStockAsOneThread) {
  MillTool t = tool("ball", 6);
  HeightField base(0, 0, 0.1, 300, 300, 0.0f);
  MillSim one(base, 1), two(base, 2);
  for (auto* s : {&one, &two}) {
    s->setTool(&t);
    for (int k = 0; k < 600; ++k) {
      double x = 2 + (k % 100) * 0.26, y = 3 + (k / 100) * 3.5, z = -0.5 - 0.3 * std::sin(x);
      s->line({x, y, z}, {x + 0.26, y, -0.5 - 0.3 * std::sin(x + 0.26)}, false, 0);
    }
  }
  ASSERT_EQ(two.threads(), 2);
  EXPECT_EQ(one.field().data(), two.field().data());
}

TEST(MillSim, RapidIntoTheStockIsACollisionWithItsTag) {
  MillTool t = tool("flat", 10);
  MillSim s(HeightField(0, 0, 0.1, 500, 500, 0.0f), 2);
  s.setTool(&t);
  s.line({-10, 25, 5}, {60, 25, 5}, true, 1);        // above: no contact
  s.line({-10, 25, -1}, {60, 25, -1}, false, 2);     // cut: feed
  s.line({60, 25, -1}, {-10, 25, -1}, true, 3);      // back along the slot: no contact
  s.line({-10, 40, -0.5}, {20, 40, -0.5}, true, 4);  // through material: collision
  const auto& c = s.contacts();
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].tag, 4u);
  EXPECT_EQ(c[0].kind, MillContact::Rapid);
  EXPECT_NEAR(c[0].depth, 0.5, 1e-6);
}

TEST(MillSim, HolderAndShankContacts) {
  ToolSpec spec;
  spec.type = "flat";
  spec.diameter = 6;
  spec.fluteLength = 5;
  spec.length = 60;
  spec.holderLength = 40;  // holder face 20 above the tip
  spec.holderDiameter = 30;
  MillTool t = millToolFromSpec(spec, 7);
  EXPECT_DOUBLE_EQ(t.holderZ, 20);
  MillSim s(HeightField(0, 0, 0.1, 500, 500, 0.0f), 1);
  s.setTool(&t);
  s.line({10, 10, -4}, {40, 10, -4}, false, 1);   // flutes deep enough: fine
  s.line({10, 20, -8}, {40, 20, -8}, false, 2);   // 3 mm of shank in the material
  s.line({5, 45, -25}, {5, 45, -25}, false, 3);   // plunge 25 deep: holder 5 mm into the stock
  s.arcXY(25, 40, 5, 0, M_PI, -7, -7, false, 4);  // half circle 2 mm of shank deep
  std::map<std::pair<uint32_t, int>, float> got;
  for (const auto& c : s.contacts()) got[{c.tag, c.kind}] = c.depth;
  EXPECT_EQ(got.count({1, MillContact::Shank}), 0u);
  float shank = got[{2, MillContact::Shank}], holder = got[{3, MillContact::Holder}];
  EXPECT_NEAR(shank, 3, 1e-5);
  float arcShank = got[{4, MillContact::Shank}];
  EXPECT_NEAR(arcShank, 2, 1e-5);
  EXPECT_NEAR(holder, 5, 1e-5);
}

TEST(MillSim, HelixCutsTheRampedCircle) {
  MillTool t = tool("flat", 4);
  MillSim s(HeightField(-10, -10, 0.05, 400, 400, 0.0f), 1);
  s.setTool(&t);
  s.arcXY(0, 0, 5, 0, 2 * M_PI, 0, -2, false, 0);
  const HeightField& f = s.field();
  // At angle 0 the tool is at z 0 then -2 after a full turn: the lowest is there.
  int i = static_cast<int>((5 + 10) / 0.05), j = static_cast<int>(10 / 0.05);
  EXPECT_NEAR(f.at(i, j), -2.0, 2e-3);
  // At x = -5 the tool last covers the cell 2 asin(0.2) past half a turn: z = -1.1282.
  int i2 = static_cast<int>((-5 + 10) / 0.05);
  EXPECT_NEAR(f.at(i2, j), -2 * (M_PI + 2 * std::asin(0.2)) / (2 * M_PI), 0.005);
}

TEST(MillAnalysis, FacePassUncutAreaAndBands) {
  HeightField f(0, 0, 0.1, 200, 100, 1.0f);  // 20 x 10 mm, top at 1
  MillTool t = tool("face", 10);
  sweepLine(f, t, {-6, 3, 0}, {26, 3, 0});  // covers y < 8
  MillTarget target;
  target.z = 0;
  MillAnalysis a = analyseMill(f, target);
  EXPECT_EQ(a.cells, 20000u);
  EXPECT_NEAR(a.uncutArea(), 20 * 2.0, 1e-9);  // y 8..10 untouched
  EXPECT_NEAR(a.maxExcess, 1.0, 1e-6);
  EXPECT_EQ(a.maxGouge, 0);
  EXPECT_EQ(a.bands[4].cells, 16000u);  // within tolerance
  EXPECT_EQ(a.bands.back().cells, 4000u);
  target.region = std::array<double, 4>{0, 0, 20, 7.5};
  EXPECT_EQ(analyseMill(f, target).uncutCells, 0u);
  target.z = 0.045;  // the face 0.045 deeper than wanted: a gouge band
  target.region.reset();
  MillAnalysis g = analyseMill(f, target);
  EXPECT_NEAR(g.maxGouge, 0.045, 1e-6);
  EXPECT_EQ(g.bands[1].cells, 16000u);     // [-5t, -3t)
  EXPECT_EQ(g.bands.back().cells, 4000u);  // (5t, inf): the uncut strip
  nlohmann::json j = g.toJson();
  EXPECT_NEAR(j["in_tolerance"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(j["uncut_area"].get<double>(), 40.0, 1e-9);
}

TEST(MillAnalysis, NoCellUnderTheTargetIsNotMeasured) {
  HeightField f(0, 0, 0.1, 200, 100, 1.0f);
  MillTarget target;
  target.z = 0;
  target.region = std::array<double, 4>{100, 100, 120, 120};  // off the stock
  MillAnalysis a = analyseMill(f, target);
  ASSERT_EQ(a.cells, 0u);
  nlohmann::json j = a.toJson();
  EXPECT_FALSE(j["measured"].get<bool>());
  EXPECT_TRUE(j["in_tolerance"].is_null());  // never 100 % within
  EXPECT_TRUE(j["max"].is_null());
  EXPECT_TRUE(j["bands"][4]["share"].is_null());
  EXPECT_NE(j["not_measured"].get<std::string>().find("target"), std::string::npos);
}

TEST(MillTools, ShapesFromTheSetup) {
  EXPECT_EQ(tool("bull", 10, 5).kind, MillToolKind::Ball);
  EXPECT_NEAR(tool("drill", 10, 0, 90).profile(5), 5, 1e-12);
  EXPECT_NEAR(tool("bull", 10, 2).profile(5), 2, 1e-12);
  EXPECT_EQ(tool("bull", 10, 2).profile(3), 0);
  EXPECT_THROW(tool("ball", 0), ToolError);
  EXPECT_THROW(tool("bull", 10, 0), ToolError);
  EXPECT_THROW(tool("probe", 6), ToolError);
}

TEST(StlWriter, ClosedMesh) {
  HeightField f(0, 0, 1, 6, 4, 0.0f);
  f.at(2, 2) = -1;
  std::string stl = encodeStl(f);
  uint32_t n;
  std::memcpy(&n, stl.data() + 80, 4);
  ASSERT_EQ(stl.size(), 84 + 50 * size_t(n));
  // Top 2*(5*3), then per boundary edge (16) two walls and one bottom triangle.
  EXPECT_EQ(n, 30u + 16u * 3u);
  // Every edge is shared by exactly two triangles, in opposite directions.
  std::map<std::array<float, 6>, int> edges;
  for (uint32_t t = 0; t < n; ++t) {
    float v[9];
    std::memcpy(v, stl.data() + 84 + 50 * t + 12, 36);
    for (int e = 0; e < 3; ++e) {
      const float* p = v + 3 * e;
      const float* q = v + 3 * ((e + 1) % 3);
      edges[{p[0], p[1], p[2], q[0], q[1], q[2]}] += 1;
    }
  }
  for (const auto& [e, count] : edges) {
    EXPECT_EQ(count, 1);
    std::array<float, 6> back{e[3], e[4], e[5], e[0], e[1], e[2]};
    EXPECT_EQ(edges.count(back), 1u);
  }
}

TEST(MillPictures, UncutCellsAreRed) {
  HeightField f(0, 0, 1, 10, 10, 1.0f);
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 5; ++j) f.at(i, j) = 0;  // lower half cut
  MillTarget target;
  auto px = [](const RgbImage& img, int x, int y) {
    return img.rgb.data() + (static_cast<size_t>(y) * static_cast<size_t>(img.width) + x) * 3;
  };
  RgbImage top = millTopView(f, &target);
  ASSERT_EQ(top.width, 10);
  const uint8_t* upper = px(top, 3, 1);  // image top = high Y = uncut
  const uint8_t* lower = px(top, 3, 8);
  EXPECT_GT(upper[0], upper[1] + 50);
  EXPECT_EQ(lower[0], lower[1]);
  RgbImage dev = millDeviationMap(f, target);
  EXPECT_GT(px(dev, 3, 1)[0], 200);
  EXPECT_GT(px(dev, 3, 8)[1], px(dev, 3, 8)[0]);
  // The height map is a colour scale, never white: the top (uncut) yellow, the cut floor
  // dark violet, each the legend's colour (heightColour) at its end.
  RgbImage height = millHeightMap(f);
  const uint8_t* high = px(height, 3, 1);
  const uint8_t* low = px(height, 3, 8);
  EXPECT_GT(high[0], 200);
  EXPECT_GT(high[1], 200);
  EXPECT_LT(high[2], 80);
  EXPECT_LT(low[0], 100);
  EXPECT_LT(low[1], 40);
  EXPECT_GT(low[2], 60);
  EXPECT_EQ(high[0], static_cast<uint8_t>(heightColour(1.0)[0] * 255 + 0.5));
}

}  // namespace
}  // namespace ncvm
