// Chamfer ,C and corner rounding ,R (30i comma form; fanuc-reference C). The control must
// see the next block before it can cut a chamfered corner, so a block with ,C/,R is held
// until the next block has been read: the held block is shortened, the chamfer (a line) or
// the corner arc is inserted, and the next block starts after it. The corner belongs to
// the ,C/,R block (its line in the trace). The geometry is src/motion/corner_round; it is
// computed on the programmed path, before mirror, scaling and rotation.
//
// Lathe G70-G73 shapes get the same corners in applyContourCorners.
#include <fmt/format.h>

#include <cmath>

#include "exec/executor.hpp"
#include "exec/words.hpp"
#include "motion/corner_round.hpp"

namespace ncvm {

namespace {
cornerw::Kind kindOf(int mode) {
  return mode == 20 ? cornerw::Kind::Cw : mode == 30 ? cornerw::Kind::Ccw : cornerw::Kind::Line;
}
}  // namespace

// Blocks that cannot follow a held ,C/,R block, found before the block does anything.
void Executor::cornerCheckBlock(const Words& w, int oneShot, bool crcMode) const {
  if (crcMode && w.hasCorner()) {
    // The control refuses ,C/,R in the block that starts or cancels compensation (in offset
    // mode the chamfered path is compensated, see crcPush). With a zero radius (a D offset of
    // 0) the compensator never starts up: only the G41/G42 block itself is the start-up
    // block, not every block after it.
    bool commanded = false;
    for (int k = 0; k < w.ng; ++k)
      commanded |= w.g[static_cast<size_t>(k)] == 410 || w.g[static_cast<size_t>(k)] == 420;
    bool startup =
        modal_.g[7] != 400 && !(crc_ && crc_->active()) && (commanded || crcRadius() != 0);
    bool cancel = modal_.g[7] == 400;
    if (startup || cancel) {
      AlarmError e(AlarmId::ChamferInStartupCancel,
                   startup ? "in the start-up block" : "in the cancel block");
      e.col = w.commaCol;
      throw e;
    }
  }
  if (crcCorner_) {
    bool stop = oneShot >= 0 || modal_.g[7] == 400 || modal_.plane != crcCorner_->plane;
    for (int k = 0; k < w.nm; ++k) {
      int m = w.m[static_cast<size_t>(k)];
      stop |= m == 0 || m == 1 || m == 2 || m == 30 || m == 98 || m == 99;
    }
    if (stop)
      throw AlarmError(AlarmId::MissingMoveAfterChamfer,
                       "the block after ,C/,R must be a move in offset mode");
    if (modal_.motion != 10 && modal_.motion != 20 && modal_.motion != 30)
      throw AlarmError(AlarmId::NotG01AfterChamfer, "the block after ,C/,R is not G01, G02 or G03");
  }
  if (w.hasCorner() && modal_.motion != 10 && modal_.motion != 20 && modal_.motion != 30 &&
      !crcMode) {
    AlarmError e(AlarmId::NotG01AfterChamfer, ",C/,R needs G01, G02 or G03");
    e.col = w.commaCol;
    throw e;
  }
  if (!cornerHold_) return;
  if (modal_.motion != 10 && modal_.motion != 20 && modal_.motion != 30)
    throw AlarmError(AlarmId::NotG01AfterChamfer, "the block after ,C/,R is not G01, G02 or G03");
  if (oneShot >= 0 || crcMode || (!lathe_ && modal_.g[9] != 800))
    throw AlarmError(AlarmId::MissingMoveAfterChamfer,
                     "the block after ,C/,R must be a move in the same plane");
  if (modal_.plane != cornerHold_->plane)
    throw AlarmError(AlarmId::MissingMoveAfterChamfer, "plane changed after ,C/,R");
}

// A G00-G03 block outside compensation: planned, then held (,C/,R), joined to the held
// block, or run.
bool Executor::plannedBlock(const Words& w, const std::array<int64_t, kMaxAxes>& target,
                            uint32_t mask, bool arc, bool cw) {
  const std::array<int64_t, kMaxAxes> start = programmedHere();
  PlannedMove m;
  m.mode = arc ? (cw ? 20 : 30) : modal_.motion == 0 ? 0 : 10;
  m.end = target;
  m.mask = mask;
  const xform::PlaneAxes pa = xform::planeAxes(modal_.plane);
  bool planeMove = target[pa.u] != start[pa.u] || target[pa.v] != start[pa.v];
  if (arc) {
    if (w.has('R') && !planeMove) {
      // An R arc that ends where it starts is a zero-length arc (no movement in the plane).
      m.mode = 10;
      if (cornerHold_)
        throw AlarmError(AlarmId::MissingMoveAfterChamfer, "zero-length arc after ,C/,R");
      if (w.hasCorner())
        throw AlarmError(AlarmId::ChamferMoveTooShort, "zero-length arc with ,C/,R");
      if (target != start) runPlanned(m);
      return true;
    }
    arcCenter(start, target, w, cw, m.cu, m.cv);
    planeMove = true;
  }
  if (cornerHold_) {
    if (m.mode == 0) throw AlarmError(AlarmId::NotG01AfterChamfer, "G00 after ,C/,R");
    if (!planeMove)
      throw AlarmError(AlarmId::MissingMoveAfterChamfer, "no move in the plane after ,C/,R");
    CornerHold h = *cornerHold_;
    cornerHold_.reset();
    const double unit = modal_.unit == InputUnit::Inch ? 25.4e6 : 1e6;
    auto p2 = [&](int64_t u, int64_t v) {
      return cornerw::P2{static_cast<double>(u) / unit, static_cast<double>(v) / unit};
    };
    cornerw::Seg a{kindOf(h.move.mode),
                   p2(h.start[pa.u], h.start[pa.v]),
                   p2(h.move.end[pa.u], h.move.end[pa.v]),
                   {h.move.cu / unit, h.move.cv / unit}};
    cornerw::Seg b{kindOf(m.mode),
                   p2(start[pa.u], start[pa.v]),
                   p2(target[pa.u], target[pa.v]),
                   {m.cu / unit, m.cv / unit}};
    cornerw::Corner c;
    EventOrigin here = origin_;
    try {
      c = cornerw::place(a, b, h.chamfer, static_cast<double>(h.amount) / unit);
    } catch (const cornerw::CornerError& e) {
      AlarmError ae(e.id, e.what());
      if (h.block) {
        ae.hasLoc = true;
        ae.loc = h.block->loc;
        ae.n = h.block->n;
      }
      throw ae;
    }
    // The held block up to the corner, then the corner, with the held block's line and feed.
    origin_ = h.origin;
    double feed = modal_.feed;
    modal_.feed = h.feed;
    PlannedMove a2 = h.move;
    auto nm = [&](double x) { return static_cast<int64_t>(std::llround(x * unit)); };
    a2.end[pa.u] = nm(c.endA.u);
    a2.end[pa.v] = nm(c.endA.v);
    runPlanned(a2);
    if (!c.none) {
      PlannedMove k = a2;
      k.end = h.move.end;  // the held block's other axes are there by now
      k.end[pa.u] = nm(c.startB.u);
      k.end[pa.v] = nm(c.startB.v);
      k.mode = c.arc ? (c.kind == cornerw::Kind::Cw ? 20 : 30) : 10;
      k.cu = c.center.u * unit;
      k.cv = c.center.v * unit;
      runPlanned(k);
    }
    origin_ = here;
    modal_.feed = feed;
  }
  if (w.hasCorner()) {
    if (m.mode == 0) {
      AlarmError e(AlarmId::NotG01AfterChamfer, ",C/,R in a G00 block");
      e.col = w.commaCol;
      throw e;
    }
    if (!planeMove)
      throw AlarmError(AlarmId::ChamferMoveTooShort, ",C/,R block does not move in the plane");
    CornerHold h;
    h.move = m;
    h.start = programmedHere();
    h.chamfer = w.hasCommaC;
    h.amount = lengthNm(w.commaValue, w.commaPoint, static_cast<int>(pa.u));
    h.origin = origin_;
    h.feed = modal_.feed;
    h.plane = modal_.plane;
    h.block = block_;
    if (h.amount <= 0)
      throw AlarmError(AlarmId::ChamferMoveTooShort, "chamfer/corner R amount must be > 0");
    effectiveFeed();  // F0 alarms now, in its own block
    cornerHold_ = h;
    programmed_ = target;  // the next block counts from the programmed corner
    return true;
  }
  runPlanned(m);
  return true;
}

// A programmed block in offset mode goes to the compensator, unless it carries ,C/,R: then
// it waits for the next block, and both are pushed cut short with the corner between them
// (a block of its own for the compensator, with an odd tag, and the line of the ,C/,R block).
bool Executor::crcPush(crc::InSeg s, const Words& w) {
  if (crcCorner_) {
    CrcCorner h = *crcCorner_;
    crcCorner_.reset();
    // A side or D change in the next block takes effect after the corner, which is a block
    // of its own with the ,C/,R block's side and D (the change happens over the next block).
    cornerw::Corner c;
    try {
      c = cornerw::place({h.seg.kind, h.seg.start, h.seg.end, h.seg.center},
                         {s.kind, s.start, s.end, s.center}, h.chamfer, h.amount);
    } catch (const cornerw::CornerError& e) {
      AlarmError ae(e.id, e.what());
      ae.hasLoc = true;
      ae.loc = h.block->loc;
      ae.n = h.block->n;
      throw ae;
    }
    crc::InSeg a = h.seg;
    a.end = c.endA;
    crc_->push(a);
    if (!c.none) {
      crc::InSeg k = h.seg;
      k.kind = c.arc ? c.kind : crc::Kind::Line;
      k.start = c.endA;
      k.end = c.startB;
      k.center = c.center;
      k.cornerArc = false;
      k.tag = h.seg.tag + 1;
      crcBlocks_[k.tag] = crcBlocks_.at(h.seg.tag);
      Pending p;
      p.tag = k.tag;
      // Before the current block's entry, which is the last one with its tag.
      auto at = pending_.end();
      for (auto it = pending_.begin(); it != pending_.end(); ++it)
        if (it->tag == s.tag) at = it;
      pending_.insert(at, std::move(p));
      crc_->push(k);
    }
    s.start = c.startB;
  }
  if (w.hasCorner()) {
    const double unit = modal_.unit == InputUnit::Inch ? 25.4e6 : 1e6;
    const xform::PlaneAxes pa = xform::planeAxes(modal_.plane);
    CrcCorner h;
    h.seg = s;
    h.chamfer = w.hasCommaC;
    h.amount =
        static_cast<double>(lengthNm(w.commaValue, w.commaPoint, static_cast<int>(pa.u))) / unit;
    h.block = block_;
    h.plane = modal_.plane;
    if (h.amount <= 0)
      throw AlarmError(AlarmId::ChamferMoveTooShort, "chamfer/corner R amount must be > 0");
    if (s.rapid) throw AlarmError(AlarmId::NotG01AfterChamfer, ",C/,R in a G00 block");
    crcCorner_ = h;
    return false;
  }
  crc_->push(s);
  return true;
}

// G70-G73 shapes: every ,C/,R shape block is cut short, the corner is inserted after it,
// and the next shape block starts after the corner. A corner on the last shape block has
// no second block: PS0069.
void Executor::applyContourCorners(lathe::Contour& c, std::vector<double>& feeds,
                                   const std::vector<ContourCorner>& corners) {
  // Work from the end so that the segment indices of earlier corners stay valid.
  for (auto it = corners.rbegin(); it != corners.rend(); ++it) {
    const ContourCorner& k = *it;
    auto fail = [&](AlarmId id, const std::string& why) {
      AlarmError e(id, why);
      e.hasLoc = true;
      e.loc = k.block->loc;
      e.n = k.block->n;
      throw e;
    };
    if (k.seg + 1 >= c.segs.size())
      fail(AlarmId::ShapeLastBlockIllegal, "chamfer/corner R in the last shape block");
    lathe::ContourSeg& sa = c.segs[k.seg];
    const lathe::ContourSeg& sb = c.segs[k.seg + 1];
    if (sa.kind == lathe::SegKind::Rapid || sb.kind == lathe::SegKind::Rapid)
      fail(AlarmId::NotG01AfterChamfer, "chamfer/corner R next to a G00 shape block");
    auto kind = [](lathe::SegKind s) {
      return s == lathe::SegKind::ArcCw    ? cornerw::Kind::Cw
             : s == lathe::SegKind::ArcCcw ? cornerw::Kind::Ccw
                                           : cornerw::Kind::Line;
    };
    // The lathe plane is G18: u = Z, v = X (radius).
    auto p2 = [](const lathe::Pt& p) { return cornerw::P2{p.z, p.x}; };
    const lathe::Pt from = k.seg == 0 ? c.start : c.segs[k.seg - 1].end;
    cornerw::Seg a{kind(sa.kind), p2(from), p2(sa.end), p2(sa.center)};
    cornerw::Seg b{kind(sb.kind), p2(sa.end), p2(sb.end), p2(sb.center)};
    cornerw::Corner r;
    try {
      r = cornerw::place(a, b, k.chamfer, k.amount);
    } catch (const cornerw::CornerError& e) {
      fail(e.id, e.what());
    }
    if (r.none) continue;
    lathe::ContourSeg ins;
    ins.blockIndex = sa.blockIndex;
    ins.kind = !r.arc                        ? lathe::SegKind::Line
               : r.kind == cornerw::Kind::Cw ? lathe::SegKind::ArcCw
                                             : lathe::SegKind::ArcCcw;
    ins.end = {r.startB.v, r.startB.u};
    ins.center = {r.center.v, r.center.u};
    sa.end = {r.endA.v, r.endA.u};
    c.segs.insert(c.segs.begin() + static_cast<std::ptrdiff_t>(k.seg + 1), ins);
    feeds.insert(feeds.begin() + static_cast<std::ptrdiff_t>(k.seg + 1), feeds[k.seg]);
  }
}

}  // namespace ncvm
