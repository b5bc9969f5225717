#include "motion/corner_round.hpp"

#include <cmath>

#include "motion/crc_geom.hpp"

namespace ncvm::cornerw {

namespace g = crc::geom;
using g::operator+;
using g::operator-;
using g::operator*;

namespace {
crc::InSeg asIn(const Seg& s) {
  crc::InSeg in;
  in.kind = s.kind;
  in.start = s.a;
  in.end = s.b;
  in.center = s.c;
  return in;
}

g::Curve curveOf(const Seg& s) {
  if (s.kind == Kind::Line) return {false, s.a, g::unit(s.b - s.a), 0};
  return {true, s.c, {}, g::len(s.a - s.c)};
}

// Whether p (on the curve of s) lies between its start and end.
bool onSeg(const Seg& s, P2 p, double eps) {
  if (s.kind == Kind::Line) {
    P2 d = s.b - s.a;
    double l = g::len(d);
    double t = g::dot(p - s.a, g::unit(d));
    return t >= -eps && t <= l + eps;
  }
  bool full = g::near(s.a, s.b, eps);
  double total = g::sweep(s.c, s.a, s.b, s.kind, full, eps);
  double part = g::sweep(s.c, s.a, p, s.kind, false, eps);
  double r = g::len(s.a - s.c);
  return part <= total + eps / std::max(r, eps) || g::near(p, s.a, eps);
}

// The point of s nearest p on its curve.
P2 foot(const Seg& s, P2 p) {
  if (s.kind == Kind::Line) {
    P2 t = g::unit(s.b - s.a);
    return s.a + g::dot(p - s.a, t) * t;
  }
  return s.c + g::len(s.a - s.c) * g::unit(p - s.c);
}
}  // namespace

Corner place(const Seg& a, const Seg& b, bool chamfer, double amount, double eps) {
  const P2 p = a.b;  // the virtual corner
  const crc::InSeg ia = asIn(a), ib = asIn(b);
  const P2 ta = g::tangentAt(ia, p), tb = g::tangentAt(ib, p);
  Corner out;
  const double turn = g::cross(ta, tb);
  if (std::abs(turn) <= 1e-12 && g::dot(ta, tb) > 0) {
    out.none = true;  // tangent blocks have no corner to break
    out.endA = out.startB = p;
    return out;
  }
  if (amount <= 0)
    throw CornerError(AlarmId::ChamferMoveTooShort, "chamfer/corner R amount must be > 0");
  if (chamfer) {
    // The points `amount` away from the corner on each block.
    g::Curve ring{true, p, {}, amount};
    auto on = [&](const Seg& s, P2 guess) {
      if (s.kind == Kind::Line) return guess;
      auto q = g::intersect(ring, curveOf(s), guess, eps);
      if (!q) throw CornerError(AlarmId::ChamferMoveTooShort, "chamfer larger than the arc");
      return *q;
    };
    out.endA = on(a, p - amount * ta);
    out.startB = on(b, p + amount * tb);
  } else {
    // The fillet centre is `amount` from both blocks on the inside of the turn.
    double d = turn > 0 ? amount : -amount;
    try {
      auto c = g::intersect(g::offsetCurve(ia, p, d, eps), g::offsetCurve(ib, p, d, eps), p, eps);
      if (!c) throw CornerError(AlarmId::ChamferMoveTooShort, "no corner arc of this radius fits");
      out.center = *c;
    } catch (const crc::CrcError&) {
      throw CornerError(AlarmId::ChamferMoveTooShort, "corner R larger than the arc radius");
    }
    out.endA = foot(a, out.center);
    out.startB = foot(b, out.center);
    out.arc = true;
    out.kind = turn > 0 ? Kind::Ccw : Kind::Cw;
  }
  if (!onSeg(a, out.endA, eps) || !onSeg(b, out.startB, eps))
    throw CornerError(AlarmId::ChamferMoveTooShort, "chamfer/corner R larger than the block");
  return out;
}

}  // namespace ncvm::cornerw
