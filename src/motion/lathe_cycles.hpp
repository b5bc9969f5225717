#pragma once
// Lathe canned cycles as pure geometry (fanuc-reference D.2, D.3): given the cycle's
// words and, for G70-G73, the finishing contour, produce the moves the control makes.
// The executor reads the words and the P..Q contour blocks, calls these planners and
// emits the moves; nothing here knows about programs, variables or the trace.
//
// Coordinates are (x, z) with x a RADIUS, in program units (mm or inch); the executor
// converts diameters. Feeds are not part of the plan: every Feed/Arc move is at the
// cycle's cutting feed unless `contourIndex` says it is a contour block (G70 uses that
// block's own F/S).
#include <stdexcept>
#include <string>
#include <vector>

#include "core/alarm.hpp"

namespace ncvm::lathe {

struct Pt {
  double x = 0, z = 0;
};

enum class SegKind { Rapid, Line, ArcCw, ArcCcw };

// One contour block ns..nf after evaluation: where it ends, and for arcs the centre.
// G02/G03 are as programmed (the executor has already applied the plane and any mirror).
struct ContourSeg {
  SegKind kind = SegKind::Line;
  Pt end;
  Pt center;            // arcs only
  int blockIndex = -1;  // program block that produced it (for the trace)
  int comp = -1;        // G40/G41/G42 (x10) in effect for the block; -1: as the block before
};

struct Contour {
  Pt start;  // the cycle start point A (where the tool is when the cycle is commanded)
  std::vector<ContourSeg> segs;  // ns..nf in order; segs[0] is the ns block
  bool nsNamesZ = false;         // the ns block names Z/W too: G71 type II (G72: names X/U)
};

struct Move {
  SegKind kind = SegKind::Line;
  Pt end;
  Pt center;              // arcs only
  int contourIndex = -1;  // index into Contour::segs when the move follows a contour block
  bool thread = false;    // synchronised threading feed (G92/G76/G32)
  // Tool-nose radius compensation (G70, G90, G94 under G41/G42): the move ends on the
  // imaginary tip `end`; `programmed` is the programmed point and `nose` the nose centre.
  bool compensated = false;
  Pt programmed, nose;
};

// Raised for the cycle alarms PS0061-PS0069 (and PS0062 for bad depths).
struct CycleError : std::runtime_error {
  CycleError(AlarmId alarm, const std::string& detail) : std::runtime_error(detail), id(alarm) {}
  AlarmId id;
};

// G71 (rough turning) and G72 (rough facing). depth = Δd (radius), retract = e,
// allowX = Δu/2 (radius, signed: + OD, - ID), allowZ = Δw. increment = the least input
// increment in program units: the shape checks compare positions in it (0 = exact).
struct RoughParams {
  double depth = 0, retract = 0, allowX = 0, allowZ = 0;
  double increment = 0;
};
std::vector<Move> roughTurning(const Contour& c, const RoughParams& p);  // G71
std::vector<Move> roughFacing(const Contour& c, const RoughParams& p);   // G72

// G73 pattern repeating: relief Δi (X, radius) and Δk (Z), d divisions.
struct PatternParams {
  double reliefX = 0, reliefZ = 0, allowX = 0, allowZ = 0;
  int divisions = 1;
};
std::vector<Move> patternRepeating(const Contour& c, const PatternParams& p);

// G70: the contour itself, then a rapid back to the start point.
std::vector<Move> finishing(const Contour& c);

// G90 (OD/ID cutting, `face` false) and G94 (end-face cutting, `face` true) from the start
// point to the end point (x, z) with taper r (radius difference start - end along the
// cutting direction).
std::vector<Move> singleCycle(const Pt& start, const Pt& end, double taper, bool face);

// G92 threading cycle: like G90 with a thread move and an optional chamfer at the end
// (chamferLength in program units along Z, 0 = none).
std::vector<Move> threadCycle(const Pt& start, const Pt& end, double taper, double chamferLength);

// G74 (face peck drilling / grooving, `alongX` false) and G75 (OD grooving, true).
// e = retract per peck, di = step between passes (P, radius), dk = peck depth (Q),
// dd = relief at the bottom (R).
struct PeckParams {
  double retract = 0, step = 0, peck = 0, relief = 0;
};
std::vector<Move> peckCycle(const Pt& start, const Pt& end, const PeckParams& p, bool alongX);

// G76 multiple threading: m finishing passes, chamfer r (0.1 lead units), tool angle a,
// minimum cut dmin, finishing allowance d, taper i, thread height k, first cut dd, lead L.
struct ThreadParams {
  int finishPasses = 1, chamfer = 0, angle = 60;
  double minCut = 0, finishAllowance = 0, taper = 0, height = 0, firstCut = 0, lead = 0;
};
std::vector<Move> multipleThreading(const Pt& start, const Pt& end, const ThreadParams& p);

}  // namespace ncvm::lathe
