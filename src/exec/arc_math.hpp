#pragma once
// The arc arithmetic the general path (motion.cpp, transforms.cpp) and the straight path
// (straight_move.cpp) share, so the two give the same doubles for the same arc. Coordinates
// are nanometres in the plane of the arc (at most 2e18: their squares stay far inside double).
#include <cmath>
#include <numbers>

namespace ncvm {

// The distance of two points of the plane: the plain square root, a few times cheaper than
// std::hypot, which guards against overflow and underflow that nanometre integers never reach.
inline double planeDistance(double du, double dv) {
  return std::sqrt(du * du + dv * dv);
}

// The angle an arc sweeps from the start (su, sv) to the end (eu, ev) around the centre
// (cu, cv), in (0, 2π]: 2π when the end is the start (a full circle), and when the end lies
// in the start's direction from the centre. One atan2 of the cross and dot products of the two
// radius vectors instead of the difference of two angles: half the libm work, and exact where
// the angle is small.
inline double arcSweep(double su, double sv, double eu, double ev, double cu, double cv, bool cw) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  if (eu == su && ev == sv) return kTwoPi;
  const double au = su - cu, av = sv - cv, bu = eu - cu, bv = ev - cv;
  const double ccw = std::atan2(au * bv - av * bu, au * bu + av * bv);  // in [-π, π]
  const double sweep = cw ? -ccw : ccw;
  return sweep <= 0 ? sweep + kTwoPi : sweep;
}

}  // namespace ncvm
