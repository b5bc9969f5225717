#include "motion/crc_geom.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace ncvm::crc::geom {

double len(P2 a) {
  return std::hypot(a.u, a.v);
}

P2 unit(P2 a) {
  double l = len(a);
  return l > 0 ? (1.0 / l) * a : P2{};
}

bool near(P2 a, P2 b, double eps) {
  return len(a - b) <= eps;
}

int turnSign(Kind k) {
  switch (k) {
    case Kind::Ccw:
      return 1;
    case Kind::Cw:
      return -1;
    case Kind::Line:
      break;
  }
  return 0;
}

P2 tangentAt(const InSeg& s, P2 p) {
  if (s.kind == Kind::Line) return unit(s.end - s.start);
  // On an arc the direction of travel is the radius turned by +-90 degrees.
  P2 radial = unit(p - s.center);
  return static_cast<double>(turnSign(s.kind)) * leftNormal(radial);
}

// Offset radius of an arc at p: a left offset moves the tool towards the centre of a G03
// arc and away from the centre of a G02 arc.
static double arcOffsetRadius(const InSeg& s, P2 p, double d, double eps) {
  double ro = len(p - s.center) - turnSign(s.kind) * d;
  if (std::abs(ro) <= eps)
    throw CrcError(AlarmId::InterferenceInCircular,
                   "arc end point falls on its centre after offset", s.tag);
  if (ro < 0)
    throw CrcError(AlarmId::NoIntersectionCrc, "cutter radius larger than the inner arc radius",
                   s.tag);
  return ro;
}

P2 offsetPoint(const InSeg& s, P2 p, double d, double eps) {
  if (s.kind == Kind::Line) return p + d * leftNormal(tangentAt(s, p));
  double ro = arcOffsetRadius(s, p, d, eps);
  return s.center + ro * unit(p - s.center);
}

Curve offsetCurve(const InSeg& s, P2 p, double d, double eps) {
  if (s.kind == Kind::Line) return {false, offsetPoint(s, p, d, eps), tangentAt(s, p), 0};
  return {true, s.center, {}, arcOffsetRadius(s, p, d, eps)};
}

// Rounding can leave a touching pair of curves a hair apart; accept a negative discriminant
// this small (relative to the sizes involved) as a single contact point.
static bool clampSmallNegative(double& disc, double scale, double eps) {
  if (disc >= 0) return true;
  if (disc < -eps * (1 + scale)) return false;
  disc = 0;
  return true;
}

static std::vector<P2> lineLine(const Curve& a, const Curve& b, double eps) {
  double c = cross(a.t, b.t);
  if (std::abs(c) <= eps) return {};
  double s = cross(b.p - a.p, b.t) / c;
  return {a.p + s * a.t};
}

static std::vector<P2> lineCircle(const Curve& l, const Curve& c, double eps) {
  P2 f = l.p - c.p;
  double b = dot(f, l.t);
  double disc = b * b - (dot(f, f) - c.r * c.r);
  if (!clampSmallNegative(disc, dot(f, f) + c.r * c.r, eps)) return {};
  double h = std::sqrt(disc);
  return {l.p + (-b - h) * l.t, l.p + (-b + h) * l.t};
}

static std::vector<P2> circleCircle(const Curve& a, const Curve& b, double eps) {
  P2 dv = b.p - a.p;
  double dd = len(dv);
  if (dd <= eps) return {};  // concentric: equal circles have no single corner point
  double x = (a.r * a.r - b.r * b.r + dd * dd) / (2 * dd);
  double h2 = a.r * a.r - x * x;
  if (!clampSmallNegative(h2, a.r * a.r + x * x, eps)) return {};
  P2 e = unit(dv);
  P2 base = a.p + x * e;
  double h = std::sqrt(h2);
  return {base + h * leftNormal(e), base - h * leftNormal(e)};
}

std::optional<P2> intersect(const Curve& a, const Curve& b, P2 ref, double eps) {
  std::vector<P2> pts;
  if (!a.circle && !b.circle)
    pts = lineLine(a, b, eps);
  else if (!a.circle)
    pts = lineCircle(a, b, eps);
  else if (!b.circle)
    pts = lineCircle(b, a, eps);
  else
    pts = circleCircle(a, b, eps);
  std::optional<P2> best;
  for (P2 p : pts)
    if (!best || len(p - ref) < len(*best - ref)) best = p;
  return best;
}

double sweep(P2 c, P2 a, P2 b, Kind k, bool full, double eps) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  double a0 = std::atan2(a.v - c.v, a.u - c.u);
  double b0 = std::atan2(b.v - c.v, b.u - c.u);
  double ang = std::fmod(turnSign(k) * (b0 - a0), kTwoPi);
  if (ang < 0) ang += kTwoPi;
  if (kTwoPi - ang <= eps) ang = 0;
  if (ang <= eps && full) ang = kTwoPi;
  return ang;
}

}  // namespace ncvm::crc::geom
