#pragma once
// The arc of a move event as an angle sweep in its plane, for code that walks it in chords
// (the stock simulation, the report's tool path picture).
#include <cmath>
#include <cstddef>
#include <numbers>

#include "canon/events.hpp"

namespace ncvm {

struct ArcSweep {
  // (u, v) the arc's plane, w its normal, each a right-handed cyclic order of X Y Z:
  // G17 (X, Y, Z), G18 (Z, X, Y), G19 (Y, Z, X), so G03 is counter-clockwise in (u, v).
  int pu = 0, pv = 1, pw = 2;
  double cu = 0, cv = 0;     // the centre in (u, v)
  double r0 = 0, r1 = 0;     // the radius at the start and at the end (they differ on a spiral)
  double a0 = 0, sweep = 0;  // the start angle and the signed sweep, radians (G03 positive)
  double w0 = 0, w1 = 0;     // the normal axis at the start and at the end (a helix)

  // The point at fraction f of the sweep, written into the X Y Z entries of p.
  template <class Point>
  void place(double f, Point& p) const {
    const double ang = a0 + sweep * f, rad = r0 + (r1 - r0) * f;
    p[static_cast<size_t>(pu)] = cu + rad * std::cos(ang);
    p[static_cast<size_t>(pv)] = cv + rad * std::sin(ang);
    p[static_cast<size_t>(pw)] = w0 + f * (w1 - w0);
  }
};

inline ArcSweep arcSweepOf(const MoveEvent& e) {
  ArcSweep a;
  a.pu = e.plane == 18 ? 2 : e.plane == 19 ? 1 : 0;
  a.pv = e.plane == 18 ? 0 : e.plane == 19 ? 2 : 1;
  a.pw = 3 - a.pu - a.pv;
  auto at = [](const AxisArray& v, int k) { return v[static_cast<size_t>(k)]; };
  a.cu = e.center[static_cast<size_t>(a.pu)], a.cv = e.center[static_cast<size_t>(a.pv)];
  const double su = at(e.start, a.pu) - a.cu, sv = at(e.start, a.pv) - a.cv;
  const double eu = at(e.end, a.pu) - a.cu, ev = at(e.end, a.pv) - a.cv;
  a.r0 = std::hypot(su, sv), a.r1 = std::hypot(eu, ev);
  a.a0 = std::atan2(sv, su);
  a.sweep = std::atan2(ev, eu) - a.a0;
  const double tau = 2 * std::numbers::pi;
  if (e.mode == MoveMode::Ccw) {
    while (a.sweep <= 1e-12) a.sweep += tau;  // end = start: a full circle
  } else {
    while (a.sweep >= -1e-12) a.sweep -= tau;
  }
  a.w0 = at(e.start, a.pw), a.w1 = at(e.end, a.pw);
  return a;
}

}  // namespace ncvm
