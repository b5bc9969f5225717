#include "sim/stock_model.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "sim/deviation.hpp"
#include "sim/lathe_insert.hpp"
#include "sim/lathe_stock.hpp"

using namespace ncvm;
using lsim::Pt;

namespace {
ncvm::Setup latheBar(double diameter, double length) {
  ncvm::Setup s = defaultSetup(MachineKind::Lathe);
  s.stock.present = true;
  s.stock.diameter = diameter;
  s.stock.length = length;
  return s;
}
double polygonArea(const std::vector<Pt>& p) {
  double a = 0;
  for (size_t k = 0; k < p.size(); ++k) {
    const Pt &u = p[k], &v = p[(k + 1) % p.size()];
    a += u.z * v.r - v.z * u.r;
  }
  return a / 2;
}
}  // namespace

TEST(StockModel, FactoryNeedsAStockSection) {
  ncvm::Setup s = defaultSetup(MachineKind::Lathe);
  EXPECT_THROW(makeStockModel(s), SetupError);
}

TEST(StockModel, MillStockNeedsABlock) {
  ncvm::Setup s = defaultSetup(MachineKind::Mill);
  s.stock.present = true;
  EXPECT_THROW(makeStockModel(s), SetupError);  // no min/max
  s.stock.min = {0, 0, -10};
  s.stock.max = {50, 50, -10};
  EXPECT_THROW(makeStockModel(s), SetupError);  // flat in Z
  s.stock.max = {50, 50, 0};
  EXPECT_NE(makeStockModel(s), nullptr);
  s.stock.frame = "machine";
  EXPECT_NE(makeStockModel(s), nullptr);
  s.stock.frame = "G54";  // the stock is not placed by a work offset table
  EXPECT_THROW(makeStockModel(s), SetupError);
  s.stock.frame = "work";
  s.tools[3].type = "ball";  // no diameter
  EXPECT_THROW(makeStockModel(s), SetupError);
}

TEST(StockModel, LatheStockNeedsADiameterAndLength) {
  ncvm::Setup s = latheBar(0, 10);
  EXPECT_THROW(makeStockModel(s), SetupError);
  s = latheBar(10, 10);
  s.stock.boreDiameter = 12;
  EXPECT_THROW(makeStockModel(s), SetupError);
  s = latheBar(10, 10);
  s.target.present = true;  // neither blocks nor a polyline
  EXPECT_THROW(makeStockModel(s), SetupError);
}

TEST(LatheInsert, NoseCentreLiesOppositeTheImaginaryTip) {
  // Tip 3 (-X, -Z): the nose centre is (+r, +r) from the programmed point, so the outline
  // touches r = 0 and z = 0 but never goes below either.
  ToolSpec t{"insert"};
  t.noseRadius = 0.8;
  t.tip = 3;
  auto o = lsim::toolOutline(t, 1e-4, 10);
  double rmin = 1e9, zmin = 1e9;
  for (const Pt& p : o) rmin = std::min(rmin, p.r), zmin = std::min(zmin, p.z);
  EXPECT_NEAR(rmin, 0, 1e-4);
  EXPECT_NEAR(zmin, 0, 1e-4);
  // Tip 2 (+X, -Z), a boring bar: the centre is (-r, +r).
  t.tip = 2;
  o = lsim::toolOutline(t, 1e-4, 10);
  double rmax = -1e9;
  zmin = 1e9;
  for (const Pt& p : o) rmax = std::max(rmax, p.r), zmin = std::min(zmin, p.z);
  EXPECT_NEAR(rmax, 0, 1e-4);
  EXPECT_NEAR(zmin, 0, 1e-4);
}

TEST(LatheInsert, SweptHullOfASquareIsItsMinkowskiSum) {
  std::vector<Pt> square{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  auto h = lsim::sweptHull(square, {0, 0}, {0, 3});
  EXPECT_NEAR(std::fabs(polygonArea(h)), 4.0, 1e-12);  // 1 x 4
  h = lsim::sweptHull(square, {0, 0}, {2, 2});
  EXPECT_NEAR(std::fabs(polygonArea(h)), 1 + 2 * 2, 1e-12);  // square + two parallelograms
}

TEST(LatheStock, AGroovePlungeRemovesItsRectangle) {
  // A drill-like flat tool of diameter 2 (r from -1 to 1 about the programmed point):
  // plunging from r 30 to r 20 at z -10 removes a 2 x 10 rectangle of the half-profile.
  ncvm::Setup s = latheBar(60, 40);
  LatheStock st(s);
  ToolSpec flat{"flat"};
  flat.diameter = 2;
  flat.fluteLength = 50;
  st.selectTool(flat);
  double before = st.area();
  EXPECT_NEAR(before, 30 * 40, 1e-9);
  // The flat tool's body runs along +Z from its end: turned sideways it is a 2 wide bar.
  double removed = st.cutLine({35, -10}, {20, -10});
  // Removed: r 20..30 (the stock ends at 30), z -10 .. 0 (body up to the front face), and
  // the tool is 2 wide in r: the swept area is r in [19, 36] x z in [-10, 40] clipped by
  // the bar r in [0, 30] x z in [-40, 0]: 11 x 10.
  EXPECT_NEAR(removed, 11 * 10, 1e-6);
  EXPECT_NEAR(st.area(), before - removed, 1e-6);
  // Cutting the same place again removes nothing.
  EXPECT_NEAR(st.cutLine({35, -10}, {20, -10}), 0, 1e-9);
}

TEST(LatheStock, FacingPastTheAxisCutsTheWholeFace) {
  // A sharp tip-3 insert facing from X+ to X-2 (r -1) at z -1: the whole face layer goes,
  // the part of the sweep past the axis mirrored onto the material near r = 0.
  ncvm::Setup s = latheBar(20, 30);
  LatheStock st(s);
  ToolSpec t{"insert"};
  t.tip = 3;
  st.selectTool(t);
  st.cutLine({12, -1}, {-1, -1});
  // Everything at z > -1 is gone: the front face is now at z = -1.
  EXPECT_NEAR(st.area(), 10 * 29, 1e-6);
}

namespace {
ToolSpec roundInsert(double nose, int tip) {
  ToolSpec t{"insert"};
  t.noseRadius = nose;
  t.tip = tip;
  return t;
}
// A profiling path of short segments with a wavy depth (the benchmark's kind of path).
std::vector<Pt> wavyPath(double step, int moves, double r0) {
  std::vector<Pt> pts;
  for (int i = 0; i <= moves; ++i) {
    double z = -i * step;
    pts.push_back({r0 + 0.05 * std::sin(z * 2), z});
  }
  return pts;
}
ClipperLib::Path intPath(const std::vector<Pt>& pts) {
  ClipperLib::Path p;
  for (const Pt& q : pts)
    p.push_back({std::llround(q.z * LatheStock::kScale), std::llround(q.r * LatheStock::kScale)});
  return p;
}
}  // namespace

TEST(LatheInsert, LinearTimeSweepIsTheHullOfBothPlacements) {
  auto outline = lsim::toolOutline(roundInsert(0.4, 3), 0.0005, 10);
  auto hull = lsim::sweptHull(outline, {}, {});
  std::vector<Pt> out;
  for (int k = 0; k < 72; ++k) {
    double a = k * std::numbers::pi / 36, len = 0.05 + 0.3 * (k % 5);
    Pt from{20, -3}, to{20 + len * std::sin(a), -3 + len * std::cos(a)};
    lsim::sweepConvex(hull, from, to, out);
    EXPECT_NEAR(polygonArea(out), polygonArea(lsim::sweptHull(outline, from, to)), 1e-9) << k;
  }
}

TEST(LatheInsert, SweepAlongAPathIsTheUnionOfItsSegmentsSweeps) {
  auto hull = lsim::sweptHull(lsim::toolOutline(roundInsert(0.4, 3), 0.0005, 10), {}, {});
  auto path = wavyPath(0.05, 400, 20);
  // Split the path where the extreme vertices change, as LatheStock does.
  size_t first = 0, runs = 0;
  while (first + 1 < path.size()) {
    size_t lo = 0, hi = 0, l2 = 0, h2 = 0;
    auto dir = [&](size_t k) { return Pt{path[k + 1].r - path[k].r, path[k + 1].z - path[k].z}; };
    lsim::supportsAcross(hull, dir(first), lo, hi);
    size_t last = first + 1;
    while (last + 1 < path.size()) {
      lsim::supportsAcross(hull, dir(last), l2, h2);
      if (l2 != lo || h2 != hi) break;
      ++last;
    }
    std::vector<Pt> run(path.begin() + static_cast<long>(first),
                        path.begin() + static_cast<long>(last) + 1),
        out;
    lsim::sweepPath(hull, run, lo, hi, out);
    ClipperLib::Clipper c;
    for (size_t k = first; k < last; ++k)
      c.AddPath(intPath(lsim::sweptHull(hull, path[k], path[k + 1])), ClipperLib::ptSubject, true);
    ClipperLib::Paths uni;
    c.Execute(ClipperLib::ctUnion, uni, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    ASSERT_EQ(uni.size(), 1u);
    double s2 = LatheStock::kScale * LatheStock::kScale;
    EXPECT_NEAR(ClipperLib::Area(uni[0]) / s2, ClipperLib::Area(intPath(out)) / s2, 1e-6) << first;
    // The same region: the union minus the path polygon leaves nothing (and the reverse).
    ClipperLib::Clipper d;
    d.AddPaths(uni, ClipperLib::ptSubject, true);
    d.AddPath(intPath(out), ClipperLib::ptClip, true);
    ClipperLib::Paths rest;
    d.Execute(ClipperLib::ctXor, rest, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    double restArea = 0;
    for (const auto& p : rest) restArea += std::fabs(ClipperLib::Area(p)) / s2;
    EXPECT_LT(restArea, 1e-6) << first;
    first = last;
    ++runs;
  }
  EXPECT_LT(runs, 100u);  // runs of several moves, not one per move
}

TEST(LatheStock, BatchedFeedMovesCutWhatSingleMovesCut) {
  auto path = wavyPath(0.05, 1500, 24.5);
  // LatheStock keeps a reference to its setup: the setups must outlive it.
  const ncvm::Setup barA = latheBar(50, 100), barB = latheBar(50, 100);
  LatheStock batched(barA), single(barB);
  batched.selectTool(roundInsert(0.4, 3));
  single.selectTool(roundInsert(0.4, 3));
  MoveEvent e;
  e.mode = MoveMode::Linear;
  for (size_t k = 1; k < path.size(); ++k) {
    e.start[0] = 2 * path[k - 1].r, e.start[2] = path[k - 1].z;
    e.end[0] = 2 * path[k].r, e.end[2] = path[k].z;
    batched.onMove(e);
    single.cutLine(path[k - 1], path[k]);
  }
  EXPECT_NEAR(batched.area(), single.area(), 1e-6);
  ClipperLib::Clipper x;
  x.AddPaths(batched.profile(), ClipperLib::ptSubject, true);
  x.AddPaths(single.profile(), ClipperLib::ptClip, true);
  ClipperLib::Paths rest;
  x.Execute(ClipperLib::ctXor, rest, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  double restArea = 0;
  for (const auto& p : rest) restArea += std::fabs(ClipperLib::Area(p));
  EXPECT_LT(restArea / (LatheStock::kScale * LatheStock::kScale), 1e-6);
}

TEST(LatheInsert, HolderRunsAlongXForODToolsAndAlongZForBoringBars) {
  ToolSpec t = roundInsert(0.4, 3);
  t.edgeLength = 5;
  t.holderDiameter = 20;
  t.holderLength = 30;
  auto box = [](const std::vector<Pt>& p) {
    double r0 = 1e9, r1 = -1e9, z0 = 1e9, z1 = -1e9;
    for (const Pt& q : p)
      r0 = std::min(r0, q.r), r1 = std::max(r1, q.r), z0 = std::min(z0, q.z),
      z1 = std::max(z1, q.z);
    return std::array<double, 4>{r0, r1, z0, z1};
  };
  // Tip 3: nose centre (+0.4, +0.4) from the tip, shank r 5.4 .. 35.4, z -9.6 .. 10.4.
  auto b = box(lsim::holderOutline(t, 10));
  EXPECT_NEAR(b[0], 5.4, 1e-12);
  EXPECT_NEAR(b[1], 35.4, 1e-12);
  EXPECT_NEAR(b[2], -9.6, 1e-12);
  EXPECT_NEAR(b[3], 10.4, 1e-12);
  // Tip 2 (a boring bar towards the chuck): centre (-0.4, +0.4), shank along +Z.
  t.tip = 2;
  b = box(lsim::holderOutline(t, 10));
  EXPECT_NEAR(b[0], -10.4, 1e-12);
  EXPECT_NEAR(b[1], 9.6, 1e-12);
  EXPECT_NEAR(b[2], 5.4, 1e-12);
  EXPECT_NEAR(b[3], 35.4, 1e-12);
  t.holderLength = 0;  // no holder given
  EXPECT_TRUE(lsim::holderOutline(t, 10).empty());
}

TEST(DeviationJson, NoSampleIsNotMeasuredNeverAPass) {
  nlohmann::json j = deviationJson({}, 0.001);
  EXPECT_EQ(j["samples"].get<size_t>(), 0u);
  EXPECT_FALSE(j["measured"].get<bool>());
  EXPECT_TRUE(j["in_tolerance"].is_null());
  EXPECT_TRUE(j["max"].is_null());
  EXPECT_TRUE(j["mean"].is_null());
  for (const auto& b : j["bands"]) EXPECT_TRUE(b["share"].is_null());
  EXPECT_EQ(notMeasuredText(j), "not measured (no point of the target was measured)");
  nlohmann::json one = deviationJson({{0.0005, 1.0}}, 0.001);
  EXPECT_TRUE(one["measured"].get<bool>());
  EXPECT_DOUBLE_EQ(one["in_tolerance"].get<double>(), 1.0);
  EXPECT_EQ(notMeasuredText(one), "");
}
