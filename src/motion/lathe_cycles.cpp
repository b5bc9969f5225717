// G70, G73 and the single-motion lathe cycles: G90/G94, G92, G74/G75 and G76
// (fanuc-reference D.2, D.3). G71/G72 live in lathe_rough.cpp.
#include "motion/lathe_cycles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "motion/lathe_geom.hpp"

namespace ncvm::lathe {

namespace {

using detail::kEps;

// Runaway guard (not a Fanuc limit): one block must not expand into millions of moves.
constexpr int kMaxRepeats = 100000;

// Collects moves, dropping those that do not move (a zero retract, a zero taper).
class Moves {
 public:
  explicit Moves(const Pt& from) : pos_(from) {}
  void add(SegKind kind, const Pt& to, bool thread = false) {
    if (detail::near(pos_, to)) return;
    Move m;
    m.kind = kind;
    m.end = to;
    m.thread = thread;
    out_.push_back(m);
    pos_ = to;
  }
  void rapid(const Pt& to) { add(SegKind::Rapid, to); }
  void feed(const Pt& to) { add(SegKind::Line, to); }
  std::vector<Move> take() { return std::move(out_); }

 private:
  Pt pos_;
  std::vector<Move> out_;
};

void checkShape(const Contour& c) {
  if (c.segs.empty()) throw CycleError(AlarmId::CycleSequenceNotFound, "empty shape program");
  if (detail::isArc(c.segs.front().kind))
    throw CycleError(AlarmId::ShapeFirstBlockNotG00G01, "first shape block is an arc");
}

// The shape translated by (dx, dz): every end point and arc centre moves, so arcs keep
// their radius (the allowance of G71-G73 is a translation, not an offset curve).
void appendShifted(const Contour& c, double dx, double dz, std::vector<Move>& out) {
  for (const auto& s : c.segs) {
    Move m;
    m.kind = s.kind;
    m.end = {s.end.x + dx, s.end.z + dz};
    if (detail::isArc(s.kind)) m.center = {s.center.x + dx, s.center.z + dz};
    out.push_back(m);
  }
}

Move rapidTo(const Pt& p) {
  Move m;
  m.kind = SegKind::Rapid;
  m.end = p;
  return m;
}

// The threading motion of G92/G76 from `from` (on the thread line) to the end Z: a thread
// move, then, when there is a chamfer, a 45 degree pull-out over its last `chamfer` of Z
// (Fanuc parameter 5130 sets the amount and 5131 the angle, 45 by default).
void threadMotion(Moves& mv, const Pt& from, const Pt& end, double chamfer, double outward) {
  double length = std::abs(end.z - from.z);
  double c = std::min(chamfer, length);
  if (c <= kEps) {
    mv.add(SegKind::Line, end, true);
    return;
  }
  double zc = end.z - detail::sign(end.z - from.z) * c;
  double xc = end.x + (from.x - end.x) * (zc - end.z) / (from.z - end.z);
  mv.add(SegKind::Line, {xc, zc}, true);
  mv.add(SegKind::Line, {xc + outward * c, end.z}, true);
}

// Which way is "out of the material" in X: towards the start point (OD: +X, ID: -X).
double outwardX(const Pt& start, const Pt& end) {
  double s = detail::sign(start.x - end.x);
  return s == 0 ? 1.0 : s;
}

// Cumulative G76 infeeds (radius, from the crest): dd*sqrt(n) so each pass removes about
// the same area; an increment below dmin is raised to dmin; roughing stops at k - d; then
// m passes at full depth k (the first of them takes the finishing allowance d).
std::vector<double> threadDepths(const ThreadParams& p) {
  std::vector<double> depths;
  double roughEnd = p.height - p.finishAllowance;
  double done = 0;
  for (int n = 1; done < roughEnd - kEps; ++n) {
    if (n > kMaxRepeats)
      throw CycleError(AlarmId::CycleIllegalCommand, "G76 first cut too small for the height");
    double target = p.firstCut * std::sqrt(static_cast<double>(n));
    if (target - done < p.minCut) target = done + p.minCut;
    if (target > roughEnd - kEps) target = roughEnd;
    depths.push_back(target);
    done = target;
  }
  for (int i = 0; i < p.finishPasses; ++i) depths.push_back(p.height);
  return depths;
}

void checkThread(const Pt& start, const Pt& end, const ThreadParams& p) {
  static constexpr std::array<int, 6> kAngles = {0, 29, 30, 55, 60, 80};
  auto bad = [](const std::string& why) { throw CycleError(AlarmId::CycleIllegalCommand, why); };
  if (p.height <= 0) bad("G76 thread height k must be > 0");
  if (p.firstCut <= 0) bad("G76 first depth of cut must be > 0");
  if (p.minCut < 0 || p.finishAllowance < 0 || p.lead < 0) bad("G76 negative value");
  if (p.finishAllowance > p.height) bad("G76 finishing allowance larger than the height");
  if (p.finishPasses < 1 || p.finishPasses > 99) bad("G76 finishing count m must be 1-99");
  if (p.chamfer < 0 || p.chamfer > 99) bad("G76 chamfer r must be 00-99");
  if (std::find(kAngles.begin(), kAngles.end(), p.angle) == kAngles.end())
    bad("G76 tool angle must be 80, 60, 55, 30, 29 or 0");
  if (std::abs(end.z - start.z) <= kEps) bad("G76 without a Z travel");
}

}  // namespace

std::vector<Move> finishing(const Contour& c) {
  checkShape(c);
  std::vector<Move> out;
  for (size_t i = 0; i < c.segs.size(); ++i) {
    const ContourSeg& s = c.segs[i];
    Move m;
    m.kind = s.kind;
    m.end = s.end;
    if (detail::isArc(s.kind)) m.center = s.center;
    m.contourIndex = static_cast<int>(i);
    out.push_back(m);
  }
  out.push_back(rapidTo(c.start));
  return out;
}

// G73: d passes of the whole shape, each translated by the allowance plus a share of the
// relief that shrinks evenly from (di, dk) on the first pass to 0 on the last. Every pass
// starts with the ns block in its own mode from A and ends with a rapid back to A. With
// d = 1 the single pass is the last one (allowance only): the formula has no first pass.
std::vector<Move> patternRepeating(const Contour& c, const PatternParams& p) {
  checkShape(c);
  if (p.divisions < 1)
    throw CycleError(AlarmId::CycleIllegalCommand, "G73 number of divisions must be >= 1");
  if (p.divisions > kMaxRepeats)
    throw CycleError(AlarmId::CycleIllegalCommand, "G73 number of divisions too large");
  std::vector<Move> out;
  for (int k = 1; k <= p.divisions; ++k) {
    double share = p.divisions == 1 ? 0.0 : double(p.divisions - k) / double(p.divisions - 1);
    appendShifted(c, p.allowX + p.reliefX * share, p.allowZ + p.reliefZ * share, out);
    out.push_back(rapidTo(c.start));
  }
  return out;
}

// G90: rapid in X to the cut start (end X + taper), feed to the end point, feed out in X
// to the start X, rapid back in Z. G94 is the same with the axes swapped (rapid in Z,
// feed along X). The taper is start minus end measured along the infeed axis, so the four
// sign cases of U, W and R need no special handling.
std::vector<Move> singleCycle(const Pt& start, const Pt& end, double taper, bool face) {
  Moves mv(start);
  if (!face) {
    mv.rapid({end.x + taper, start.z});
    mv.feed(end);
    mv.feed({start.x, end.z});
  } else {
    mv.rapid({start.x, end.z + taper});
    mv.feed(end);
    mv.feed({end.x, start.z});
  }
  mv.rapid(start);
  return mv.take();
}

// G92: rapid in X to the thread start, thread to the end Z (with the chamfer pull-out),
// rapid out in X to the start X, rapid back in Z.
std::vector<Move> threadCycle(const Pt& start, const Pt& end, double taper, double chamferLength) {
  Moves mv(start);
  Pt from{end.x + taper, start.z};
  mv.rapid(from);
  threadMotion(mv, from, end, chamferLength, outwardX(start, end));
  mv.rapid({start.x, end.z});
  mv.rapid(start);
  return mv.take();
}

namespace {

// G74/G75 axes: `cut` is the pecking axis (Z for G74, X for G75), `across` the axis the
// columns step along.
struct PeckAxes {
  bool alongX;
  double cut(const Pt& q) const { return alongX ? q.x : q.z; }
  double across(const Pt& q) const { return alongX ? q.z : q.x; }
  Pt at(double c, double a) const { return alongX ? Pt{c, a} : Pt{a, c}; }
};

// One column at `a`: feed by `peck`, rapid back by e, feed peck + e, ..., the last peck
// stopping exactly at c1 (a zero peck feeds straight to c1).
void peckColumn(Moves& mv, const PeckAxes& ax, double c0, double c1, double a, double peck,
                double retract, int& count) {
  double sc = detail::sign(c1 - c0);
  if (sc == 0) return;
  for (double c = c0;;) {
    if (++count > kMaxRepeats)
      throw CycleError(AlarmId::CycleIllegalCommand, "G74/G75 too many pecks");
    double next = peck > kEps ? c + sc * peck : c1;
    if (sc * (next - c1) >= -kEps) next = c1;
    mv.feed(ax.at(next, a));
    if (next == c1) return;
    mv.rapid(ax.at(next - sc * retract, a));
    c = next;
  }
}

}  // namespace

// G74 (alongX false) pecks along Z, with a column at every shift along X up to the end X;
// G75 (alongX true) is the same with X and Z swapped. As the addresses carry them, `step`
// is P = di, the X amount (G74: the shift between columns, G75: the peck depth) and `peck`
// is Q = dk, the Z amount (G74: the peck depth, G75: the shift). At the bottom of each
// column the tool backs off by the relief against the shift direction (only when the cycle
// shifts), rapids back to the start level, then rapids across to the next column (the last
// one shortened to end exactly at the end point); finally back to the start point.
std::vector<Move> peckCycle(const Pt& start, const Pt& end, const PeckParams& p, bool alongX) {
  if (p.retract < 0 || p.step < 0 || p.peck < 0 || p.relief < 0)
    throw CycleError(AlarmId::CycleIllegalCommand, "G74/G75 negative amount");
  PeckAxes ax{alongX};
  double peck = alongX ? p.step : p.peck;
  double shift = alongX ? p.peck : p.step;
  double c0 = ax.cut(start), c1 = ax.cut(end), a0 = ax.across(start), a1 = ax.across(end);
  double sa = detail::sign(a1 - a0);
  if (sa != 0 && shift <= kEps)
    throw CycleError(AlarmId::CycleIllegalCommand, "G74/G75 shift between passes is zero");

  Moves mv(start);
  int count = 0;
  for (double a = a0;;) {
    mv.rapid(ax.at(c0, a));
    peckColumn(mv, ax, c0, c1, a, peck, p.retract, count);
    double backedOff = a - sa * p.relief;
    mv.rapid(ax.at(c1, backedOff));
    mv.rapid(ax.at(c0, backedOff));
    if (sa == 0 || sa * (a - a1) >= -kEps) break;
    a = sa * (a + sa * shift - a1) >= -kEps ? a1 : a + sa * shift;
  }
  mv.rapid(start);
  return mv.take();
}

// G76: one G92-like pass per depth from threadDepths(). The end point is the thread root
// at the end Z; the pass at depth delta runs on the line k - delta above the root (taper i
// kept). Single-edge flank infeed (Fanuc's default): each pass starts delta * tan(a/2)
// further back along Z, so the trailing flank of the tool stays on the thread's flank and
// only the leading edge cuts. Each pass: rapid to the shifted start Z (at the start X),
// rapid in X to the thread line, thread (with the r chamfer, r/10 leads long, 45 degrees),
// rapid out in X, rapid back to the start point.
std::vector<Move> multipleThreading(const Pt& start, const Pt& end, const ThreadParams& p) {
  checkThread(start, end, p);
  double out = outwardX(start, end);
  double sz = detail::sign(end.z - start.z);
  double tanHalf = std::tan(p.angle * std::numbers::pi / 360.0);
  double chamfer = p.chamfer * 0.1 * p.lead;
  Moves mv(start);
  for (double depth : threadDepths(p)) {
    double xEnd = end.x + out * (p.height - depth);
    double zStart = start.z - sz * depth * tanHalf;
    // On the taper line through (xEnd + i, start Z) and (xEnd, end Z).
    double xStart = xEnd + p.taper * (zStart - end.z) / (start.z - end.z);
    mv.rapid({start.x, zStart});
    mv.rapid({xStart, zStart});
    threadMotion(mv, {xStart, zStart}, {xEnd, end.z}, chamfer, out);
    mv.rapid({start.x, end.z});
    mv.rapid(start);
  }
  return mv.take();
}

}  // namespace ncvm::lathe
