#pragma once
// Plane geometry for cutter compensation C (internal to src/motion/crc_*.cpp): vectors,
// tangents and offset curves of programmed blocks, and the intersections the control uses
// to place corners. Offsets are signed: d > 0 shifts to the LEFT of the direction of travel
// (G41 with a positive D), d < 0 to the right, so a negative D swaps sides without any
// special case.
#include <optional>

#include "motion/cutter_comp.hpp"

namespace ncvm::crc::geom {

inline P2 operator+(P2 a, P2 b) {
  return {a.u + b.u, a.v + b.v};
}
inline P2 operator-(P2 a, P2 b) {
  return {a.u - b.u, a.v - b.v};
}
inline P2 operator*(double k, P2 a) {
  return {k * a.u, k * a.v};
}
inline double dot(P2 a, P2 b) {
  return a.u * b.u + a.v * b.v;
}
inline double cross(P2 a, P2 b) {
  return a.u * b.v - a.v * b.u;
}
double len(P2 a);
P2 unit(P2 a);  // zero stays zero
inline P2 leftNormal(P2 t) {
  return {-t.v, t.u};
}  // t turned +90 degrees
bool near(P2 a, P2 b, double eps);

// +1 for G03 (counter-clockwise), -1 for G02; 0 for lines.
int turnSign(Kind k);

// Unit direction of travel of a block at point p (p on the block: its start or end).
P2 tangentAt(const InSeg& s, P2 p);

// Where the tool centre sits at point p of block s with signed offset d, perpendicular to
// the block. For arcs the offset radius must stay positive: zero means the start or end
// falls on the centre (PS0038), negative means the tool cannot follow the arc (PS0033).
P2 offsetPoint(const InSeg& s, P2 p, double d, double eps);

// The offset path of a block as an infinite line or a full circle, so that corners can be
// intersected beyond the ends of the blocks (outer corners extend both paths).
struct Curve {
  bool circle = false;
  P2 p;          // line: a point on it; circle: the centre
  P2 t;          // line: unit direction
  double r = 0;  // circle: radius
};
Curve offsetCurve(const InSeg& s, P2 p, double d, double eps);

// The intersection of two offset paths nearest to `ref`, or none (parallel lines, circles
// that do not meet). Near-tangent contacts count as one point, because rounding must not
// turn a touching corner into an alarm.
std::optional<P2> intersect(const Curve& a, const Curve& b, P2 ref, double eps);

// Sweep of an arc from a to b around c in the arc's direction, in [0, 2*pi); `full` maps a
// zero sweep to a full turn (a programmed full circle).
double sweep(P2 c, P2 a, P2 b, Kind k, bool full, double eps);

}  // namespace ncvm::crc::geom
