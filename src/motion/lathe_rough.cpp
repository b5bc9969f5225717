// G71 (stock removal in turning) and G72 (stock removal in facing), types I and II.
//
// Both run in a frame (lathe_geom.hpp) where levels step towards smaller u and passes
// run towards larger w; G72 is G71 with X and Z swapped. Behaviour follows fanuc-reference
// D.3 and Fanuc-compatible controls' descriptions (Tomatech TAC-100XT G71 steps, HUST H6D-T
// G71 notes, Haas G71 type 2 notes):
//  - the cut direction along the depth axis is the direction of A -> A' (the ns block);
//  - the finishing allowance translates the contour by (du/2, dw);
//  - the infeed to each level uses the ns block's mode (G00 rapid, G01 feed);
//  - each pass feeds parallel to the pass axis until it meets the shifted contour, then
//    retracts at 45 degrees by e at feed and returns at rapid to the start column;
//  - levels continue while they are short of the shifted contour's deepest point; the
//    thinner remainder is left to the final pass, which moves to the shifted A' and follows
//    the whole shifted contour (the "semi-finishing" pass), then rapids back to A.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "motion/lathe_cycles.hpp"
#include "motion/lathe_geom.hpp"

namespace ncvm::lathe {

namespace {

using detail::Frame;
using detail::Interval;
using detail::kEps;
using detail::Path;
using detail::Piece;

// A runaway guard, not a Fanuc limit: a tiny depth of cut on a long contour would
// otherwise build millions of moves from one block.
constexpr int kMaxLevels = 100000;

double depthOf(const Pt& p, bool facing) {
  return facing ? p.z : p.x;
}
double passOf(const Pt& p, bool facing) {
  return facing ? p.x : p.z;
}

// The frame's orientation comes from the geometry, as on the control: the infeed runs
// from A towards A' (the ns block); the passes run from the ns point towards the contour's
// end. When A' does not move along the depth axis, the allowance's sign (+ OD, - ID)
// decides, and failing that the contour point farthest from A.
Frame chooseFrame(const Contour& c, const RoughParams& p, bool facing) {
  const Pt& a = c.start;
  const Pt& ns = c.segs.front().end;
  const Pt& last = c.segs.back().end;
  double sd = detail::sign(depthOf(ns, facing) - depthOf(a, facing));
  if (sd == 0) sd = -detail::sign(facing ? p.allowZ : p.allowX);
  if (sd == 0) {
    double far = 0;
    for (const auto& s : c.segs) {
      double d = depthOf(s.end, facing) - depthOf(a, facing);
      if (std::abs(d) > std::abs(far)) far = d;
    }
    sd = detail::sign(far);
  }
  if (sd == 0) sd = -1;
  double sp = detail::sign(passOf(last, facing) - passOf(ns, facing));
  if (sp == 0) sp = detail::sign(passOf(last, facing) - passOf(a, facing));
  if (sp == 0) sp = -1;
  return Frame{facing, -sd, sp};
}

// Type I: the shape after A' must rise steadily away from the infeed and run steadily
// along the passes. Type II: only the pass axis must be monotonic (pockets allowed).
// Positions are compared in least increments, as the control holds them: an arc whose
// computed extreme passes its end point by less than half an increment (floating-point
// noise of the centre, e.g. 2e-7 mm) does not turn back.
void checkMonotonic(const Path& path, size_t first, bool typeTwo, double increment) {
  constexpr double pi = std::numbers::pi;
  const double tol = std::max(kEps, increment / 2);
  for (size_t i = first; i < path.size(); ++i) {
    const Piece& p = path[i];
    bool back = p.b.z < p.a.z - tol;
    bool down = !typeTwo && p.b.x < p.a.x - tol;
    if (detail::isArc(p.kind)) {
      // An extreme inside the sweep reverses the axis when it lies beyond the end it turns
      // back to: past b for a maximum, before a for a minimum.
      double r = std::hypot(p.a.x - p.c.x, p.a.z - p.c.z);
      auto passes = [&](double phi, double overshoot) {
        return detail::sweepsThrough(p, phi) && overshoot > tol;
      };
      back = back || passes(0, p.c.z + r - p.b.z) || passes(pi, p.a.z - (p.c.z - r));
      down = down || (!typeTwo &&
                      (passes(pi / 2, p.c.x + r - p.b.x) || passes(-pi / 2, p.a.x - (p.c.x - r))));
    }
    if (back || down)
      throw CycleError(AlarmId::ShapeNotMonotonous,
                       "shape block " + std::to_string(i - first + 2) +
                           (back ? " reverses along the cutting direction"
                                 : " turns back towards the infeed (type I)"));
  }
}

// Plans the passes of one G71/G72 cycle in the frame.
class Rougher {
 public:
  Rougher(Path path, size_t contourFirst, Pt home, Pt nsPoint, const RoughParams& p, bool typeTwo,
          SegKind infeed)
      : path_(std::move(path)),
        first_(contourFirst),
        home_(home),
        ns_(nsPoint),
        depth_(p.depth),
        e_(p.retract),
        typeTwo_(typeTwo),
        infeed_(infeed),
        pos_(home) {}

  std::vector<Move> run() {
    double bottom = detail::minU(path_);
    double prev = home_.x;
    // A shape of the ns block alone has nothing to rough: only the final pass is left.
    for (int k = 1; path_.size() > first_; ++k) {
      double level = home_.x - k * depth_;
      if (level <= bottom + kEps) break;
      if (k > kMaxLevels)
        throw CycleError(AlarmId::CycleIllegalCommand, "depth of cut too small for the shape");
      cutLevel(level, prev);
      prev = level;
    }
    finalPass();
    return std::move(out_);
  }

 private:
  void go(SegKind kind, const Pt& to) {
    if (detail::near(pos_, to)) return;
    Move m;
    m.kind = kind;
    m.end = to;
    out_.push_back(m);
    pos_ = to;
  }
  void follow(double s0, double s1) {
    detail::appendPath(path_, s0, s1, false, out_);
    pos_ = detail::pointAt(path_, s1);
  }
  // Away from the part by e, and back along the pass by `back` (e: 45 degrees).
  void retract(double back) { go(SegKind::Line, {pos_.x + e_, pos_.z - back}); }

  // Rapid over everything between path positions sa and sb, then down to `to`.
  void travel(const Pt& to, double sa, double sb) {
    double clear =
        std::max({pos_.x, to.x, detail::maxU(path_, std::min(sa, sb), std::max(sa, sb)) + e_});
    go(SegKind::Rapid, {clear, pos_.z});
    go(SegKind::Rapid, {clear, to.z});
    go(SegKind::Rapid, to);
  }

  void cutLevel(double level, double prev) {
    std::vector<Interval> regions = detail::belowLevel(path_, level);
    prevRegions_ = detail::belowLevel(path_, prev);
    last_ = 0;
    bool joined = false;
    for (size_t j = 0; j < regions.size(); ++j) {
      if (!joined) enter(regions[j], level);
      go(SegKind::Line, {level, detail::pointAt(path_, regions[j].s1).z});
      const Interval* next = j + 1 < regions.size() ? &regions[j + 1] : nullptr;
      joined = leave(regions[j], next);
    }
    // Back to the start column above everything passed on the way out (type I: the
    // retract already clears the level just cut, so this is one rapid along the pass).
    double clear = std::max(pos_.x, detail::maxU(path_, 0, last_) + e_);
    go(SegKind::Rapid, {clear, pos_.z});
    go(SegKind::Rapid, {clear, home_.z});
  }

  // Reaching the start of a region: from the start column when the shape is below the
  // level there, otherwise (type II pocket) down its entry wall from the previous level.
  void enter(const Interval& r, double level) {
    if (r.s0 <= kEps) {
      go(infeed_, {level, detail::pointAt(path_, 0).z});
      return;
    }
    const Interval* wall = detail::containing(prevRegions_, r.s0);
    double top = wall ? wall->s0 : 0;
    Pt entry = detail::pointAt(path_, top);
    travel({entry.x + e_, entry.z}, last_, top);
    go(SegKind::Line, entry);
    follow(top, r.s0);
  }

  // After the level meets the shape. Type I retracts at once. Type II follows the shape up
  // to the previous level (cutting the wall between the two levels) and retracts there, or,
  // when the shape dips below the level again first, follows it into the next pocket.
  // Returns true when the tool is already at the start of `next`.
  bool leave(const Interval& r, const Interval* next) {
    double end = static_cast<double>(path_.size());
    if (!typeTwo_ || r.s1 >= end - kEps) {
      last_ = r.s1;
      retract(e_);
      return false;
    }
    const Interval* wall = detail::containing(prevRegions_, r.s1);
    double up = wall ? wall->s1 : r.s1;
    if (next && next->s0 <= up + kEps) {
      follow(r.s1, next->s0);
      last_ = next->s0;
      return true;
    }
    follow(r.s1, up);
    last_ = up;
    // In a groove narrower than e the 45 degree retract would hit the entry wall: back off
    // along the pass no further than that wall is at the previous level (steeper retract).
    double room = wall && wall->s0 > kEps ? pos_.z - detail::pointAt(path_, wall->s0).z : e_;
    retract(std::clamp(room, 0.0, e_));
    return false;
  }

  // To the shifted A' in the ns block's mode, along the whole shifted shape (its own
  // G00/G01/G02/G03), then rapid back to A.
  void finalPass() {
    go(infeed_, ns_);
    size_t from = out_.size();
    detail::appendPath(path_, static_cast<double>(first_), static_cast<double>(path_.size()), true,
                       out_);
    if (out_.size() > from) pos_ = out_.back().end;
    go(SegKind::Rapid, home_);
  }

  Path path_;
  size_t first_;
  Pt home_, ns_;
  double depth_, e_;
  bool typeTwo_;
  SegKind infeed_;
  Pt pos_;
  double last_ = 0;  // path position of the last contact on the current level
  std::vector<Interval> prevRegions_;
  std::vector<Move> out_;
};

void checkParams(const Contour& c, const RoughParams& p) {
  if (p.depth <= 0) throw CycleError(AlarmId::CycleIllegalCommand, "depth of cut must be > 0");
  if (p.retract < 0) throw CycleError(AlarmId::CycleIllegalCommand, "retract must be >= 0");
  if (c.segs.empty()) throw CycleError(AlarmId::CycleSequenceNotFound, "empty shape program");
  if (detail::isArc(c.segs.front().kind))
    throw CycleError(AlarmId::ShapeFirstBlockNotG00G01, "first shape block is an arc");
}

std::vector<Move> rough(const Contour& c, const RoughParams& p, bool facing) {
  checkParams(c, p);
  Frame f = chooseFrame(c, p, facing);
  Pt shift{p.allowX, p.allowZ};
  auto toFrame = [&](const Pt& q) { return f.to({q.x + shift.x, q.z + shift.z}); };
  Pt home = f.to(c.start);
  Pt ns = toFrame(c.segs.front().end);

  // The region test needs the shape from the start column on: when the shifted A' is off
  // that column (type II ns with Z, or a Z allowance), a lead-in at A's height joins them.
  Path path;
  if (std::abs(ns.z - home.z) > kEps) path.push_back({SegKind::Line, {ns.x, home.z}, ns, {}});
  size_t first = path.size();
  Pt at = ns;
  for (size_t i = 1; i < c.segs.size(); ++i) {
    const ContourSeg& s = c.segs[i];
    Piece piece{s.kind, at, toFrame(s.end), toFrame(s.center)};
    piece.kind = f.arcKind(s.kind);
    path.push_back(piece);
    at = piece.b;
  }
  checkMonotonic(path, first, c.nsNamesZ, p.increment);

  SegKind infeed = c.segs.front().kind == SegKind::Rapid ? SegKind::Rapid : SegKind::Line;
  Rougher r(std::move(path), first, home, ns, p, c.nsNamesZ, infeed);
  std::vector<Move> moves = r.run();
  for (auto& m : moves) {
    m.end = f.from(m.end);
    if (detail::isArc(m.kind)) m.center = f.from(m.center);
    m.kind = f.arcKind(m.kind);
  }
  return moves;
}

}  // namespace

std::vector<Move> roughTurning(const Contour& c, const RoughParams& p) {
  return rough(c, p, false);
}

std::vector<Move> roughFacing(const Contour& c, const RoughParams& p) {
  return rough(c, p, true);
}

}  // namespace ncvm::lathe
