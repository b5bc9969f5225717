// Cutter compensation C as a stream: the control holds each compensated block until it has
// read the next block that moves in the plane, because the end of a block is a corner that
// depends on both. Corner geometry lives in crc_corner.cpp, vector maths in crc_geom.cpp.
#include "motion/cutter_comp.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "motion/crc_corner.hpp"
#include "motion/crc_geom.hpp"

namespace ncvm::crc {

using namespace geom;

namespace {

double sideSign(Side s) {
  switch (s) {
    case Side::Left:
      return 1;
    case Side::Right:
      return -1;
    case Side::Off:
      break;
  }
  return 0;
}

// D0 cancels like G40 (fanuc-reference E.1, [S9]).
bool compensated(const InSeg& s) {
  return s.side != Side::Off && s.radius != 0;
}

bool zeroLine(const InSeg& s, double eps) {
  return s.kind == Kind::Line && near(s.start, s.end, eps);
}

OutSeg copyOf(const InSeg& s) {
  return {s.kind, s.start, s.end, s.center, s.rapid, s.tag, false, false};
}

}  // namespace

struct Compensator::Impl {
  // A block read but not yet executed: its end waits for the next move.
  struct Held {
    InSeg seg;
    P2 from;  // tool centre where it starts
    bool startup = false;
  };

  Options opt;
  std::function<void(const OutSeg&)> out;
  bool offset = false;  // between start-up and cancel
  std::optional<Held> held;
  P2 tool;               // tool centre after the last emitted piece
  double vecRadius = 0;  // D of the vector currently applied (for G39 after a break)
  int idle = 0;          // non-moving blocks read since the held block

  Impl(Options o, std::function<void(const OutSeg&)> f) : opt(o), out(std::move(f)) {}

  double eps() const { return opt.epsilon; }
  // Signed offset of a block at its end: its own side and its own D.
  static double endOffset(const InSeg& s) { return sideSign(s.side) * s.radius; }

  void push(const InSeg& s) {
    if (!offset) return compensated(s) && !zeroLine(s, eps()) ? startUp(s) : passThrough(s);
    if (!compensated(s)) return cancel(s);
    // A move of length zero in the plane limits the lookahead like a block without motion.
    if (zeroLine(s, eps())) return pushNonMoving(s.tag);
    follow(s);
  }

  void pushNonMoving(int) {
    if (!offset || !held) return;
    // 15i/30i rule: with N blocks read, M of them non-moving, intersections need N-2 >= M.
    if (++idle > std::max(0, opt.lookahead - 2)) finishPerpendicular();
  }

  void flush() {
    if (held) finishPerpendicular();
  }

  void passThrough(const InSeg& s) {
    out(copyOf(s));
    tool = s.end;
  }

  void startUp(const InSeg& s) {
    if (s.kind != Kind::Line)
      throw CrcError(AlarmId::NoCircInStartupCancel, "start-up block must be G00 or G01", s.tag);
    offset = true;
    idle = 0;
    held = Held{s, s.start, true};
  }

  // A block in offset mode: it places the corner at the end of the held block.
  void follow(const InSeg& b) {
    idle = 0;
    if (!held) return startAfterBreak(b);
    const Held a = *held;
    double dA = endOffset(a.seg);
    double dB = sideSign(b.side) * a.seg.radius;  // b's start still uses a's D
    if (b.cornerArc) return cornerArc(a, dA, b, dB);
    corner::Rule rule = corner::Rule::Offset;
    if (a.startup) rule = opt.startupTypeB ? corner::Rule::StartupB : corner::Rule::StartupA;
    auto pts = corner::place(a.seg, dA, b, dB, rule, eps());
    emitCorner(a, pts);
    held = Held{b, pts.back(), false};
  }

  // The held block was executed without a corner (lookahead broken or buffering stopped):
  // its vector stays, so the next block starts from where the tool is.
  void startAfterBreak(const InSeg& b) {
    if (b.cornerArc) {
      P2 to = cornerArcEnd(b, sideSign(b.side) * vecRadius);
      emitArc(tool, to, b, sideSign(b.side) * vecRadius);
      tool = to;
    }
    held = Held{b, tool, false};
  }

  // G39: the previous block ends perpendicular to itself, then an arc of radius r around the
  // programmed corner turns the vector until it is perpendicular to the next block (with
  // I/J: to the left (G41) or right (G42) of that direction). The next block starts there.
  void cornerArc(const Held& a, double dA, const InSeg& b, double dB) {
    P2 from = offsetPoint(a.seg, a.seg.end, dA, eps());
    P2 to = cornerArcEnd(b, dB);
    emitBlock(a, from);
    emitArc(from, to, b, dB);
    held = Held{b, to, false};
  }

  P2 cornerArcEnd(const InSeg& b, double d) const {
    if (b.cornerHasDir && len(b.cornerDir) > eps())
      return b.start + d * leftNormal(unit(b.cornerDir));
    return offsetPoint(b, b.start, d, eps());
  }

  void emitArc(P2 from, P2 to, const InSeg& b, double d) {
    if (near(from, to, eps())) return;
    // G41 goes round the corner clockwise, G42 counter-clockwise (16/18-C manual, G39).
    Kind k = d > 0 ? Kind::Cw : Kind::Ccw;
    out({k, from, to, b.start, false, b.tag, true});
  }

  void cancel(const InSeg& c) {
    if (c.kind != Kind::Line)
      throw CrcError(AlarmId::NoCircInStartupCancel, "cancel block must be G00 or G01", c.tag);
    if (held) emitCorner(*held, cancelCorner(*held, c));
    out({Kind::Line, tool, c.end, {}, c.rapid, c.tag, false, false});
    tool = c.end;
    offset = false;
    held.reset();
    idle = 0;
  }

  std::vector<P2> cancelCorner(const Held& a, const InSeg& c) const {
    double dA = endOffset(a.seg);
    if (c.hasIJK && len(c.ijk) > eps()) return corner::placeToward(a.seg, dA, c.ijk, eps());
    if (zeroLine(c, eps())) return {offsetPoint(a.seg, a.seg.end, dA, eps())};
    auto rule = opt.startupTypeB ? corner::Rule::CancelB : corner::Rule::CancelA;
    return corner::place(a.seg, dA, c, dA, rule, eps());
  }

  void suspend() {
    if (held) {
      const Held a = *held;
      if (a.seg.kind == Kind::Line) {
        // A straight block simply ends on its programmed point.
        if (!a.startup) checkInterference(a.seg, a.from, a.seg.end);
        out({Kind::Line, a.from, a.seg.end, {}, a.seg.rapid, a.seg.tag, false, false});
      } else {
        // An arc keeps its radius: it ends perpendicular, then the vector is removed.
        emitCorner(a, {offsetPoint(a.seg, a.seg.end, endOffset(a.seg), eps())});
        out({Kind::Line, tool, a.seg.end, {}, a.seg.rapid, a.seg.tag, false, false});
      }
      tool = a.seg.end;
    }
    offset = false;
    held.reset();
    idle = 0;
  }

  void finishPerpendicular() {
    const Held a = *held;
    emitCorner(a, {offsetPoint(a.seg, a.seg.end, endOffset(a.seg), eps())});
    held.reset();
  }

  // Block a up to pts[0], then the control's extra moves, which belong to a.
  void emitCorner(const Held& a, const std::vector<P2>& pts) {
    emitBlock(a, pts.front());
    for (size_t i = 1; i < pts.size(); ++i)
      out({Kind::Line, pts[i - 1], pts[i], {}, a.seg.rapid, a.seg.tag, true});
    tool = pts.back();
  }

  void emitBlock(const Held& a, P2 end) {
    if (!a.startup) checkInterference(a.seg, a.from, end);
    out({a.seg.kind, a.from, end, a.seg.center, a.seg.rapid, a.seg.tag, false});
    tool = end;
    vecRadius = a.seg.radius;
  }

  // PS0041: the compensated block runs against its programmed direction (for an arc, its
  // sweep differs from the programmed one by more than 180 degrees): the cutter would cut
  // into a step or groove narrower than itself.
  void checkInterference(const InSeg& s, P2 from, P2 to) const {
    bool reversed = false;
    if (s.kind == Kind::Line) {
      P2 d = to - from;
      reversed = len(d) > eps() && dot(d, s.end - s.start) < 0;
    } else {
      bool full = near(s.start, s.end, eps());
      double want = sweep(s.center, s.start, s.end, s.kind, full, eps());
      double got = sweep(s.center, from, to, s.kind, full && near(from, to, eps()), eps());
      reversed = std::abs(got - want) > std::numbers::pi;
    }
    if (reversed)
      throw CrcError(AlarmId::InterferenceInCrc, "compensated path runs against the programmed one",
                     s.tag);
  }
};

Compensator::Compensator(Options o, std::function<void(const OutSeg&)> out)
    : impl_(std::make_shared<Impl>(o, std::move(out))) {}

void Compensator::push(const InSeg& s) {
  impl_->push(s);
}
void Compensator::pushNonMoving(int tag) {
  impl_->pushNonMoving(tag);
}
void Compensator::flush() {
  impl_->flush();
}
void Compensator::suspend() {
  impl_->suspend();
}
bool Compensator::active() const {
  return impl_->offset;
}

}  // namespace ncvm::crc
