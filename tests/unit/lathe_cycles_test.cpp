// Lathe canned cycles (src/motion/lathe_cycles.hpp). Expected paths are worked out by hand
// in the comments; x is a radius throughout.
#include "motion/lathe_cycles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace ncvm;
using namespace ncvm::lathe;

namespace {

constexpr double kTol = 1e-9;

ContourSeg seg(SegKind kind, double x, double z, double cx = 0, double cz = 0) {
  ContourSeg s;
  s.kind = kind;
  s.end = {x, z};
  s.center = {cx, cz};
  return s;
}

Contour contour(Pt start, std::vector<ContourSeg> segs, bool typeTwo = false) {
  Contour c;
  c.start = start;
  c.segs = std::move(segs);
  c.nsNamesZ = typeTwo;
  return c;
}

const char* kindName(SegKind k) {
  switch (k) {
    case SegKind::Rapid:
      return "G00";
    case SegKind::Line:
      return "G01";
    case SegKind::ArcCw:
      return "G02";
    case SegKind::ArcCcw:
      return "G03";
  }
  return "?";
}

std::string dump(const std::vector<Move>& moves) {
  std::ostringstream os;
  for (size_t i = 0; i < moves.size(); ++i) {
    const Move& m = moves[i];
    os << i << ": " << kindName(m.kind) << " X" << m.end.x << " Z" << m.end.z;
    if (m.kind == SegKind::ArcCw || m.kind == SegKind::ArcCcw)
      os << " (c " << m.center.x << "," << m.center.z << ")";
    if (m.thread) os << " thread";
    os << "\n";
  }
  return os.str();
}

struct Want {
  SegKind kind;
  double x, z;
};

void expectMoves(const std::vector<Move>& got, const std::vector<Want>& want, double tol = kTol) {
  ASSERT_EQ(got.size(), want.size()) << dump(got);
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(got[i].kind, want[i].kind) << "move " << i << "\n" << dump(got);
    EXPECT_NEAR(got[i].end.x, want[i].x, tol) << "move " << i << "\n" << dump(got);
    EXPECT_NEAR(got[i].end.z, want[i].z, tol) << "move " << i << "\n" << dump(got);
  }
}

void expectAlarm(const std::function<void()>& f, AlarmId id) {
  try {
    f();
    ADD_FAILURE() << "no CycleError, expected " << alarmCode(id);
  } catch (const CycleError& e) {
    EXPECT_EQ(e.id, id) << alarmCode(e.id) << " " << e.what();
  }
}

bool isArc(const Move& m) {
  return m.kind == SegKind::ArcCw || m.kind == SegKind::ArcCcw;
}

// Signed sweep of an arc move from `from` (CCW positive, seen with Z across and X up).
double sweepOf(const Pt& from, const Move& m) {
  double a0 = std::atan2(from.x - m.center.x, from.z - m.center.z);
  double a1 = std::atan2(m.end.x - m.center.x, m.end.z - m.center.z);
  double sweep = a1 - a0;
  if (m.kind == SegKind::ArcCcw)
    while (sweep <= 0) sweep += 2 * std::numbers::pi;
  if (m.kind == SegKind::ArcCw)
    while (sweep >= 0) sweep -= 2 * std::numbers::pi;
  return sweep;
}

// Points along a move (lines and arcs), for the gouge check.
std::vector<Pt> sample(const Pt& from, const Move& m, int n = 200) {
  std::vector<Pt> pts;
  double a0 = std::atan2(from.x - m.center.x, from.z - m.center.z);
  double sweep = isArc(m) ? sweepOf(from, m) : 0;
  double r = std::hypot(from.x - m.center.x, from.z - m.center.z);
  for (int i = 0; i <= n; ++i) {
    double t = double(i) / n;
    if (!isArc(m)) {
      pts.push_back({from.x + t * (m.end.x - from.x), from.z + t * (m.end.z - from.z)});
    } else {
      double a = a0 + t * sweep;
      pts.push_back({m.center.x + r * std::sin(a), m.center.z + r * std::cos(a)});
    }
  }
  return pts;
}

// The x values at which a move crosses z (exactly, circle-line for arcs).
std::vector<double> xsAtZ(const Pt& from, const Move& m, double z) {
  std::vector<double> xs;
  if (!isArc(m)) {
    if (z >= std::min(from.z, m.end.z) && z <= std::max(from.z, m.end.z) && from.z != m.end.z)
      xs.push_back(from.x + (m.end.x - from.x) * (z - from.z) / (m.end.z - from.z));
    return xs;
  }
  double r = std::hypot(from.x - m.center.x, from.z - m.center.z);
  double dz = z - m.center.z;
  if (std::abs(dz) > r) return xs;
  double h = std::sqrt(r * r - dz * dz);
  double a0 = std::atan2(from.x - m.center.x, from.z - m.center.z);
  double sweep = sweepOf(from, m);
  for (double x : {m.center.x + h, m.center.x - h}) {
    double d =
        sweep > 0 ? std::atan2(x - m.center.x, dz) - a0 : a0 - std::atan2(x - m.center.x, dz);
    d = std::fmod(d + 4 * std::numbers::pi, 2 * std::numbers::pi);
    if (d <= std::abs(sweep) + 1e-12 || d >= 2 * std::numbers::pi - 1e-12) xs.push_back(x);
  }
  return xs;
}

// Radius of a piecewise-linear OD shape (z descending) at z; nullopt outside it.
std::optional<double> shapeX(const std::vector<Pt>& shape, double z) {
  for (size_t i = 0; i + 1 < shape.size(); ++i) {
    const Pt &a = shape[i], &b = shape[i + 1];
    double lo = std::min(a.z, b.z), hi = std::max(a.z, b.z);
    if (z < lo || z > hi || a.z == b.z) continue;
    return a.x + (b.x - a.x) * (z - a.z) / (b.z - a.z);
  }
  return std::nullopt;
}

// Checks no move of `moves` (from `start`) goes below the shape, and that for each sampled
// z the deepest cutting move reaches the shape (the roughed envelope is the shape).
void expectEnvelope(const Pt& start, const std::vector<Move>& moves,
                    const std::function<std::optional<double>(double)>& shape, double z0,
                    double z1) {
  Pt pos = start;
  for (const auto& m : moves) {
    for (const auto& p : sample(pos, m)) {
      auto sx = shape(p.z);
      if (sx) {
        // 1e-5: at an arc's Z extreme x moves by sqrt(2 r eps) for a rounding eps in z.
        EXPECT_GE(p.x, *sx - 1e-5) << "gouge at z " << p.z << "\n" << dump(moves);
      }
    }
    pos = m.end;
  }
  for (int i = 0; i <= 400; ++i) {
    double z = z0 + (z1 - z0) * i / 400.0;
    auto sx = shape(z);
    if (!sx) continue;
    double lowest = 1e9;
    pos = start;
    for (const auto& m : moves) {
      if (m.kind != SegKind::Rapid)
        for (double x : xsAtZ(pos, m, z)) lowest = std::min(lowest, x);
      pos = m.end;
    }
    EXPECT_NEAR(lowest, *sx, 1e-6) << "envelope at z " << z;
  }
}

// The stepped OD part used by several tests: diameter 20 to Z-20, face, diameter 30 to
// Z-40, face up to diameter 50. A at X50 Z2 (radius 25).
Contour steppedOd() {
  return contour({25, 2}, {seg(SegKind::Rapid, 10, 2), seg(SegKind::Line, 10, -20),
                           seg(SegKind::Line, 15, -20), seg(SegKind::Line, 15, -40),
                           seg(SegKind::Line, 25, -40)});
}

}  // namespace

// ---------------------------------------------------------------- G71 type I

// G71 U2 R0.5; G71 P Q U0.5 W0.1. Shifted shape: X10.25 from Z2.1 to Z-19.9, X15.25 to
// Z-39.9, face to X25.25. Levels 23, 21, ..., 11 (9 would pass X10.25, the shifted A').
// Levels above 15.25 end on the far face (Z-39.9), the others on the first face (Z-19.9).
// Each: rapid X to the level, feed Z, 45 degree retract by 0.5, rapid back to Z2.
TEST(LatheG71, SteppedOdPassesSemiFinishAndReturn) {
  std::vector<Move> moves = roughTurning(steppedOd(), {2, 0.5, 0.25, 0.1});
  std::vector<Want> want;
  for (double level : {23.0, 21.0, 19.0, 17.0, 15.0, 13.0, 11.0}) {
    double zEnd = level > 15.25 ? -39.9 : -19.9;
    want.push_back({SegKind::Rapid, level, 2});
    want.push_back({SegKind::Line, level, zEnd});
    want.push_back({SegKind::Line, level + 0.5, zEnd + 0.5});
    want.push_back({SegKind::Rapid, level + 0.5, 2});
  }
  // Semi-finishing along the shifted shape, from the shifted A' (ns block G00: rapid).
  want.push_back({SegKind::Rapid, 10.25, 2.1});
  want.push_back({SegKind::Line, 10.25, -19.9});
  want.push_back({SegKind::Line, 15.25, -19.9});
  want.push_back({SegKind::Line, 15.25, -39.9});
  want.push_back({SegKind::Line, 25.25, -39.9});
  want.push_back({SegKind::Rapid, 25, 2});
  expectMoves(moves, want);
  for (const auto& m : moves) {
    EXPECT_EQ(m.contourIndex, -1);  // roughing feed, not the shape blocks' own F
    EXPECT_FALSE(m.thread);
  }
}

TEST(LatheG71, RoughedEnvelopeIsTheShapeShiftedByTheAllowance) {
  std::vector<Move> moves = roughTurning(steppedOd(), {2, 0.5, 0.25, 0.1});
  std::vector<Pt> shifted = {
      {10.25, 2.1}, {10.25, -19.9}, {15.25, -19.9}, {15.25, -39.9}, {25.25, -39.9}};
  expectEnvelope(
      {25, 2}, moves, [&](double z) { return shapeX(shifted, z); }, 2.0, -39.85);
}

// Depth 2.5 without allowance puts level 15 exactly on the second diameter: the pass stops
// at the first face (Z-20) instead of riding along the finished diameter; level 10 is the
// first diameter itself and is left to the final pass.
TEST(LatheG71, LevelOnADiameterStopsAtItsShoulder) {
  std::vector<Move> moves = roughTurning(steppedOd(), {2.5, 0.5, 0, 0});
  std::vector<Want> want;
  for (double level : {22.5, 20.0, 17.5, 15.0, 12.5}) {
    double zEnd = level > 15 ? -40 : -20;
    want.push_back({SegKind::Rapid, level, 2});
    want.push_back({SegKind::Line, level, zEnd});
    want.push_back({SegKind::Line, level + 0.5, zEnd + 0.5});
    want.push_back({SegKind::Rapid, level + 0.5, 2});
  }
  want.push_back({SegKind::Rapid, 10, 2});
  want.push_back({SegKind::Line, 10, -20});
  want.push_back({SegKind::Line, 15, -20});
  want.push_back({SegKind::Line, 15, -40});
  want.push_back({SegKind::Line, 25, -40});
  want.push_back({SegKind::Rapid, 25, 2});
  expectMoves(moves, want);
}

// G01 in the ns block: the infeed to each level is a feed, as the ns block's mode.
TEST(LatheG71, NsBlockG01FeedsTheInfeed) {
  Contour c = steppedOd();
  c.segs[0].kind = SegKind::Line;
  std::vector<Move> moves = roughTurning(c, {2, 0.5, 0, 0});
  ASSERT_FALSE(moves.empty());
  EXPECT_EQ(moves[0].kind, SegKind::Line);
  EXPECT_NEAR(moves[0].end.x, 23, kTol);
}

// Taper: X6 to Z-10, taper to X16 at Z-20, face to X20; U0.4 W0.1, depth 3. Shifted taper
// x = 6.2 + (-9.9 - z), so level 14 ends at Z-17.7, 11 at Z-14.7, 8 at Z-11.7; level 17
// is above the taper and ends on the face at Z-19.9; level 5 would pass X6.2.
TEST(LatheG71, TaperPassesEndOnTheTaper) {
  Contour c = contour({20, 2}, {seg(SegKind::Rapid, 6, 2), seg(SegKind::Line, 6, -10),
                                seg(SegKind::Line, 16, -20), seg(SegKind::Line, 20, -20)});
  std::vector<Move> moves = roughTurning(c, {3, 0.5, 0.2, 0.1});
  std::vector<Want> want;
  for (auto [level, zEnd] :
       std::vector<std::pair<double, double>>{{17, -19.9}, {14, -17.7}, {11, -14.7}, {8, -11.7}}) {
    want.push_back({SegKind::Rapid, level, 2});
    want.push_back({SegKind::Line, level, zEnd});
    want.push_back({SegKind::Line, level + 0.5, zEnd + 0.5});
    want.push_back({SegKind::Rapid, level + 0.5, 2});
  }
  want.push_back({SegKind::Rapid, 6.2, 2.1});
  want.push_back({SegKind::Line, 6.2, -9.9});
  want.push_back({SegKind::Line, 16.2, -19.9});
  want.push_back({SegKind::Line, 20.2, -19.9});
  want.push_back({SegKind::Rapid, 20, 2});
  expectMoves(moves, want);
  std::vector<Pt> shifted = {{6.2, 2.1}, {6.2, -9.9}, {16.2, -19.9}, {20.2, -19.9}};
  expectEnvelope(
      {20, 2}, moves, [&](double z) { return shapeX(shifted, z); }, 2, -19.8);
}

// A ball end: X0 Z0, G03 to X20 Z-10 R10 (centre X0 Z-10), X20 to Z-20, face to X40.
// With U0.4 W0.1 the centre moves to (0.2, -9.9); a level L meets the arc where
// (L - 0.2)^2 + (z + 9.9)^2 = 100. Levels 17, 14, 11 end on the face (Z-19.9).
TEST(LatheG71, ArcInShapeStopsPassesOnTheCircle) {
  Contour c = contour({20, 2}, {seg(SegKind::Rapid, 0, 2), seg(SegKind::Line, 0, 0),
                                seg(SegKind::ArcCcw, 10, -10, 0, -10), seg(SegKind::Line, 10, -20),
                                seg(SegKind::Line, 20, -20)});
  std::vector<Move> moves = roughTurning(c, {3, 0.5, 0.2, 0.1});
  std::vector<Want> want;
  for (double level : {17.0, 14.0, 11.0, 8.0, 5.0, 2.0}) {
    double zEnd = level > 10.2 ? -19.9 : -9.9 + std::sqrt(100 - (level - 0.2) * (level - 0.2));
    want.push_back({SegKind::Rapid, level, 2});
    want.push_back({SegKind::Line, level, zEnd});
    want.push_back({SegKind::Line, level + 0.5, zEnd + 0.5});
    want.push_back({SegKind::Rapid, level + 0.5, 2});
  }
  want.push_back({SegKind::Rapid, 0.2, 2.1});
  want.push_back({SegKind::Line, 0.2, 0.1});
  want.push_back({SegKind::ArcCcw, 10.2, -9.9});
  want.push_back({SegKind::Line, 10.2, -19.9});
  want.push_back({SegKind::Line, 20.2, -19.9});
  want.push_back({SegKind::Rapid, 20, 2});
  expectMoves(moves, want);
  const Move& arc = moves[moves.size() - 4];
  EXPECT_NEAR(arc.center.x, 0.2, kTol);  // the arc is translated, radius unchanged
  EXPECT_NEAR(arc.center.z, -9.9, kTol);
  auto shape = [](double z) -> std::optional<double> {
    if (z > 0.1 || z < -19.9) return std::nullopt;
    if (z > -9.9) return 0.2 + std::sqrt(std::max(0.0, 100 - (z + 9.9) * (z + 9.9)));
    return 10.2;
  };
  expectEnvelope({20, 2}, moves, shape, 0.1, -19.8);
}

// ID: A at X10 Z2 (radius 5); bore radius 20 to Z-10, face to 15, bore 15 to Z-30, face to
// 5. U-0.4 W0.1: the shape moves to 19.8 / 14.8. Levels step up from 5 by 2 while below
// 19.8: 7..13 end on the bottom face (Z-29.9), 15..19 on the first face (Z-9.9); the
// retract moves towards the axis.
TEST(LatheG71, InsideDiameterStepsTowardsLargerX) {
  Contour c = contour(
      {5, 2}, {seg(SegKind::Rapid, 20, 2), seg(SegKind::Line, 20, -10), seg(SegKind::Line, 15, -10),
               seg(SegKind::Line, 15, -30), seg(SegKind::Line, 5, -30)});
  std::vector<Move> moves = roughTurning(c, {2, 0.5, -0.2, 0.1});
  std::vector<Want> want;
  for (double level : {7.0, 9.0, 11.0, 13.0, 15.0, 17.0, 19.0}) {
    double zEnd = level < 14.8 ? -29.9 : -9.9;
    want.push_back({SegKind::Rapid, level, 2});
    want.push_back({SegKind::Line, level, zEnd});
    want.push_back({SegKind::Line, level - 0.5, zEnd + 0.5});
    want.push_back({SegKind::Rapid, level - 0.5, 2});
  }
  want.push_back({SegKind::Rapid, 19.8, 2.1});
  want.push_back({SegKind::Line, 19.8, -9.9});
  want.push_back({SegKind::Line, 14.8, -9.9});
  want.push_back({SegKind::Line, 14.8, -29.9});
  want.push_back({SegKind::Line, 4.8, -29.9});
  want.push_back({SegKind::Rapid, 5, 2});
  expectMoves(moves, want);
}

// ---------------------------------------------------------------- G71 type II

// A groove: X10 to Z-10, down to X6 at Z-14, X6 to Z-18, up to X10 at Z-22, X10 to Z-30,
// face to X20. Depth 2, e 0.5, no allowance. Levels 18..12 cut to the face; level 10 only
// the groove (the lands are at exactly 10); level 8 enters the groove down its wall from
// level 10 (X10 Z-10 to X8 Z-12), cuts to Z-20 and follows the wall up to level 10.
TEST(LatheG71TypeII, PocketIsRoughedAndFollowedUp) {
  Contour c =
      contour({20, 2},
              {seg(SegKind::Rapid, 10, 2), seg(SegKind::Line, 10, -10), seg(SegKind::Line, 6, -14),
               seg(SegKind::Line, 6, -18), seg(SegKind::Line, 10, -22), seg(SegKind::Line, 10, -30),
               seg(SegKind::Line, 20, -30)},
              true);
  std::vector<Move> moves = roughTurning(c, {2, 0.5, 0, 0});
  // The pass of level 8 inside the groove, and the wall follow after it.
  bool found = false;
  for (size_t i = 2; i + 2 < moves.size(); ++i) {
    if (moves[i].kind != SegKind::Line || std::abs(moves[i].end.x - 8) > kTol ||
        std::abs(moves[i].end.z + 20) > kTol)
      continue;
    found = true;
    EXPECT_NEAR(moves[i - 1].end.x, 8, kTol);  // came down the entry wall to X8 Z-12
    EXPECT_NEAR(moves[i - 1].end.z, -12, kTol);
    EXPECT_NEAR(moves[i - 2].end.x, 10, kTol);
    EXPECT_NEAR(moves[i - 2].end.z, -10, kTol);
    EXPECT_EQ(moves[i + 1].kind, SegKind::Line);  // follows the exit wall up to level 10
    EXPECT_NEAR(moves[i + 1].end.x, 10, kTol);
    EXPECT_NEAR(moves[i + 1].end.z, -22, kTol);
    EXPECT_EQ(moves[i + 2].kind, SegKind::Line);  // then the 45 degree retract
    EXPECT_NEAR(moves[i + 2].end.x, 10.5, kTol);
    EXPECT_NEAR(moves[i + 2].end.z, -21.5, kTol);
  }
  EXPECT_TRUE(found) << dump(moves);
  std::vector<Pt> shape = {{10, 2}, {10, -10}, {6, -14}, {6, -18}, {10, -22}, {10, -30}, {20, -30}};
  expectEnvelope(
      {20, 2}, moves, [&](double z) { return shapeX(shape, z); }, 2, -29.9);
  EXPECT_EQ(moves.back().kind, SegKind::Rapid);
  EXPECT_NEAR(moves.back().end.x, 20, kTol);
  EXPECT_NEAR(moves.back().end.z, 2, kTol);
}

// Two grooves and an allowance: every level cuts each region below it, nothing gouges the
// shifted shape, and the envelope is the shifted shape.
TEST(LatheG71TypeII, TwoPocketsWithAllowance) {
  Contour c = contour({20, 2},
                      {seg(SegKind::Line, 12, 0), seg(SegKind::Line, 12, -5),
                       seg(SegKind::Line, 7, -10), seg(SegKind::Line, 12, -15),
                       seg(SegKind::Line, 12, -18), seg(SegKind::ArcCw, 12, -26, 12, -22),
                       seg(SegKind::Line, 12, -30), seg(SegKind::Line, 20, -34)},
                      true);
  std::vector<Move> moves = roughTurning(c, {1.5, 0.3, 0.2, 0.1});
  auto shape = [](double z) -> std::optional<double> {
    z -= 0.1;  // undo the W shift, then add the U shift to the result
    double x;
    if (z > 0 || z < -34) return std::nullopt;
    if (z > -5)
      x = 12;
    else if (z > -10)
      x = 12 - (-5 - z);
    else if (z > -15)
      x = 7 + (-10 - z);
    else if (z > -18)
      x = 12;
    else if (z > -26)
      x = 12 - std::sqrt(std::max(0.0, 16 - (z + 22) * (z + 22)));
    else if (z > -30)
      x = 12;
    else
      x = 12 + 2 * (-30 - z);
    return x + 0.2;
  };
  expectEnvelope({20, 2}, moves, shape, 0.05, -33.95);
}

// Random shapes: OD, Z falling, X wandering (type II) or rising (type I), with some
// quarter arcs. For each, the roughing must not throw, must never go below the shifted
// shape, and must leave exactly the shifted shape; G72 on the same shape with X and Z
// swapped, and G71 on the shape mirrored in X (ID) or in Z, must give the same moves
// swapped or mirrored.
namespace {

struct Rng {
  uint64_t s;
  double next() {  // uniform in [0, 1)
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return double(s >> 11) / double(1ull << 53);
  }
};

Contour randomShape(Rng& rng, bool typeTwo) {
  std::vector<ContourSeg> segs;
  double x = 5 + 10 * rng.next(), z = 0;
  segs.push_back(seg(SegKind::Rapid, x, typeTwo ? 0 : 2));
  if (!typeTwo) segs.push_back(seg(SegKind::Line, x, 0));
  for (int i = 0; i < 8; ++i) {
    double d = 0.5 + 3 * rng.next();
    double dir = typeTwo ? (rng.next() < 0.5 ? -1 : 1) : 1;
    double x1 = std::clamp(x + dir * d, 2.0, 24.0);
    if (rng.next() < 0.3 && std::abs(x1 - x) > 0.1) {
      // Quarter arc from (x, z) to (x1, z - |x1 - x|), centre at a corner of its box.
      double z1 = z - std::abs(x1 - x);
      Pt c = rng.next() < 0.5 ? Pt{x1, z} : Pt{x, z1};
      double a0 = std::atan2(x - c.x, z - c.z), a1 = std::atan2(x1 - c.x, z1 - c.z);
      double sweep = std::remainder(a1 - a0, 2 * std::numbers::pi);
      segs.push_back(seg(sweep > 0 ? SegKind::ArcCcw : SegKind::ArcCw, x1, z1, c.x, c.z));
      z = z1;
    } else {
      double r = rng.next();
      double z1 = r < 0.2 ? z : z - (0.5 + 4 * rng.next());  // some vertical faces
      segs.push_back(seg(SegKind::Line, x1, z1));
      z = z1;
    }
    x = x1;
  }
  segs.push_back(seg(SegKind::Line, 28, z - 1));
  return contour({30, 3}, segs, typeTwo);
}

// Lowest x of the (shifted) shape at z, over every block that spans z.
std::optional<double> shapeAt(const Contour& c, double dx, double dz, double z) {
  std::optional<double> lowest;
  Pt pos{c.segs[0].end.x + dx, c.segs[0].end.z + dz};
  for (size_t i = 1; i < c.segs.size(); ++i) {
    Move m;
    m.kind = c.segs[i].kind;
    m.end = {c.segs[i].end.x + dx, c.segs[i].end.z + dz};
    m.center = {c.segs[i].center.x + dx, c.segs[i].center.z + dz};
    std::vector<double> xs = xsAtZ(pos, m, z);
    if (!isArc(m) && std::abs(pos.z - z) < 1e-9 && std::abs(m.end.z - z) < 1e-9)
      xs = {pos.x, m.end.x};  // a face lying at exactly this z
    for (double x : xs)
      if (!lowest || x < *lowest) lowest = x;
    pos = m.end;
  }
  return lowest;
}

Pt swapped(const Pt& p) {
  return {p.z, p.x};
}
SegKind mirrored(SegKind k) {
  return k == SegKind::ArcCw ? SegKind::ArcCcw : k == SegKind::ArcCcw ? SegKind::ArcCw : k;
}

}  // namespace

TEST(LatheG71TypeII, RandomShapesNeverGougeAndLeaveTheShape) {
  Rng rng{12345};
  for (int n = 0; n < 150; ++n) {
    bool typeTwo = n % 3 != 0;
    Contour c = randomShape(rng, typeTwo);
    RoughParams p{0.7 + 2 * rng.next(), 0.4 * rng.next(), 0.3 * rng.next(), 0.2 * rng.next()};
    SCOPED_TRACE("shape " + std::to_string(n));
    std::vector<Move> moves;
    ASSERT_NO_THROW(moves = roughTurning(c, p));
    double zEnd = c.segs.back().end.z + p.allowZ;
    double z0 = c.segs[0].end.z + p.allowZ;
    expectEnvelope(
        c.start, moves, [&](double z) { return shapeAt(c, p.allowX, p.allowZ, z); }, z0 - 0.0123,
        zEnd + 0.0137);
    // G72 is G71 with the axes swapped.
    Contour f = c;
    f.start = swapped(c.start);
    for (auto& s : f.segs) {
      s.end = swapped(s.end);
      s.center = swapped(s.center);
      s.kind = mirrored(s.kind);
    }
    std::vector<Move> faced = roughFacing(f, {p.depth, p.retract, p.allowZ, p.allowX});
    ASSERT_EQ(faced.size(), moves.size());
    for (size_t i = 0; i < moves.size(); ++i) {
      EXPECT_EQ(faced[i].kind, mirrored(moves[i].kind));
      EXPECT_NEAR(faced[i].end.x, moves[i].end.z, 1e-9);
      EXPECT_NEAR(faced[i].end.z, moves[i].end.x, 1e-9);
    }
    // Mirrored in X (an ID shape, U negative) or in Z (cutting towards +Z): same moves,
    // mirrored.
    for (auto mirror : {std::pair{-1.0, 1.0}, std::pair{1.0, -1.0}}) {
      // (clang 14 cannot capture structured bindings in a lambda.)
      const double mx = mirror.first, mz = mirror.second;
      Contour m = c;
      auto flip = [&](const Pt& q) { return Pt{mx < 0 ? 40 - q.x : q.x, mz * q.z}; };
      m.start = flip(c.start);
      for (auto& s : m.segs) {
        s.end = flip(s.end);
        s.center = flip(s.center);
        s.kind = mirrored(s.kind);
      }
      std::vector<Move> got = roughTurning(m, {p.depth, p.retract, mx * p.allowX, mz * p.allowZ});
      ASSERT_EQ(got.size(), moves.size());
      for (size_t i = 0; i < moves.size(); ++i) {
        Pt want = flip(moves[i].end);
        EXPECT_EQ(got[i].kind, mirrored(moves[i].kind));
        EXPECT_NEAR(got[i].end.x, want.x, 1e-9);
        EXPECT_NEAR(got[i].end.z, want.z, 1e-9);
      }
    }
  }
}

// ---------------------------------------------------------------- G72

// Face shape: A X44 Z2 (radius 22); ns Z-6 at X44; face to X28 (radius 14), G03 R4 to X20
// Z-2 (centre X28 Z-2), X20 to Z0, face to X0. Depth 2, no allowance. Levels Z0 (ends at
// the X10 step), Z-2 (ends where the arc reaches Z-2, X10) and Z-4 (meets the arc at
// x = 14 - 4 sin 60). Retract: +0.5 in Z, +0.5 in X (back towards the start).
TEST(LatheG72, FaceShapeWithArc) {
  Contour c = contour({22, 2}, {seg(SegKind::Rapid, 22, -6), seg(SegKind::Line, 14, -6),
                                seg(SegKind::ArcCcw, 10, -2, 14, -2), seg(SegKind::Line, 10, 0),
                                seg(SegKind::Line, 0, 0)});
  std::vector<Move> moves = roughFacing(c, {2, 0.5, 0, 0});
  std::vector<Want> want;
  double x4 = 14 - 4 * std::sin(std::numbers::pi / 3);
  for (auto [level, xEnd] : std::vector<std::pair<double, double>>{{0, 10}, {-2, 10}, {-4, x4}}) {
    want.push_back({SegKind::Rapid, 22, level});
    want.push_back({SegKind::Line, xEnd, level});
    want.push_back({SegKind::Line, xEnd + 0.5, level + 0.5});
    want.push_back({SegKind::Rapid, 22, level + 0.5});
  }
  want.push_back({SegKind::Rapid, 22, -6});
  want.push_back({SegKind::Line, 14, -6});
  want.push_back({SegKind::ArcCcw, 10, -2});
  want.push_back({SegKind::Line, 10, 0});
  want.push_back({SegKind::Line, 0, 0});
  want.push_back({SegKind::Rapid, 22, 2});
  expectMoves(moves, want);
  EXPECT_NEAR(moves[moves.size() - 4].center.x, 14, kTol);
  EXPECT_NEAR(moves[moves.size() - 4].center.z, -2, kTol);
}

// Steps with U0.4 W0.3: shifted shape (22.2,-7.7) (16.2,-7.7) (16.2,-3.7) (8.2,-3.7)
// (8.2,0.3) (0.2,0.3). Depth 3 from Z2: levels -1 (ends at X8.2), -4 and -7 (X16.2).
TEST(LatheG72, FaceStepsWithAllowance) {
  Contour c = contour(
      {22, 2}, {seg(SegKind::Rapid, 22, -8), seg(SegKind::Line, 16, -8), seg(SegKind::Line, 16, -4),
                seg(SegKind::Line, 8, -4), seg(SegKind::Line, 8, 0), seg(SegKind::Line, 0, 0)});
  std::vector<Move> moves = roughFacing(c, {3, 0.5, 0.2, 0.3});
  std::vector<Want> want;
  for (auto [level, xEnd] :
       std::vector<std::pair<double, double>>{{-1, 8.2}, {-4, 16.2}, {-7, 16.2}}) {
    want.push_back({SegKind::Rapid, 22, level});
    want.push_back({SegKind::Line, xEnd, level});
    want.push_back({SegKind::Line, xEnd + 0.5, level + 0.5});
    want.push_back({SegKind::Rapid, 22, level + 0.5});
  }
  want.push_back({SegKind::Rapid, 22.2, -7.7});
  want.push_back({SegKind::Line, 16.2, -7.7});
  want.push_back({SegKind::Line, 16.2, -3.7});
  want.push_back({SegKind::Line, 8.2, -3.7});
  want.push_back({SegKind::Line, 8.2, 0.3});
  want.push_back({SegKind::Line, 0.2, 0.3});
  want.push_back({SegKind::Rapid, 22, 2});
  expectMoves(moves, want);
}

// ---------------------------------------------------------------- G73, G70

Contour filletShape() {
  // X10 from Z2 to Z-10, G02 R5 fillet to X15 Z-15 (centre X15 Z-10), face to X20.
  return contour({30, 5}, {seg(SegKind::Rapid, 10, 2), seg(SegKind::Line, 10, -10),
                           seg(SegKind::ArcCw, 15, -15, 15, -10), seg(SegKind::Line, 20, -15)});
}

// G73 U6 W3 R3; G73 P Q U0.4 W0.1: offsets (6.2, 3.1), (3.2, 1.6), (0.2, 0.1).
TEST(LatheG73, PassesShrinkEvenlyToTheAllowance) {
  std::vector<Move> moves = patternRepeating(filletShape(), {6, 3, 0.2, 0.1, 3});
  std::vector<Want> want;
  for (auto [dx, dz] : std::vector<std::pair<double, double>>{{6.2, 3.1}, {3.2, 1.6}, {0.2, 0.1}}) {
    want.push_back({SegKind::Rapid, 10 + dx, 2 + dz});
    want.push_back({SegKind::Line, 10 + dx, -10 + dz});
    want.push_back({SegKind::ArcCw, 15 + dx, -15 + dz});
    want.push_back({SegKind::Line, 20 + dx, -15 + dz});
    want.push_back({SegKind::Rapid, 30, 5});
  }
  expectMoves(moves, want);
  EXPECT_NEAR(moves[2].center.x, 15 + 6.2, kTol);
  EXPECT_NEAR(moves[2].center.z, -10 + 3.1, kTol);
  for (const auto& m : moves) EXPECT_EQ(m.contourIndex, -1);
}

TEST(LatheG73, OneDivisionIsTheFinalPass) {
  std::vector<Move> moves = patternRepeating(filletShape(), {6, 3, 0.2, 0.1, 1});
  ASSERT_EQ(moves.size(), 5u);
  EXPECT_NEAR(moves[0].end.x, 10.2, kTol);
  EXPECT_NEAR(moves[0].end.z, 2.1, kTol);
}

TEST(LatheG70, FollowsTheShapeWithItsBlocksThenRapidsBack) {
  std::vector<Move> moves = finishing(filletShape());
  expectMoves(moves, {{SegKind::Rapid, 10, 2},
                      {SegKind::Line, 10, -10},
                      {SegKind::ArcCw, 15, -15},
                      {SegKind::Line, 20, -15},
                      {SegKind::Rapid, 30, 5}});
  for (int i = 0; i < 4; ++i) EXPECT_EQ(moves[size_t(i)].contourIndex, i);
  EXPECT_EQ(moves[4].contourIndex, -1);
  EXPECT_NEAR(moves[2].center.x, 15, kTol);
  EXPECT_NEAR(moves[2].center.z, -10, kTol);
}

// ---------------------------------------------------------------- G90, G94

// R = radius at the cut start minus radius at the cut end. The four sign cases of D.2:
// (1) U<0 W<0 R<0, (2) U>0 W<0 R>0, (3) U<0 W<0 R>0, (4) U>0 W<0 R<0 (|R| <= |U/2|).
TEST(LatheG90, FourTaperSignCases) {
  struct Case {
    Pt start, end;
    double r;
  };
  for (const Case& k : {Case{{30, 2}, {20, -20}, -3}, Case{{10, 2}, {20, -20}, 3},
                        Case{{30, 2}, {20, -20}, 3}, Case{{10, 2}, {20, -20}, -3}}) {
    std::vector<Move> moves = singleCycle(k.start, k.end, k.r, false);
    expectMoves(moves, {{SegKind::Rapid, 20 + k.r, k.start.z},
                        {SegKind::Line, 20, -20},
                        {SegKind::Line, k.start.x, -20},
                        {SegKind::Rapid, k.start.x, k.start.z}});
  }
}

TEST(LatheG90, StraightTurning) {
  expectMoves(singleCycle({25, 2}, {20, -30}, 0, false), {{SegKind::Rapid, 20, 2},
                                                          {SegKind::Line, 20, -30},
                                                          {SegKind::Line, 25, -30},
                                                          {SegKind::Rapid, 25, 2}});
}

// G94 X20 Z-5 R-2 from X60 Z2: rapid in Z to Z-7 (end Z + R), feed to X20 Z-5 (the taper
// face), feed out in Z to Z2, rapid back in X.
TEST(LatheG94, FaceCycleWithTaper) {
  expectMoves(singleCycle({30, 2}, {10, -5}, -2, true), {{SegKind::Rapid, 30, -7},
                                                         {SegKind::Line, 10, -5},
                                                         {SegKind::Line, 10, 2},
                                                         {SegKind::Rapid, 30, 2}});
  expectMoves(singleCycle({30, 2}, {10, -5}, 0, true), {{SegKind::Rapid, 30, -5},
                                                        {SegKind::Line, 10, -5},
                                                        {SegKind::Line, 10, 2},
                                                        {SegKind::Rapid, 30, 2}});
}

// ---------------------------------------------------------------- G92

// M24 thread root radius 9 to Z-20 from X24 Z5 (radius 12), chamfer 2: the thread move
// stops 2 before the end and pulls out at 45 degrees to X11 at Z-20.
TEST(LatheG92, ChamferPullOut) {
  std::vector<Move> moves = threadCycle({12, 5}, {9, -20}, 0, 2);
  expectMoves(moves, {{SegKind::Rapid, 9, 5},
                      {SegKind::Line, 9, -18},
                      {SegKind::Line, 11, -20},
                      {SegKind::Rapid, 12, -20},
                      {SegKind::Rapid, 12, 5}});
  EXPECT_FALSE(moves[0].thread);
  EXPECT_TRUE(moves[1].thread);
  EXPECT_TRUE(moves[2].thread);
  EXPECT_FALSE(moves[3].thread);
}

// Taper R-1: the thread line runs from X8 Z5 to X9 Z-20; at Z-18 it is at 9 - 2/25.
TEST(LatheG92, TaperAndNoChamfer) {
  std::vector<Move> tapered = threadCycle({12, 5}, {9, -20}, -1, 2);
  expectMoves(tapered, {{SegKind::Rapid, 8, 5},
                        {SegKind::Line, 9 - 2.0 / 25, -18},
                        {SegKind::Line, 11 - 2.0 / 25, -20},
                        {SegKind::Rapid, 12, -20},
                        {SegKind::Rapid, 12, 5}});
  std::vector<Move> plain = threadCycle({12, 5}, {9, -20}, 0, 0);
  expectMoves(plain, {{SegKind::Rapid, 9, 5},
                      {SegKind::Line, 9, -20},
                      {SegKind::Rapid, 12, -20},
                      {SegKind::Rapid, 12, 5}});
  EXPECT_TRUE(plain[1].thread);
}

// ---------------------------------------------------------------- G74, G75

// G74 R0.5; G74 Z-10 Q3000 on the centre line from Z2: feed 3, back 0.5, feed 3.5, ...
// the last peck ends exactly at Z-10, then rapid back to Z2.
TEST(LatheG74, PeckDrillingOnTheCentreLine) {
  std::vector<Move> moves = peckCycle({0, 2}, {0, -10}, {0.5, 0, 3, 0}, false);
  expectMoves(moves, {{SegKind::Line, 0, -1},
                      {SegKind::Rapid, 0, -0.5},
                      {SegKind::Line, 0, -4},
                      {SegKind::Rapid, 0, -3.5},
                      {SegKind::Line, 0, -7},
                      {SegKind::Rapid, 0, -6.5},
                      {SegKind::Line, 0, -10},
                      {SegKind::Rapid, 0, 2}});
}

// Face grooving from X20 Z1 (radius 10) to radius 16 at Z-5, P2.5 Q4 R0.2: columns at
// 10, 12.5, 15 and 16 (the last shortened); relief 0.2 back towards the start at each
// bottom before the rapid out.
TEST(LatheG74, FaceGroovingColumnsAndRelief) {
  std::vector<Move> moves = peckCycle({10, 1}, {16, -5}, {0.5, 2.5, 4, 0.2}, false);
  std::vector<Want> want;
  for (double x : {10.0, 12.5, 15.0, 16.0}) {
    if (x != 10.0) want.push_back({SegKind::Rapid, x, 1});
    want.push_back({SegKind::Line, x, -3});
    want.push_back({SegKind::Rapid, x, -2.5});
    want.push_back({SegKind::Line, x, -5});
    want.push_back({SegKind::Rapid, x - 0.2, -5});
    want.push_back({SegKind::Rapid, x - 0.2, 1});
  }
  want.push_back({SegKind::Rapid, 10, 1});
  expectMoves(moves, want);
}

// G75 R0.5; G75 X24 Z-14 P3000 Q1500: pecks in X (P = 3 deep, back 0.5) from radius 20 to
// 12, columns every Q = 1.5 in Z from Z-10 to Z-14.
TEST(LatheG75, GroovingPecksInX) {
  std::vector<Move> moves = peckCycle({20, -10}, {12, -14}, {0.5, 3, 1.5, 0}, true);
  std::vector<Want> want;
  for (double z : {-10.0, -11.5, -13.0, -14.0}) {
    if (z != -10.0) want.push_back({SegKind::Rapid, 20, z});
    want.push_back({SegKind::Line, 17, z});
    want.push_back({SegKind::Rapid, 17.5, z});
    want.push_back({SegKind::Line, 14, z});
    want.push_back({SegKind::Rapid, 14.5, z});
    want.push_back({SegKind::Line, 12, z});
    want.push_back({SegKind::Rapid, 20, z});
  }
  want.push_back({SegKind::Rapid, 20, -10});
  expectMoves(moves, want);
}

// ---------------------------------------------------------------- G76

// M20x2.5 OD: G76 P021060 Q100 R50; G76 X16.932 Z-30 P1534 Q400 F2.5 from X25 Z5.
// k = 1.534, dd = 0.4, dmin = 0.1, d = 0.05: depths 0.4 sqrt(n) = 0.4, 0.5657, 0.6928,
// 0.8; then the increments fall below 0.1 and are raised to it: 0.9, 1.0, ... 1.4; the next
// (1.5) passes k - d = 1.484 and is clamped there; then m = 2 passes at 1.534.
// Each pass cuts 1.534 - depth above the root (radius 8.466), starts depth * tan 30 further
// back in Z (flank infeed) and ends with a 2.5 chamfer (r = 10 -> 1.0 lead).
TEST(LatheG76, PassDepthsFlankInfeedAndChamfer) {
  ThreadParams p;
  p.finishPasses = 2;
  p.chamfer = 10;
  p.angle = 60;
  p.minCut = 0.1;
  p.finishAllowance = 0.05;
  p.height = 1.534;
  p.firstCut = 0.4;
  p.lead = 2.5;
  Pt start{12.5, 5}, end{8.466, -30};
  std::vector<Move> moves = multipleThreading(start, end, p);
  std::vector<double> depths = {0.4,
                                0.4 * std::sqrt(2.0),
                                0.4 * std::sqrt(3.0),
                                0.8,
                                0.9,
                                1.0,
                                1.1,
                                1.2,
                                1.3,
                                1.4,
                                1.484,
                                1.534,
                                1.534};
  ASSERT_EQ(moves.size(), depths.size() * 6) << dump(moves);
  double tan30 = std::tan(std::numbers::pi / 6);
  for (size_t n = 0; n < depths.size(); ++n) {
    const Move* m = &moves[n * 6];
    double x = 8.466 + 1.534 - depths[n];
    double z = 5 + depths[n] * tan30;
    SCOPED_TRACE("pass " + std::to_string(n + 1));
    EXPECT_EQ(m[0].kind, SegKind::Rapid);  // shift along Z at the start X
    EXPECT_NEAR(m[0].end.x, 12.5, 1e-9);
    EXPECT_NEAR(m[0].end.z, z, 1e-9);
    EXPECT_EQ(m[1].kind, SegKind::Rapid);  // in to the pass depth
    EXPECT_NEAR(m[1].end.x, x, 1e-9);
    EXPECT_TRUE(m[2].thread);  // thread to the chamfer start, 2.5 before the end
    EXPECT_NEAR(m[2].end.x, x, 1e-9);
    EXPECT_NEAR(m[2].end.z, -27.5, 1e-9);
    EXPECT_TRUE(m[3].thread);  // 45 degree pull-out ending at the end Z
    EXPECT_NEAR(m[3].end.x, x + 2.5, 1e-9);
    EXPECT_NEAR(m[3].end.z, -30, 1e-9);
    EXPECT_EQ(m[4].kind, SegKind::Rapid);
    EXPECT_NEAR(m[4].end.x, 12.5, 1e-9);
    EXPECT_EQ(m[5].kind, SegKind::Rapid);
    EXPECT_NEAR(m[5].end.z, 5, 1e-9);
  }
  // The first three depths follow dd * sqrt(n) exactly; the last pass is at the root.
  EXPECT_NEAR(moves[1].end.x, 10 - 0.4, 1e-12);
  EXPECT_NEAR(moves[moves.size() - 5].end.x, 8.466, 1e-12);
}

// Radial infeed (a = 0), no chamfer, internal thread (start inside the root): the passes go
// outwards in X, all from the same Z.
TEST(LatheG76, RadialInfeedInternalThread) {
  ThreadParams p;
  p.finishPasses = 1;
  p.angle = 0;
  p.height = 1.0;
  p.firstCut = 0.5;
  p.lead = 1.5;
  std::vector<Move> moves = multipleThreading({8, 3}, {10, -12}, p);
  // depths 0.5, 0.7071, 0.8660, 1.0 (clamped to k - d = 1.0), then 1.0 once more.
  std::vector<double> depths = {0.5, std::sqrt(0.5), std::sqrt(0.75), 1.0, 1.0};
  ASSERT_EQ(moves.size(), depths.size() * 4) << dump(moves);
  for (size_t n = 0; n < depths.size(); ++n) {
    EXPECT_NEAR(moves[n * 4].end.x, 10 - 1.0 + depths[n], 1e-9);
    EXPECT_NEAR(moves[n * 4].end.z, 3, 1e-9);
    EXPECT_TRUE(moves[n * 4 + 1].thread);
    EXPECT_NEAR(moves[n * 4 + 1].end.z, -12, 1e-9);
  }
}

// ---------------------------------------------------------------- alarms

TEST(LatheCycleAlarms, Codes) {
  EXPECT_EQ(alarmCode(AlarmId::CycleAddressPQNotFound), "PS0061");
  EXPECT_EQ(alarmCode(AlarmId::CycleIllegalCommand), "PS0062");
  EXPECT_EQ(alarmCode(AlarmId::CycleSequenceNotFound), "PS0063");
  EXPECT_EQ(alarmCode(AlarmId::ShapeNotMonotonous), "PS0064");
  EXPECT_EQ(alarmCode(AlarmId::ShapeFirstBlockNotG00G01), "PS0065");
  EXPECT_EQ(alarmCode(AlarmId::CycleUnavailableCommand), "PS0066");
  EXPECT_EQ(alarmCode(AlarmId::CycleNotInMemory), "PS0067");
  EXPECT_EQ(alarmCode(AlarmId::ShapeLastBlockIllegal), "PS0069");
  EXPECT_STREQ(alarmMessage(AlarmId::ShapeNotMonotonous), "SHAPE PROGRAM NOT MONOTONOUSLY");
}

TEST(LatheCycleAlarms, RoughingChecks) {
  Contour good = steppedOd();
  expectAlarm([&] { roughTurning(good, {0, 0.5, 0, 0}); }, AlarmId::CycleIllegalCommand);
  expectAlarm([&] { roughFacing(good, {-1, 0.5, 0, 0}); }, AlarmId::CycleIllegalCommand);
  expectAlarm(
      [&] {
        roughTurning(contour({25, 2}, {}), {2, 0.5, 0, 0});
      },
      AlarmId::CycleSequenceNotFound);
  Contour arcFirst = contour({25, 2}, {seg(SegKind::ArcCw, 10, 2, 17.5, 2)});
  expectAlarm([&] { roughTurning(arcFirst, {2, 0.5, 0, 0}); }, AlarmId::ShapeFirstBlockNotG00G01);
  expectAlarm(
      [&] {
        patternRepeating(arcFirst, {1, 1, 0, 0, 2});
      },
      AlarmId::ShapeFirstBlockNotG00G01);
  // A groove in a type I shape (the ns block names only X).
  Contour groove = contour(
      {20, 2}, {seg(SegKind::Rapid, 10, 2), seg(SegKind::Line, 10, -10), seg(SegKind::Line, 6, -14),
                seg(SegKind::Line, 10, -18), seg(SegKind::Line, 20, -18)});
  expectAlarm([&] { roughTurning(groove, {2, 0.5, 0, 0}); }, AlarmId::ShapeNotMonotonous);
  groove.nsNamesZ = true;  // type II accepts it
  EXPECT_NO_THROW(roughTurning(groove, {2, 0.5, 0, 0}));
  // Z going back is refused even in type II.
  Contour back = contour({20, 2},
                         {seg(SegKind::Rapid, 10, 2), seg(SegKind::Line, 10, -10),
                          seg(SegKind::Line, 14, -8), seg(SegKind::Line, 20, -8)},
                         true);
  expectAlarm([&] { roughTurning(back, {2, 0.5, 0, 0}); }, AlarmId::ShapeNotMonotonous);
  // An arc that turns back along Z: a half circle from X10 Z-10 to X20 Z-10 around X15
  // Z-10, through Z-15 and back to Z-10.
  Contour bulge = contour({25, 2},
                          {seg(SegKind::Rapid, 10, 2), seg(SegKind::Line, 10, -10),
                           seg(SegKind::ArcCw, 20, -10, 15, -10), seg(SegKind::Line, 25, -12)},
                          true);
  expectAlarm([&] { roughTurning(bulge, {2, 0.5, 0, 0}); }, AlarmId::ShapeNotMonotonous);
  // Compared in least increments, a real reversal (5 mm) is still one.
  expectAlarm([&] { roughTurning(bulge, {2, 0.5, 0, 0, 0.001}); }, AlarmId::ShapeNotMonotonous);
  // A shape that goes deeper than its ns point in type I.
  Contour deeper = contour({20, 2}, {seg(SegKind::Rapid, 10, 2), seg(SegKind::Line, 8, -10),
                                     seg(SegKind::Line, 20, -10)});
  expectAlarm([&] { roughTurning(deeper, {2, 0.5, 0, 0}); }, AlarmId::ShapeNotMonotonous);
}

TEST(LatheCycleAlarms, OtherCycles) {
  expectAlarm([&] { finishing(contour({25, 2}, {})); }, AlarmId::CycleSequenceNotFound);
  expectAlarm(
      [&] {
        patternRepeating(filletShape(), {1, 1, 0, 0, 0});
      },
      AlarmId::CycleIllegalCommand);
  expectAlarm(
      [&] {
        peckCycle({10, 1}, {16, -5}, {0.5, 0, 4, 0}, false);
      },
      AlarmId::CycleIllegalCommand);
  ThreadParams p;
  p.height = 1.534;
  p.firstCut = 0.4;
  p.lead = 2.5;
  p.angle = 45;
  expectAlarm([&] { multipleThreading({12, 5}, {8.466, -30}, p); }, AlarmId::CycleIllegalCommand);
  p.angle = 60;
  EXPECT_NO_THROW(multipleThreading({12, 5}, {8.466, -30}, p));
  p.height = 0;
  expectAlarm([&] { multipleThreading({12, 5}, {8.466, -30}, p); }, AlarmId::CycleIllegalCommand);
  p.height = 1.534;
  p.firstCut = 0;
  expectAlarm([&] { multipleThreading({12, 5}, {8.466, -30}, p); }, AlarmId::CycleIllegalCommand);
  p.firstCut = 0.4;
  p.finishAllowance = 2;
  expectAlarm([&] { multipleThreading({12, 5}, {8.466, -30}, p); }, AlarmId::CycleIllegalCommand);
}
