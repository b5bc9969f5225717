#pragma once
// The volume a milling tool sweeps, cut out of a height field. Each function lowers every
// cell of the field to the lower envelope of the tool moved along the path, exactly at the
// cell centre (no sampling along the path), and returns the largest amount it lowered a
// cell: the penetration, which for a rapid or a holder is a collision.
//
// Rows can be split among threads: a Stripe names the rows one call may touch, so threads
// running the same moves on different stripes never share a cell (mill_stock_sim.hpp).
#include <array>

#include "sim/heightfield.hpp"
#include "sim/mill_tools.hpp"

namespace ncvm {

using Point3 = std::array<double, 3>;

// Rows j with (j >> kStripeShift) % count == index; {0, 1} is every row.
struct Stripe {
  static constexpr int kStripeShift = 4;  // 16-row stripes: small enough to balance two cores
  int index = 0, count = 1;
  bool owns(int j) const { return count == 1 || ((j >> kStripeShift) % count) == index; }
};

enum class SweepMode : bool { Cut, Measure };  // Measure: penetration only, field unchanged

// Straight move of the tool tip from a to b. startCut: this tool standing at `a` was cut into
// this field already (an earlier cut of the same tool passed through `a`, e.g. the move
// before ended there). Heights only go down, so cells where the tool at `a` is the lowest
// point of the move cannot change: the kernel skips them, about half of the footprint of a
// short move. The result is the same as without the flag (to float rounding).
float sweepLine(HeightField& f, const MillTool& tool, const Point3& a, const Point3& b,
                Stripe stripe = {}, SweepMode mode = SweepMode::Cut, bool startCut = false);

// Whether a move from `a` continues one that ended at `end` closely enough for startCut
// (1 nm: far below a float height's resolution at these sizes).
inline bool continuesFrom(const Point3& end, const Point3& a) {
  auto near = [](double u, double v) { return u - v <= 1e-6 && v - u <= 1e-6; };
  return near(end[0], a[0]) && near(end[1], a[1]) && near(end[2], a[2]);
}

// Circular move in the XY plane at constant Z: centre (cx, cy), from angle a0 through
// `sweep` radians (positive counter-clockwise, |sweep| <= 2 pi), tip at height z.
float sweepArcXY(HeightField& f, const MillTool& tool, double cx, double cy, double radius,
                 double a0, double sweep, double z, Stripe stripe = {},
                 SweepMode mode = SweepMode::Cut);

// The sweep of the tool's flat-bottomed cylinder of radius r lifted by `lift` above the tip:
// a holder or a shank, measured only.
float holderPenetration(const HeightField& f, double r, double lift, const Point3& a,
                        const Point3& b, Stripe stripe = {});

}  // namespace ncvm
