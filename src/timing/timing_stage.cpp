#include "timing/timing_stage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace ncvm {

using timing::blockTime;
using timing::Ramp;
using timing::rampDistance;
using timing::reachable;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = 1e-12;
// Plane axes (p, q) and the helix axis of G17/G18/G19.
struct PlaneAxes {
  int p, q, h;
};
PlaneAxes planeAxes(int plane) {
  if (plane == 18) return {2, 0, 1};
  if (plane == 19) return {1, 2, 0};
  return {0, 1, 2};
}
}  // namespace

TimingStage::TimingStage(const Setup& setup, EventSink* next)
    : setup_(setup), t_(setup.timing), next_(next) {
  for (size_t k = 0; k < kMaxAxes; ++k) {
    const AxisConfig& a = setup.axes[k];
    double half = a.diameter ? 0.5 : 1.0;  // lathe X: positions are diameters, motion radius
    scaleMm_[k] = half;
    scaleInch_[k] = a.rotary ? half : 25.4 * half;
    accel_[k] = t_.accel[k];
    jerk_[k] = t_.accelChangeMs > 0 ? t_.accel[k] / (t_.accelChangeMs / 1000.0) : 0.0;
    cornerDiff_[k] = t_.cornerSpeedDiff[k] / 60.0;
  }
  tMin_ = t_.minBlockTimeMs / 1000.0;
  if (t_.dynamic) {
    size_t cap = 4 * static_cast<size_t>(std::max(1, t_.lookaheadBlocks)) + 256;
    held_.reserve(cap);
    if (next_) events_.reserve(cap);
  }
}

// ---- spindle ---------------------------------------------------------------------------

double TimingStage::cssTarget(double x, const MoveEvent& e) const {
  // The rpm G96 asks for at diameter x (work coordinates, as the control computes it).
  double perMin = e.inch ? 12.0 : 1000.0;
  double dia = std::fabs(x);
  double limit = e.rpmLimit > 0 ? e.rpmLimit : kInf;
  if (dia <= 0) return std::isinf(limit) ? rpm_ : limit;
  return std::min(e.surfaceSpeed * perMin / (std::numbers::pi * dia), limit);
}

void TimingStage::followSpindle(double target, double seconds) {
  double step = t_.spindleAccel * seconds;
  rpm_ = rpm_ < target ? std::min(target, rpm_ + step) : std::max(target, rpm_ - step);
}

// Feed per revolution at the spindle's actual speed: mm/s averaged over the move. Under G96
// the rpm follows X (clamped by G50/G92 S) as fast as the spindle acceleration allows.
double TimingStage::spindleFeed(const MoveEvent& e, double lengthMm) {
  bool running = dir_ == SpindleDir::Cw || dir_ == SpindleDir::Ccw;
  double unit = e.inch ? 25.4 : 1.0;
  if (!running || rpm_ <= 0) {
    if (e.surfaceSpeed <= 0 || !running) return 0;
  }
  if (e.surfaceSpeed <= 0) return e.perRev * unit * rpm_ / 60.0;
  // Midpoint steps along the move: exact for a spindle that keeps up (time ~ integral of x).
  int steps = static_cast<int>(std::clamp(std::ceil(lengthMm / 0.25), 16.0, 400.0));
  double seconds = 0, ds = lengthMm / steps;
  for (int k = 0; k < steps; ++k) {
    double f = (k + 0.5) / steps;
    double x = e.start[0] + (e.end[0] - e.start[0]) * f;
    double target = cssTarget(x, e);
    // The step's time at the current speed bounds how far the spindle can follow.
    double v = e.perRev * unit * std::max(rpm_, 1e-9) / 60.0;
    followSpindle(target, ds / v);
    if (rpm_ <= 0) return 0;
    seconds += ds / (e.perRev * unit * rpm_ / 60.0);
  }
  return seconds > 0 ? lengthMm / seconds : 0;
}

// ---- planning ----------------------------------------------------------------------------

TimingStage::Segment TimingStage::segmentFor(const MoveEvent& e, AxisArray& dirIn,
                                             AxisArray& dirOut) {
  Segment s;
  const AxisArray& scale = e.inch ? scaleInch_ : scaleMm_;
  AxisArray d{};
  double sq = 0;
  for (size_t k = 0; k < kMaxAxes; ++k) {
    d[k] = (e.mend[k] - e.mstart[k]) * scale[k];
    sq += d[k] * d[k];
  }
  double unit = e.inch ? 25.4 : 1.0;
  s.length = e.length * unit;
  if (s.length <= kEps) {
    s.length = 0;
    s.vmax = kInf;
    s.vJunction = kInf;
    return s;
  }
  double feed = e.perRev > 0 ? spindleFeed(e, s.length) : e.feed * unit / 60.0;
  feed *= t_.feedOverride / 100.0;
  double a = kInf, j = kInf;
  if (!e.arc) {
    double chord = std::sqrt(sq);
    for (size_t k = 0; k < kMaxAxes; ++k) {
      double u = chord > 0 ? d[k] / chord : 0;
      dirIn[k] = dirOut[k] = u;
      if (std::fabs(u) > 1e-9) {
        a = std::min(a, accel_[k] / std::fabs(u));
        if (jerk_[k] > 0) j = std::min(j, jerk_[k] / std::fabs(u));
      }
    }
  } else {
    PlaneAxes pl = planeAxes(e.plane);
    auto P = static_cast<size_t>(pl.p), Q = static_cast<size_t>(pl.q),
         H = static_cast<size_t>(pl.h);
    auto radial = [&](const AxisArray& pt, double& rp, double& rq) {
      rp = (pt[P] - e.center[P]) * scale[P];
      rq = (pt[Q] - e.center[Q]) * scale[Q];
    };
    double rp0, rq0, rp1, rq1;
    radial(e.start, rp0, rq0);
    radial(e.end, rp1, rq1);
    double r = std::hypot(rp0, rq0);
    double dh = d[H];
    double planar = std::sqrt(std::max(0.0, s.length * s.length - dh * dh));
    double sign = e.mode == MoveMode::Ccw ? 1.0 : -1.0;
    auto tangent = [&](double rp, double rq, AxisArray& u) {
      double rr = std::hypot(rp, rq);
      u.fill(0);
      if (rr <= 0) return;
      u[P] = -sign * rq / rr * planar / s.length;
      u[Q] = sign * rp / rr * planar / s.length;
      u[H] = dh / s.length;
    };
    tangent(rp0, rq0, dirIn);
    tangent(rp1, rq1, dirOut);
    // The tangent turns through the plane: the slower plane axis limits the path.
    for (size_t k : {P, Q}) {
      a = std::min(a, accel_[k]);
      if (jerk_[k] > 0) j = std::min(j, jerk_[k]);
    }
    // Feed clamp by the arc radius (1730/1731 give the acceleration V^2/R, 1732 the floor).
    if (t_.arcClampFeed > 0 && r > 0) {
      double v = t_.arcClampFeed / 60.0;
      double aArc = v * v / t_.arcClampRadius;
      double clamp = std::max(std::sqrt(aArc * r), t_.arcClampMinFeed / 60.0);
      feed = std::min(feed, clamp);
    }
  }
  s.vmax = feed;
  // The control cannot finish a block faster than it prepares one.
  if (tMin_ > 0) s.vmax = std::min(s.vmax, s.length / tMin_);
  s.ramp = Ramp{a, std::isinf(j) ? 0.0 : j};
  return s;
}

double TimingStage::rapidTime(const MoveEvent& e) const {
  const AxisArray& scale = e.inch ? scaleInch_ : scaleMm_;
  double over = t_.rapidOverride / 100.0;
  AxisArray d{};
  double sq = 0;
  for (size_t k = 0; k < kMaxAxes; ++k) {
    d[k] = std::fabs(e.mend[k] - e.mstart[k]) * scale[k];
    sq += d[k] * d[k];
  }
  auto axisRamp = [&](size_t k, double& rate) {
    rate = setup_.axes[k].rapidRate / 60.0 * over;
    double t1 = t_.rapidT1Ms[k] / 1000.0, t2 = t_.rapidT2Ms[k] / 1000.0;
    Ramp r;
    r.a = t1 > 0 ? rate / t1 : kInf;
    r.j = t2 > 0 && t1 > 0 ? r.a / t2 : 0.0;
    return r;
  };
  double time = 0;
  if (setup_.lrp()) {
    // Linear interpolation type positioning: one path speed that no axis exceeds.
    double len = std::sqrt(sq);
    if (len <= kEps) return 0;
    double v = kInf, a = kInf, j = kInf;
    for (size_t k = 0; k < kMaxAxes; ++k) {
      if (d[k] <= kEps) continue;
      double rate;
      Ramp r = axisRamp(k, rate);
      double f = len / d[k];
      v = std::min(v, rate * f);
      a = std::min(a, r.a * f);
      if (r.j > 0) j = std::min(j, r.j * f);
    }
    time = blockTime(0, 0, v, len, Ramp{a, std::isinf(j) ? 0.0 : j});
  } else {
    // Non-linear (dog-leg) positioning: every axis at its own rate and time constants.
    for (size_t k = 0; k < kMaxAxes; ++k) {
      if (d[k] <= kEps) continue;
      double rate;
      Ramp r = axisRamp(k, rate);
      time = std::max(time, blockTime(0, 0, rate, d[k], r));
    }
  }
  return time;
}

// Groups the held blocks into runs. A run ends at an exact stop, at a joint whose corner
// speed is below the feed, where the feed changes by more than 20 %, and after 128 blocks
// (so memory stays bounded; a cut inside a cruise costs nothing).
void TimingStage::buildRuns(size_t look) {
  size_t n = held_.size();
  runs_.clear();
  lengths_.assign(n + 1, 0.0);
  for (size_t i = 0; i < n; ++i) lengths_[i + 1] = lengths_[i] + held_[i].s.length;
  bool open = false;
  size_t realBlocks = 0;
  for (size_t i = 0; i < n; ++i) {
    const Segment& s = held_[i].s;
    bool join = open && !runs_.back().stopAfter && std::isinf(runs_.back().exitCap);
    if (join && s.length > 0 && realBlocks > 0) {
      const Run& r = runs_.back();
      double lo = std::min(r.vmax, s.vmax), hi = std::max(r.vmax, s.vmax);
      join = s.vJunction >= lo * (1 - 1e-9) && lo >= 0.8 * hi && i - r.first < 128;
    }
    if (!join) {
      runs_.push_back(Run{i, i, 0, kInf, s.vJunction, Ramp{kInf, 0}, false, kInf, 0, 0});
      open = true;
      realBlocks = 0;
    }
    Run& r = runs_.back();
    r.last = i;
    r.length += s.length;
    r.stopAfter = s.stopAfter;
    if (s.length > 0) {
      if (realBlocks == 0) r.vJunction = std::min(r.vJunction, s.vJunction);
      ++realBlocks;
      r.vmax = std::min(r.vmax, s.vmax);
      r.ramp.a = std::min(r.ramp.a, s.ramp.a);
      if (s.ramp.j > 0) r.ramp.j = r.ramp.j > 0 ? std::min(r.ramp.j, s.ramp.j) : s.ramp.j;
      // Look-ahead depth inside the run: at the end of block i the control must be able to
      // stop within the look-ahead - 1 blocks it has read after it.
      // That caps the run's speed; with nothing read ahead (look-ahead 1) it stops there.
      size_t lastSeen = std::min(n, i + look);
      if (lastSeen < n) {
        double window = lengths_[lastSeen] - lengths_[i + 1];
        if (window <= 0)
          r.exitCap = 0;
        else if (rampDistance(0, r.vmax, s.ramp) > window)  // else it stops in time at vmax
          r.vmax = std::min(r.vmax, reachable(0, window, s.ramp));
      }
    }
  }
}

void TimingStage::plan(bool toStop) {
  size_t n = held_.size();
  if (n == 0) return;
  size_t look = static_cast<size_t>(std::max(1, t_.lookaheadBlocks));
  buildRuns(look);
  size_t m = runs_.size();
  // Without a stop in sight, forward only the runs that end before the last look-ahead
  // window: their speeds no longer depend on blocks not read yet.
  size_t commitRuns = m;
  if (!toStop) {
    commitRuns = 0;
    while (commitRuns < m && runs_[commitRuns].last + look < n) ++commitRuns;
    if (commitRuns == 0) return;
  }
  vEntryMax_.assign(m, 0.0);
  vExitMax_.assign(m, 0.0);
  vExitMax_[m - 1] = 0;  // a stop (or, for a partial plan, the end of what is known)
  for (size_t i = m; i-- > 0;) {
    Run& r = runs_[i];
    vExitMax_[i] = std::min(vExitMax_[i], r.exitCap);
    if (r.stopAfter) vExitMax_[i] = 0;
    double vmax = std::isinf(r.vmax) ? vExitMax_[i] : r.vmax;
    double entry = std::min({vmax, r.vJunction, reachable(vExitMax_[i], r.length, r.ramp)});
    vEntryMax_[i] = entry;
    if (i > 0) vExitMax_[i - 1] = std::min(entry, runs_[i - 1].vmax);
  }
  double v = entry_;
  for (size_t i = 0; i < m; ++i) {
    Run& r = runs_[i];
    r.vEntry = i == 0 ? entry_ : std::min(v, vEntryMax_[i]);
    r.vExit = std::min(vExitMax_[i], reachable(r.vEntry, r.length, r.ramp));
    if (r.length <= 0) r.vExit = std::min(r.vEntry, vExitMax_[i]);
    v = r.vExit;
  }
  for (size_t i = 0; i < commitRuns; ++i) commit(runs_[i]);
  entry_ = toStop ? 0.0 : runs_[commitRuns - 1].vExit;
  size_t done = runs_[commitRuns - 1].last + 1;
  auto doneDiff = static_cast<std::ptrdiff_t>(done);
  held_.erase(held_.begin(), held_.begin() + doneDiff);
  if (next_) {
    events_.erase(events_.begin(), events_.begin() + doneDiff);
    size_t sent = 0;
    while (sent < after_.size() && after_[sent].seq < heldBase_ + done) ++sent;
    after_.erase(after_.begin(), after_.begin() + static_cast<std::ptrdiff_t>(sent));
  }
  heldBase_ += done;
  if (toStop) haveDir_ = false;
}

void TimingStage::commit(const Run& run) {
  timing::Profile prof = timing::makeProfile(
      run.vEntry, run.vExit, std::isinf(run.vmax) ? 0.0 : run.vmax, run.length, run.ramp);
  double s = 0, before = 0;
  // The G96 events to send after the moves of this run (sorted by their move).
  size_t sp = 0;
  while (next_ && sp < after_.size() && after_[sp].seq < heldBase_ + run.first) ++sp;
  for (size_t i = run.first; i <= run.last; ++i) {
    const Held& h = held_[i];
    s += h.s.length;
    double at = i == run.last ? prof.total() : prof.timeAt(s);
    double time = std::max(at - before, tMin_);
    before = at;
    if (i == run.last && run.stopAfter) time += t_.inPositionS;
    report_.addMoveTime(h.mode, h.at, h.length, time, h.timeSimple);
    if (!next_) continue;
    MoveEvent& e = events_[i];
    e.time = time;
    next_->onMove(e);
    for (; sp < after_.size() && after_[sp].seq == heldBase_ + i; ++sp)
      next_->onSpindle(after_[sp].e);
  }
}

// ---- events --------------------------------------------------------------------------------

void TimingStage::onMove(const MoveEvent& in) {
  if (!t_.dynamic) {
    // The simple model: time is length / feed already (timeSimple -1 means the same).
    report_.addMove(in, in.time, in.time);
    forwardMove(in);
    return;
  }
  if (in.mode == MoveMode::Rapid || in.thread) {
    stop();
    MoveEvent e = in;
    e.timeSimple = in.time;
    // Threads run at the spindle-synchronised feed; rapids end with the in-position check.
    e.time = in.thread ? std::max(in.time, tMin_) : rapidTime(in) + t_.inPositionS;
    e.time = std::max(e.time, tMin_);
    if (in.surfaceSpeed > 0 && (dir_ == SpindleDir::Cw || dir_ == SpindleDir::Ccw))
      followSpindle(cssTarget(in.end[0], in), e.time);
    report_.addMove(e, e.time, e.timeSimple);
    forwardMove(e);
    return;
  }
  report_.trackDrilling(in);
  if (next_) {
    events_.push_back(in);
    events_.back().timeSimple = in.time;
  }
  held_.push_back(Held{{}, in.at, in.length, in.time, in.mode});
  Held& h = held_.back();
  AxisArray dirIn{}, dirOut{};
  h.s = segmentFor(in, dirIn, dirOut);
  if (h.s.length > 0) {
    if (!haveDir_) {
      h.s.vJunction = held_.size() == 1 && entry_ == 0 ? 0.0 : kInf;
    } else {
      // Automatic corner deceleration: no axis may change its speed by more than 1783.
      double v = kInf;
      for (size_t k = 0; k < kMaxAxes; ++k) {
        double du = std::fabs(dirIn[k] - lastDir_[k]);
        if (du > 1e-9) v = std::min(v, cornerDiff_[k] / du);
      }
      h.s.vJunction = v;
    }
    lastDir_ = dirOut;
    haveDir_ = true;
  }
  if (in.surfaceSpeed > 0 && in.perRev <= 0 && (dir_ == SpindleDir::Cw || dir_ == SpindleDir::Ccw))
    followSpindle(cssTarget(in.end[0], in), in.time);
  h.s.stopAfter = in.exactStop;
  if (in.exactStop) {
    stop();
    return;
  }
  size_t look = static_cast<size_t>(std::max(1, t_.lookaheadBlocks));
  if (held_.size() >= 4 * look + 64) plan(false);
}

void TimingStage::finish() {
  stop();
}

void TimingStage::onDwell(const DwellEvent& e) {
  stop();
  double t = e.time;
  if (t_.dynamic && e.revolutions > 0 && rpm_ > 0) t = e.revolutions * 60.0 / rpm_;
  report_.add(TimeKind::Dwell, e.at, t, e.time);
  if (next_) next_->onDwell(e);
}

void TimingStage::onMessage(const MessageEvent& e) {
  stop();
  if (next_) next_->onMessage(e);
}

void TimingStage::onAlarm(const AlarmEvent& e) {
  stop();
  if (next_) next_->onAlarm(e);
}

void TimingStage::onTool(const ToolEvent& e) {
  stop();
  bool change = e.change || setup_.kind == MachineKind::Lathe;
  if (change) report_.toolSelected(e.tool, e.at);
  double t = e.change ? t_.toolChangeS : t_.tCodeS;
  report_.add(TimeKind::Auxiliary, e.at, t_.dynamic ? t : 0.0, 0.0);
  if (next_) next_->onTool(e);
}

void TimingStage::onSpindle(const SpindleEvent& e) {
  if (e.follows && t_.dynamic) {
    // G96 following: the model computes the rpm itself; keep the event's place in order.
    if (!next_) return;
    if (!held_.empty())
      after_.push_back(After{heldBase_ + held_.size() - 1, e});
    else
      next_->onSpindle(e);
    return;
  }
  stop();
  double t = 0;
  if (t_.dynamic) {
    auto signedRpm = [](SpindleDir d, double rpm) {
      return d == SpindleDir::Cw ? rpm : d == SpindleDir::Ccw ? -rpm : 0.0;
    };
    double from = signedRpm(dir_, rpm_), to = signedRpm(e.dir, e.rpm);
    if (t_.spindleWait) t += std::fabs(to - from) / t_.spindleAccel;
    if (e.dir != dir_ && !e.follows) t += t_.mCodeS;
  }
  rpm_ = (e.dir == SpindleDir::Cw || e.dir == SpindleDir::Ccw) ? e.rpm : 0.0;
  dir_ = e.dir;
  report_.add(TimeKind::Auxiliary, e.at, t, 0.0);
  if (next_) next_->onSpindle(e);
}

void TimingStage::onCoolant(const CoolantEvent& e) {
  stop();
  report_.add(TimeKind::Auxiliary, e.at, t_.dynamic ? t_.coolantS : 0.0, 0.0);
  if (next_) next_->onCoolant(e);
}

void TimingStage::onAux(const AuxEvent& e) {
  stop();
  report_.add(TimeKind::Auxiliary, e.at, t_.dynamic ? t_.mCodeS : 0.0, 0.0);
  if (next_) next_->onAux(e);
}

void TimingStage::onOffset(const OffsetEvent& e) {
  stop();
  if (next_) next_->onOffset(e);
}

void TimingStage::onSkip(const SkipEvent& e) {
  stop();
  if (next_) next_->onSkip(e);
}

}  // namespace ncvm
