#include "motion/lathe_geom.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncvm::lathe::detail {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
// Angle fraction below which an arc "ends at" an angle rather than passing it: the
// overshoot it allows is r * (1 - cos(1e-6 * 2pi)), a few 1e-11 of the radius.
constexpr double kAngleTol = 1e-6;

double angleOf(const Pt& p, const Pt& c) {
  return std::atan2(p.x - c.x, p.z - c.z);
}
double radiusOf(const Pt& p, const Pt& c) {
  return std::hypot(p.x - c.x, p.z - c.z);
}

// Local parameter (0..1 over the sweep) at which an arc reaches angle phi, or -1.
double paramOfAngle(const Piece& p, double phi) {
  double sweep = sweepOf(p);
  if (sweep == 0) return -1;
  double d = sweep > 0 ? phi - angleOf(p.a, p.c) : angleOf(p.a, p.c) - phi;
  d = std::fmod(d, kTwoPi);
  if (d < 0) d += kTwoPi;
  return d / std::abs(sweep);
}

Pt at(const Piece& p, double t) {
  if (t <= 0) return p.a;
  if (t >= 1) return p.b;
  if (!isArc(p.kind)) return {p.a.x + t * (p.b.x - p.a.x), p.a.z + t * (p.b.z - p.a.z)};
  double theta = angleOf(p.a, p.c) + t * sweepOf(p);
  // Blend the radii so a slightly unequal arc (within parameter 3410) still ends on b.
  double r = radiusOf(p.a, p.c) + t * (radiusOf(p.b, p.c) - radiusOf(p.a, p.c));
  return {p.c.x + r * std::sin(theta), p.c.z + r * std::cos(theta)};
}

// Parameters strictly inside (0, 1) where the piece crosses u = level.
std::vector<double> crossings(const Piece& p, double level) {
  std::vector<double> ts;
  if (!isArc(p.kind)) {
    double du = p.b.x - p.a.x;
    if (du != 0) ts.push_back((level - p.a.x) / du);
  } else {
    double r = radiusOf(p.a, p.c);
    double k = r > 0 ? (level - p.c.x) / r : 2;
    if (std::abs(k) <= 1) {
      double alpha = std::asin(k);  // circle-line intersection: sin(theta) = k
      ts.push_back(paramOfAngle(p, alpha));
      ts.push_back(paramOfAngle(p, std::numbers::pi - alpha));
    }
  }
  std::erase_if(ts, [](double t) { return !(t > 0 && t < 1); });
  std::sort(ts.begin(), ts.end());
  return ts;
}

// Highest (or lowest, sign -1) u of a piece between local parameters t0 and t1.
double extremeU(const Piece& p, double t0, double t1, double sgn) {
  double best = std::max(sgn * at(p, t0).x, sgn * at(p, t1).x);
  if (isArc(p.kind)) {
    double t = paramOfAngle(p, sgn * std::numbers::pi / 2);
    if (t >= t0 && t <= t1) best = std::max(best, sgn * at(p, t).x);
  }
  return sgn * best;
}

}  // namespace

bool isArc(SegKind k) {
  return k == SegKind::ArcCw || k == SegKind::ArcCcw;
}

bool near(const Pt& a, const Pt& b) {
  return std::abs(a.x - b.x) <= kEps && std::abs(a.z - b.z) <= kEps;
}

double sign(double v) {
  return v > kEps ? 1.0 : v < -kEps ? -1.0 : 0.0;
}

Pt Frame::to(const Pt& p) const {
  double depth = swap ? p.z : p.x;
  double pass = swap ? p.x : p.z;
  return {su * depth, sw * pass};
}

Pt Frame::from(const Pt& q) const {
  double depth = su * q.x;  // su and sw are +-1, their own inverses
  double pass = sw * q.z;
  return swap ? Pt{pass, depth} : Pt{depth, pass};
}

SegKind Frame::arcKind(SegKind k) const {
  bool flips = ((su < 0) != (sw < 0)) != swap;
  if (!flips || !isArc(k)) return k;
  return k == SegKind::ArcCw ? SegKind::ArcCcw : SegKind::ArcCw;
}

double sweepOf(const Piece& p) {
  if (!isArc(p.kind) || near(p.a, p.b)) return 0;
  double d = angleOf(p.b, p.c) - angleOf(p.a, p.c);
  if (p.kind == SegKind::ArcCcw) {
    while (d <= 0) d += kTwoPi;
  } else {
    while (d >= 0) d -= kTwoPi;
  }
  return d;
}

Pt pointAt(const Path& path, double s) {
  if (path.empty()) return {};
  double last = static_cast<double>(path.size() - 1);
  double i = std::clamp(std::floor(s), 0.0, last);
  return at(path[static_cast<size_t>(i)], s - i);
}

std::vector<Interval> belowLevel(const Path& path, double level) {
  std::vector<Interval> out;
  for (size_t i = 0; i < path.size(); ++i) {
    std::vector<double> ts = crossings(path[i], level);
    ts.insert(ts.begin(), 0.0);
    ts.push_back(1.0);
    double base = static_cast<double>(i);
    for (size_t k = 0; k + 1 < ts.size(); ++k) {
      // Between two crossings the piece is wholly above or below: test the middle.
      if (at(path[i], (ts[k] + ts[k + 1]) / 2).x >= level - kEps) continue;
      double s0 = base + ts[k], s1 = base + ts[k + 1];
      if (!out.empty() && out.back().s1 >= s0 - 1e-12)
        out.back().s1 = s1;
      else
        out.push_back({s0, s1});
    }
  }
  return out;
}

const Interval* containing(const std::vector<Interval>& ivs, double s) {
  for (const auto& iv : ivs)
    if (s >= iv.s0 - 1e-9 && s <= iv.s1 + 1e-9) return &iv;
  return nullptr;
}

double maxU(const Path& path, double s0, double s1) {
  double best = pointAt(path, s0).x;
  for (size_t i = 0; i < path.size(); ++i) {
    double base = static_cast<double>(i);
    double t0 = std::max(0.0, s0 - base), t1 = std::min(1.0, s1 - base);
    if (t0 <= t1) best = std::max(best, extremeU(path[i], t0, t1, 1));
  }
  return best;
}

double minU(const Path& path) {
  double best = pointAt(path, 0).x;
  for (const auto& p : path) best = std::min(best, extremeU(p, 0, 1, -1));
  return best;
}

bool sweepsThrough(const Piece& p, double phi) {
  double t = paramOfAngle(p, phi);
  return t > kAngleTol && t < 1 - kAngleTol;
}

void appendPath(const Path& path, double s0, double s1, bool keepRapid, std::vector<Move>& out) {
  for (size_t i = 0; i < path.size(); ++i) {
    double base = static_cast<double>(i);
    double t0 = std::max(0.0, s0 - base), t1 = std::min(1.0, s1 - base);
    if (t0 >= t1) continue;
    const Piece& p = path[i];
    Pt from = at(p, t0), to = at(p, t1);
    if (near(from, to)) continue;
    Move m;
    m.kind = p.kind == SegKind::Rapid && !keepRapid ? SegKind::Line : p.kind;
    m.end = to;
    if (isArc(p.kind)) m.center = p.c;
    out.push_back(m);
  }
}

}  // namespace ncvm::lathe::detail
