// Cutter compensation C in the control (fanuc-reference E.1). While G41/G42 is active the
// control reads ahead: a block's tool-centre path is known only when the next move in the
// plane has been read. So every block is deferred: its plane move goes to the compensator
// (src/motion/cutter_comp), everything else it does (other-axis moves, M codes, messages)
// becomes a pending action, and the pending list is released in program order as the
// compensator places each corner. Trace order and machine state stay those of execution.
#include <fmt/format.h>

#include <cmath>

#include "exec/executor.hpp"
#include "exec/words.hpp"

namespace ncvm {

namespace {
struct PlaneIdx {
  size_t u, v;
};
PlaneIdx planeIdx(int plane) {
  if (plane == 18) return {2, 0};
  if (plane == 19) return {1, 2};
  return {0, 1};
}
}  // namespace

// Events produced while blocks are deferred become actions that replay them later.
void Executor::DeferSink::onMove(const MoveEvent& e) {
  ex->deferEvent([e](EventSink& s) { s.onMove(e); });
}
void Executor::DeferSink::onDwell(const DwellEvent& e) {
  ex->deferEvent([e](EventSink& s) { s.onDwell(e); });
}
void Executor::DeferSink::onMessage(const MessageEvent& e) {
  std::string text(e.text), source(e.source);
  EventOrigin at = e.at;
  ex->deferEvent([at, text, source](EventSink& s) { s.onMessage(MessageEvent{at, text, source}); });
}
void Executor::DeferSink::onAlarm(const AlarmEvent& e) {
  std::string code(e.code), text(e.text);
  EventOrigin at = e.at;
  ex->deferEvent([at, code, text](EventSink& s) { s.onAlarm(AlarmEvent{at, code, text}); });
}
void Executor::DeferSink::onTool(const ToolEvent& e) {
  ex->deferEvent([e](EventSink& s) { s.onTool(e); });
}
void Executor::DeferSink::onSpindle(const SpindleEvent& e) {
  ex->deferEvent([e](EventSink& s) { s.onSpindle(e); });
}
void Executor::DeferSink::onCoolant(const CoolantEvent& e) {
  ex->deferEvent([e](EventSink& s) { s.onCoolant(e); });
}
void Executor::DeferSink::onAux(const AuxEvent& e) {
  ex->deferEvent([e](EventSink& s) { s.onAux(e); });
}
void Executor::DeferSink::onOffset(const OffsetEvent& e) {
  std::string kind(e.kind), name(e.name);
  OffsetEvent copy = e;
  ex->deferEvent([copy, kind, name](EventSink& s) {
    OffsetEvent o = copy;
    o.kind = kind;
    o.name = name;
    s.onOffset(o);
  });
}
void Executor::DeferSink::onSignal(const SignalEvent& e) {
  ex->deferEvent([e](EventSink& s) { s.onSignal(e); });
}
void Executor::DeferSink::onSkip(const SkipEvent& e) {
  ex->deferEvent([e](EventSink& s) { s.onSkip(e); });
}
void Executor::DeferSink::onWorkOrigin(const WorkOriginEvent& e) {
  ex->deferEvent([e](EventSink& s) { s.onWorkOrigin(e); });
}
void Executor::DeferSink::onComment(const CommentEvent& e) {
  std::string text(e.text);
  EventOrigin at = e.at;
  ex->deferEvent([at, text](EventSink& s) { s.onComment(CommentEvent{at, text}); });
}

void Executor::deferEvent(std::function<void(EventSink&)> replay) {
  Pending p;
  p.action = [this, replay] { replay(realSink_); };
  pending_.push_back(std::move(p));
}

bool Executor::crcBusy() const {
  return !pending_.empty() || (crc_ && crc_->active());
}

double Executor::crcRadius() const {
  if (lathe_) return tnrcRadius();
  int d = modal_.dOffset;
  if (d <= 0 || d >= kToolRows) return 0.0;
  const ToolOffsetRow& r = mem_.tools[static_cast<size_t>(d)];
  return toProgramUnits(r.geometry[kFieldRorD] + r.wear[kFieldRorD], 2, false);
}

void Executor::ensureCompensator() {
  if (crc_) return;
  crc::Options o;
  o.startupTypeB = setup_.bit("5003#0");
  crc_ = std::make_unique<crc::Compensator>(o, [this](const crc::OutSeg& s) { crcOutput(s); });
}

// The compensator placed (part of) the tool-centre path of block `s.tag`: every earlier
// block is complete.
void Executor::crcOutput(const crc::OutSeg& s) {
  for (Pending& p : pending_) {
    if (p.tag < 0) continue;
    if (p.tag < s.tag) p.closed = true;
    if (p.tag == s.tag) p.segs.push_back(s);
  }
}

void Executor::releasePending(bool all) {
  bool deferring = deferring_;
  deferring_ = false;
  auto saved = programmed_;
  while (!pending_.empty()) {
    Pending& p = pending_.front();
    if (p.tag >= 0 && !p.closed && !all) break;
    Pending cur = std::move(p);
    pending_.pop_front();
    if (cur.tag < 0) {
      cur.action();
      continue;
    }
    const CrcBlock& info = crcBlocks_.at(cur.tag);
    EventOrigin savedOrigin = origin_;
    double savedFeed = modal_.feed;
    int savedPlane = modal_.plane;
    origin_ = info.origin;
    modal_.feed = info.feed;
    modal_.plane = info.plane;
    const PlaneIdx pi = planeIdx(info.plane);
    double unit = modal_.unit == InputUnit::Inch ? 25.4e6 : 1e6;
    for (size_t k = 0; k < cur.segs.size(); ++k) {
      const crc::OutSeg& o = cur.segs[k];
      // A G39 corner arc is the G39 block's motion.
      origin_ = (k == 0 && o.inserted && o.kind != crc::Kind::Line && info.cornerArc)
                    ? info.cornerOrigin
                    : info.origin;
      std::array<int64_t, kMaxAxes> target{};
      for (size_t a = 0; a < kMaxAxes; ++a) target[a] = machine_[a] - offset_[a];
      // The block's other axes arrive with its last piece.
      if (!o.inserted && k + 1 == cur.segs.size()) target = info.target;
      // Lathe: the compensator places the nose centre; the tool moves its imaginary tip.
      const crc::P2 tip = o.vectorAtEnd ? info.tip : crc::P2{};
      target[pi.u] = static_cast<int64_t>(std::llround((o.end.u + tip.u) * unit));
      target[pi.v] = static_cast<int64_t>(std::llround((o.end.v + tip.v) * unit));
      programmedEnd_ = &info.programmedEnd;
      AxisArray nose{};
      if (lathe_) {
        nose = tnrcNoseEnd(target, info.tip);
        noseEnd_ = &nose;
      }
      if (o.kind == crc::Kind::Line) {
        bool same = true;
        for (size_t a = 0; a < kMaxAxes; ++a) same &= target[a] == machine_[a] - offset_[a];
        if (!same) moveTo(target, o.rapid ? MoveMode::Rapid : MoveMode::Linear, 0);
      } else {
        arcWithCenter(target, (o.center.u + tip.u) * unit, (o.center.v + tip.v) * unit,
                      o.kind == crc::Kind::Cw);
      }
      programmedEnd_ = nullptr;
      noseEnd_ = nullptr;
    }
    origin_ = savedOrigin;
    modal_.feed = savedFeed;
    modal_.plane = savedPlane;
    crcBlocks_.erase(cur.tag);
  }
  programmed_ = saved;
  deferring_ = deferring;
}

// Ends compensation lookahead: everything held is placed and executed (M00, M02, M30, G28,
// G53 and the end of the program stop buffering, as on the control).
void Executor::crcDrain() {
  if (!crcBusy()) return;
  try {
    if (crc_) crc_->flush();
  } catch (const crc::CrcError& e) {
    throw AlarmError(e.id, e.what());
  }
  releasePending(true);
}

// Mirror, scaling and rotation act before compensation: the compensator sees the
// transformed path (a reflection swaps G41/G42 and G02/G03) and D is never scaled.
// Returns the transformed end point.
std::array<int64_t, kMaxAxes> Executor::crcTransform(crc::InSeg& s,
                                                     const std::array<int64_t, kMaxAxes>& target) {
  if (!xf_.active()) return target;
  if (xf_.rotation && xf_.rotPlane != modal_.plane)
    throw AlarmError(
        AlarmId::IllegalPlaneForRotation,
        fmt::format("cutter compensation in G{} under G68 in G{}", modal_.plane, xf_.rotPlane));
  const PlaneIdx pi = planeIdx(modal_.plane);
  const double unit = modal_.unit == InputUnit::Inch ? 25.4e6 : 1e6;
  auto map = [&](const std::array<int64_t, kMaxAxes>& base, crc::P2& p) {
    xform::P3 q{static_cast<double>(base[0]), static_cast<double>(base[1]),
                static_cast<double>(base[2])};
    q[pi.u] = p.u * unit;
    q[pi.v] = p.v * unit;
    q = xf_.apply(q);
    p = {q[pi.u] / unit, q[pi.v] / unit};
  };
  map(programmed_, s.start);
  map(target, s.end);
  if (s.kind != crc::Kind::Line) map(programmed_, s.center);
  auto mapDir = [&](crc::P2& v) {
    xform::P3 d{};
    d[pi.u] = v.u;
    d[pi.v] = v.v;
    d = xf_.applyVector(d);
    v = {d[pi.u], d[pi.v]};
  };
  if (s.hasIJK) mapDir(s.ijk);
  if (s.cornerHasDir) mapDir(s.cornerDir);
  if (xf_.flips(modal_.plane)) {
    if (s.kind != crc::Kind::Line)
      s.kind = s.kind == crc::Kind::Cw ? crc::Kind::Ccw : crc::Kind::Cw;
    if (s.side != crc::Side::Off)
      s.side = s.side == crc::Side::Left ? crc::Side::Right : crc::Side::Left;
  }
  return transformed(target);
}

// A block in compensation mode. Returns true when it had motion.
bool Executor::crcBlock(const Words& w, const std::array<int64_t, kMaxAxes>& target, uint32_t mask,
                        bool arc, bool cw) {
  ensureCompensator();
  const PlaneIdx pi = planeIdx(modal_.plane);
  double unit = modal_.unit == InputUnit::Inch ? 25.4e6 : 1e6;
  int tag = (crcTag_ += 2);  // odd tags: the ,C/,R corner after a block (crcPush)
  bool planeMove = (mask & ((1u << pi.u) | (1u << pi.v))) || (arc && w.any("IJKR"));
  crc::Side side = modal_.g[7] == 410   ? crc::Side::Left
                   : modal_.g[7] == 420 ? crc::Side::Right
                                        : crc::Side::Off;
  try {
    if (planeMove) {
      crc::InSeg s;
      s.kind = arc ? (cw ? crc::Kind::Cw : crc::Kind::Ccw) : crc::Kind::Line;
      s.start = {static_cast<double>(programmed_[pi.u]) / unit,
                 static_cast<double>(programmed_[pi.v]) / unit};
      s.end = {static_cast<double>(target[pi.u]) / unit, static_cast<double>(target[pi.v]) / unit};
      if (arc) {
        double cu = 0, cv = 0;
        arcCenter(programmed_, target, w, cw, cu, cv);
        s.center = {cu / unit, cv / unit};
      }
      s.rapid = modal_.motion == 0;
      s.side = side;
      s.radius = crcRadius();
      if (side != crc::Side::Off && s.radius == 0 && !warnedNoRadius_) {
        // Old 0-M programs name the radius with H in the G41/G42 block; with D0 the path is
        // not compensated at all, which must not pass silently.
        warnedNoRadius_ = true;
        warn("W005", lathe_ ? "G41/G42 with a zero nose radius (R of the T offset): no compensation"
                     : w.has('H') ? "G41/G42 with D0 (H in the block is a length offset, not the "
                                    "radius): no compensation"
                                  : "G41/G42 with D0 or a zero D offset: no compensation");
      }
      s.tag = tag;
      s.cornerArc = g39Pending_;
      s.cornerHasDir = g39Pending_ && g39HasDir_;
      s.cornerDir = g39Dir_;
      if (!lathe_ && side != crc::Side::Off && !arc && (w.has("IJK"[pi.u]) || w.has("IJK"[pi.v]))) {
        // G41/G42 with I, J, K in a G00/G01 block (a start-up block, or G41/G42 again in
        // offset mode) sets the direction of the offset vector on the control; ncvm does not
        // model it, and must not move as if the words were not there.
        for (int k = 0; k < w.ng; ++k) {
          const int g = w.g[static_cast<size_t>(k)];
          if (g != 410 && g != 420) continue;
          AlarmError e(AlarmId::ImproperGCode,
                       fmt::format("G{} with I/J/K (the direction of the offset vector) is not "
                                   "supported by ncvm yet",
                                   g / 10));
          e.col = w.gcol[static_cast<size_t>(k)];
          throw e;
        }
      }
      if (side == crc::Side::Off && w.any("IJK") && !arc) {
        s.hasIJK = true;
        s.ijk = {w.has("IJK"[pi.u]) ? w.value("IJK"[pi.u]) : 0.0,
                 w.has("IJK"[pi.v]) ? w.value("IJK"[pi.v]) : 0.0};
      }
      const std::array<int64_t, kMaxAxes> actual = crcTransform(s, target);
      CrcBlock info;
      info.tip = lathe_ ? tnrcTipVector(s.radius) : crc::P2{};
      info.origin = origin_;
      info.cornerArc = g39Pending_;
      info.cornerOrigin = g39Origin_;
      g39Pending_ = false;
      info.target = actual;
      info.feed = modal_.feed;
      info.plane = modal_.plane;
      for (int k = 0; k < kMaxAxes; ++k)
        info.programmedEnd[static_cast<size_t>(k)] =
            toProgramUnits(actual[static_cast<size_t>(k)], k, true);
      crcBlocks_[tag] = info;
      Pending p;
      p.tag = tag;
      pending_.push_back(std::move(p));
      programmed_ = target;
      // The compensator places a block's whole path (with its extra corner moves) before it
      // returns from the next push: every earlier block is complete now, even when the next
      // block raises an alarm before any of its own path is out.
      if (crcPush(s, w))
        for (Pending& held : pending_)
          if (held.tag >= 0 && held.tag < tag) held.closed = true;
    } else {
      if (mask) {
        // A move of the other axes only: it happens in its turn, from wherever the
        // compensated path has brought the tool.
        std::array<int64_t, kMaxAxes> t = transformed(target);
        uint32_t m = mask;
        EventOrigin at = origin_;
        Pending p;
        p.action = [this, t, m, at] {
          std::array<int64_t, kMaxAxes> to{};
          for (size_t a = 0; a < kMaxAxes; ++a)
            to[a] = (m & (1u << a)) ? t[a] : machine_[a] - offset_[a];
          EventOrigin saved = origin_;
          origin_ = at;
          moveTo(to, modal_.motion == 0 ? MoveMode::Rapid : MoveMode::Linear, m);
          origin_ = saved;
        };
        pending_.push_back(std::move(p));
        for (size_t a = 0; a < kMaxAxes; ++a)
          if (mask & (1u << a)) programmed_[a] = target[a];
      }
      if (crcCorner_)
        throw AlarmError(AlarmId::MissingMoveAfterChamfer,
                         "the block after ,C/,R does not move in the plane");
      crc_->pushNonMoving(tag);
    }
  } catch (const crc::CrcError& e) {
    throw AlarmError(e.id, e.what());
  }
  if (side == crc::Side::Off && !crc_->active()) {
    crcDrain();
  } else {
    releasePending(false);
  }
  return planeMove || mask;
}

}  // namespace ncvm
