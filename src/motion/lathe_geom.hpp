#pragma once
// Internal plane geometry shared by the lathe cycles (not part of the public interface).
//
// G71 and G72 are the same algorithm with the axes swapped and mirrored, so the roughing
// code works in a "frame" (u, w): u is the depth axis, and the cut levels step towards
// smaller u; w is the pass axis, and every pass runs towards larger w. A Pt in the frame
// holds u in .x and w in .z, so arc orientation keeps its meaning: an arc is CCW when the
// angle atan2(x - cx, z - cz) grows (G03 seen with Z across and X up, as on the control).
#include <vector>

#include "motion/lathe_cycles.hpp"

namespace ncvm::lathe::detail {

// Geometry tolerance in program units: far below one least increment (0.001 mm,
// 0.0001 in), far above double rounding on machine-sized numbers.
inline constexpr double kEps = 1e-7;

bool isArc(SegKind k);
bool near(const Pt& a, const Pt& b);
double sign(double v);  // -1, 0 or +1 (0 within kEps)

// Program (x, z) <-> frame (u, w): an optional swap of the axes, then a sign per axis.
// Every mirror or swap reverses arc orientation, hence arcKind().
struct Frame {
  bool swap = false;
  double su = 1, sw = 1;

  Pt to(const Pt& p) const;
  Pt from(const Pt& q) const;
  SegKind arcKind(SegKind k) const;
};

// One piece of a path: a line or an arc from a to b (centre c for arcs).
struct Piece {
  SegKind kind = SegKind::Line;
  Pt a, b, c;
};
using Path = std::vector<Piece>;

// A position on a path is s in [0, size]: piece floor(s) at its local parameter
// (fraction of the length for a line, of the swept angle for an arc).
struct Interval {
  double s0 = 0, s1 = 0;
};

double sweepOf(const Piece& p);  // signed swept angle of an arc, CCW positive
Pt pointAt(const Path& path, double s);

// Maximal intervals (in path order) where the path lies strictly below the level u = L.
std::vector<Interval> belowLevel(const Path& path, double level);
// The interval of `ivs` that contains s, or nullptr.
const Interval* containing(const std::vector<Interval>& ivs, double s);

double maxU(const Path& path, double s0, double s1);  // highest u on [s0, s1]
double minU(const Path& path);

// Whether an arc passes through angle phi strictly inside its sweep (not at an end).
bool sweepsThrough(const Piece& p, double phi);

// Appends moves following the path from s0 to s1 (s0 <= s1). Lines and arcs keep their
// kind; rapids become feeds unless keepRapid. Zero-length pieces are skipped.
void appendPath(const Path& path, double s0, double s1, bool keepRapid, std::vector<Move>& out);

}  // namespace ncvm::lathe::detail
