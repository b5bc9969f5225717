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
  threeAxes_ = true;
  for (size_t k = 3; k < kMaxAxes; ++k) threeAxes_ = threeAxes_ && !setup.axes[k].present;
  size_t axes = threeAxes_ ? 3 : kMaxAxes;
  uniform_ = true;
  slowest_ = Ramp{kInf, kInf};
  slowestValid_ = true;
  for (size_t k = 0; k < axes; ++k) {
    uniform_ = uniform_ && accel_[k] == accel_[0] && jerk_[k] == jerk_[0] &&
               cornerDiff_[k] == cornerDiff_[0];
    slowestValid_ = slowestValid_ && accel_[k] > 0 && std::isfinite(accel_[k]);
    slowest_.a = std::min(slowest_.a, accel_[k]);
    if (jerk_[k] > 0) slowest_.j = std::min(slowest_.j, jerk_[k]);
  }
  if (std::isinf(slowest_.j)) slowest_.j = 0;
  look_ = static_cast<size_t>(std::max(1, t_.lookaheadBlocks));
  trigger_ = 4 * look_ + 256;
  if (t_.dynamic) {
    held_.reserve(trigger_);
    if (next_) events_.reserve(trigger_);
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

// The block's length, feed and path limits, and its unit tangents at both ends (tanIn_,
// tanOut_). Runs once per cutting move: no allocation, one square root for a line.
void TimingStage::setSegment(const MoveEvent& e, Held& h) {
  if (threeAxes_)
    segment<3>(e, h);
  else
    segment<kMaxAxes>(e, h);
}

// N: the axes that can move (a three-axis machine has no A, B, C: half the work).
template <size_t N>
void TimingStage::segment(const MoveEvent& e, Held& h) {
  const AxisArray& scale = e.inch ? scaleInch_ : scaleMm_;
  AxisArray d{};
  double sq = 0;
  for (size_t k = 0; k < N; ++k) {
    d[k] = (e.mend[k] - e.mstart[k]) * scale[k];
    sq += d[k] * d[k];
  }
  double unit = e.inch ? 25.4 : 1.0;
  h.len = e.length * unit;
  if (h.len <= kEps) {
    h.len = 0;
    h.vmax = kInf;
    h.vJunction = kInf;
    return;
  }
  double feed = e.perRev > 0 ? spindleFeed(e, h.len) : e.feed * unit / 60.0;
  if (t_.feedOverride != 100) feed *= t_.feedOverride / 100.0;
  double a = kInf, j = kInf;
  if (!e.arc) {
    double inv = sq > 0 ? 1.0 / std::sqrt(sq) : 0.0;
    if (uniform_) {
      // min over the axes of accel / |u_k| is accel / max |u_k|.
      double big = 0;
      for (size_t k = 0; k < N; ++k) {
        double u = d[k] * inv;
        tanIn_[k] = u;
        big = std::max(big, std::fabs(u));
      }
      if (big > 1e-9) {
        a = accel_[0] / big;
        if (jerk_[0] > 0) j = jerk_[0] / big;
      }
    } else {
      for (size_t k = 0; k < N; ++k) {
        double u = d[k] * inv;
        tanIn_[k] = u;
        if (std::fabs(u) > 1e-9) {
          a = std::min(a, accel_[k] / std::fabs(u));
          if (jerk_[k] > 0) j = std::min(j, jerk_[k] / std::fabs(u));
        }
      }
    }
    tanOut_ = tanIn_;
  } else {
    PlaneAxes pl = planeAxes(e.plane);
    auto P = static_cast<size_t>(pl.p), Q = static_cast<size_t>(pl.q),
         H = static_cast<size_t>(pl.h);
    double rp0 = (e.start[P] - e.center[P]) * scale[P], rq0 = (e.start[Q] - e.center[Q]) * scale[Q];
    double rp1 = (e.end[P] - e.center[P]) * scale[P], rq1 = (e.end[Q] - e.center[Q]) * scale[Q];
    double r = std::sqrt(rp0 * rp0 + rq0 * rq0), r1 = std::sqrt(rp1 * rp1 + rq1 * rq1);
    double dh = d[H];
    double planar = std::sqrt(std::max(0.0, h.len * h.len - dh * dh));
    double sign = e.mode == MoveMode::Ccw ? 1.0 : -1.0;
    auto tangent = [&](double rp, double rq, double rr, AxisArray& u) {
      u.fill(0);
      if (rr <= 0) return;
      double f = sign * planar / (rr * h.len);
      u[P] = -rq * f;
      u[Q] = rp * f;
      u[H] = dh / h.len;
    };
    tangent(rp0, rq0, r, tanIn_);
    tangent(rp1, rq1, r1, tanOut_);
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
  h.vmax = feed;
  // The control cannot finish a block faster than it prepares one.
  if (tMin_ > 0) h.vmax = std::min(h.vmax, h.len / tMin_);
  h.ramp = Ramp{a, std::isinf(j) ? 0.0 : j};
}

// Automatic corner deceleration: no axis may change its speed by more than 1783 at the joint.
void TimingStage::setJunction(Held& h) {
  if (!haveDir_) {
    h.vJunction = held_.size() == 1 && entry_ == 0 ? 0.0 : kInf;
  } else if (uniform_) {
    double big = 0;
    size_t n = threeAxes_ ? 3 : kMaxAxes;
    for (size_t k = 0; k < n; ++k) big = std::max(big, std::fabs(tanIn_[k] - lastDir_[k]));
    h.vJunction = big > 1e-9 ? cornerDiff_[0] / big : kInf;
  } else {
    double v = kInf;
    for (size_t k = 0; k < kMaxAxes; ++k) {
      double du = std::fabs(tanIn_[k] - lastDir_[k]);
      if (du > 1e-9) v = std::min(v, cornerDiff_[k] / du);
    }
    h.vJunction = v;
  }
  lastDir_ = tanOut_;
  haveDir_ = true;
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

// Adds the next held block to the runs. A run ends at an exact stop, at a joint whose corner
// speed is below the feed, where the feed changes by more than 20 %, and after 128 blocks
// (so memory stays bounded; a cut inside a cruise costs nothing). Each block is grouped once,
// when the look-ahead window after it has been read (capped), or at a stop (not capped: the
// control sees the stop).
void TimingStage::group(bool capped) {
  size_t i = grouped_++;
  const Held& s = held_[i];
  bool join = !runs_.empty() && !runs_.back().stopAfter && std::isinf(runs_.back().exitCap);
  if (join && s.len > 0 && runs_.back().realBlocks > 0) {
    const Run& r = runs_.back();
    double lo = std::min(r.vmax, s.vmax), hi = std::max(r.vmax, s.vmax);
    join = s.vJunction >= lo * (1 - 1e-9) && lo >= 0.8 * hi && i - r.first < 128;
  }
  if (!join) {
    Run fresh;
    fresh.first = i;
    fresh.vmax = kInf;
    fresh.vJunction = s.vJunction;
    fresh.ramp = Ramp{kInf, 0};
    fresh.exitCap = kInf;
    runs_.push_back(fresh);
  }
  Run& r = runs_.back();
  r.last = i;
  r.length += s.len;
  r.stopAfter = s.stopAfter;
  if (s.len <= 0) return;
  if (r.realBlocks == 0) r.vJunction = std::min(r.vJunction, s.vJunction);
  ++r.realBlocks;
  r.vmax = std::min(r.vmax, s.vmax);
  r.ramp.a = std::min(r.ramp.a, s.ramp.a);
  if (s.ramp.j > 0) r.ramp.j = r.ramp.j > 0 ? std::min(r.ramp.j, s.ramp.j) : s.ramp.j;
  if (!capped) return;
  // Look-ahead depth: at the end of block i the control must be able to stop within the
  // look-ahead - 1 blocks it has read after it. That caps the run's speed; with nothing read
  // ahead (look-ahead 1) it stops there.
  double window = held_[i + look_ - 1].cum - s.cum;
  if (window <= 0) {
    r.exitCap = 0;
    return;
  }
  if (slowestValid_) {
    // Most blocks stop in time at their feed even on the slowest axis: no exact test.
    if (r.vmax != boundV_) boundV_ = r.vmax, boundD_ = rampDistance(0, r.vmax, slowest_);
    if (boundD_ <= window) return;
  }
  if (rampDistance(0, r.vmax, s.ramp) > window)
    r.vmax = std::min(r.vmax, reachable(0, window, s.ramp));
}

void TimingStage::plan(bool toStop) {
  size_t n = held_.size();
  if (n == 0) return;
  // The blocks whose window is not read yet go into provisional runs (without a cap); the
  // last final run may grow by them, so it is restored afterwards.
  size_t finalRuns = runs_.size();
  Run lastFinal;
  if (finalRuns > 0) lastFinal = runs_.back();
  size_t groupedBefore = grouped_;
  while (grouped_ < n) group(false);
  size_t m = runs_.size();
  // Without a stop in sight, forward only the runs that end before the last look-ahead
  // window: their speeds no longer depend on blocks not read yet.
  size_t commitRuns = m;
  if (!toStop) {
    commitRuns = 0;
    while (commitRuns < m && runs_[commitRuns].last + look_ < n) ++commitRuns;
  }
  double v = entry_;
  if (commitRuns > 0) {
    // Backward pass from the end of what is read (a stop there), as far as a limit changes:
    // a run that can no longer change and gets the same exit limit as in an earlier pass
    // keeps its entry limit, and so does every run before it.
    for (size_t i = m; i-- > 0;) {
      Run& r = runs_[i];
      double exitMax = i + 1 == m ? 0.0 : std::min(runs_[i + 1].vEntryMax, r.vmax);
      exitMax = std::min(exitMax, r.exitCap);
      if (r.stopAfter) exitMax = 0;
      bool fixed = i + 1 < finalRuns;
      if (fixed && r.planned && exitMax == r.vExitMax) break;
      double vmax = std::isinf(r.vmax) ? exitMax : r.vmax;
      r.vExitMax = exitMax;
      r.vEntryMax = std::min({vmax, r.vJunction, reachable(exitMax, r.length, r.ramp)});
      r.planned = fixed;
    }
    // Forward pass over the runs to send.
    for (size_t i = 0; i < commitRuns; ++i) {
      Run& r = runs_[i];
      r.vEntry = i == 0 ? entry_ : std::min(v, r.vEntryMax);
      r.vExit = r.length <= 0 ? std::min(r.vEntry, r.vExitMax)
                              : std::min(r.vExitMax, reachable(r.vEntry, r.length, r.ramp));
      v = r.vExit;
      commit(r);
    }
  }
  if (toStop) {
    for (const Mark& mk : marks_) applyMark(mk);  // after the last held move
    marks_.clear();
    entry_ = 0;
    runs_.clear();
    grouped_ = 0;
    if (next_) {
      events_.clear();
      after_.clear();
    }
    held_.clear();
    heldBase_ += n;
    haveDir_ = false;
    return;
  }
  // Drop the provisional runs, restore the last final one.
  runs_.resize(finalRuns);
  if (finalRuns > 0) runs_.back() = lastFinal;
  grouped_ = groupedBefore;
  if (commitRuns == 0) return;
  entry_ = v;  // the exit speed of the last run sent
  // Every run sent is final (its blocks' windows are read), so it is among runs_[0, finalRuns).
  size_t done = runs_[commitRuns - 1].last + 1;
  auto doneDiff = static_cast<std::ptrdiff_t>(done);
  held_.erase(held_.begin(), held_.begin() + doneDiff);
  runs_.erase(runs_.begin(), runs_.begin() + static_cast<std::ptrdiff_t>(commitRuns));
  for (Run& r : runs_) r.first -= done, r.last -= done;
  grouped_ -= done;
  if (next_) {
    events_.erase(events_.begin(), events_.begin() + doneDiff);
    size_t sent = 0;
    while (sent < after_.size() && after_[sent].seq < heldBase_ + done) ++sent;
    after_.erase(after_.begin(), after_.begin() + static_cast<std::ptrdiff_t>(sent));
  }
  heldBase_ += done;
}

void TimingStage::commit(const Run& run) {
  timing::Profile prof = timing::makeProfile(
      run.vEntry, run.vExit, std::isinf(run.vmax) ? 0.0 : run.vmax, run.length, run.ramp);
  double s = 0, before = 0, model = 0, simple = 0, length = 0;
  // The G96 events to send after the moves of this run (sorted by their move).
  size_t sp = 0;
  while (next_ && sp < after_.size() && after_[sp].seq < heldBase_ + run.first) ++sp;
  uint64_t count = 0;
  for (size_t i = run.first; i <= run.last; ++i) {
    if (!marks_.empty() && marks_.front().seq == heldBase_ + i) [[unlikely]] {
      // An operation starts here: the moves so far go to the one before.
      report_.addCutting(model, simple, length, count);
      model = simple = length = 0, count = 0;
      while (!marks_.empty() && marks_.front().seq == heldBase_ + i) {
        applyMark(marks_.front());
        marks_.erase(marks_.begin());
      }
    }
    ++count;
    const Held& h = held_[i];
    s += h.len;
    double at = i == run.last ? prof.total() : prof.timeAt(s);
    double time = std::max(at - before, tMin_);
    before = at;
    if (i == run.last && run.stopAfter) time += t_.inPositionS;
    report_.addLineTime(h.at, time, h.timeSimple);
    report_.addDrillMove(h.drill, time, h.timeSimple);
    model += time, simple += h.timeSimple, length += h.length;
    if (!next_) continue;
    MoveEvent& e = events_[i];
    e.time = time;
    next_->onMove(e);
    for (; sp < after_.size() && after_[sp].seq == heldBase_ + i; ++sp) {
      if (const auto* rpm = std::get_if<SpindleEvent>(&after_[sp].e))
        next_->onSpindle(*rpm);
      else
        next_->onWorkOrigin(std::get<WorkOriginEvent>(after_[sp].e));
    }
  }
  // The run's blocks are all cutting moves of the current operation: one sum for them.
  report_.addCutting(model, simple, length, count);
}

void TimingStage::applyMark(const Mark& m) {
  report_.commentSeen(m.text, m.at);
  if (next_) next_->onComment(CommentEvent{m.at, m.text});
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
  if (next_) {
    events_.push_back(in);
    events_.back().timeSimple = in.time;
  }
  double cum = held_.empty() ? 0.0 : held_.back().cum;
  Held& h = held_.emplace_back();
  h.at = in.at;
  h.length = in.length;
  h.timeSimple = in.time;
  h.drill = DrillMove::of(in);
  setSegment(in, h);
  h.cum = cum + h.len;
  if (h.len > 0) setJunction(h);
  if (in.surfaceSpeed > 0 && in.perRev <= 0 && (dir_ == SpindleDir::Cw || dir_ == SpindleDir::Ccw))
    followSpindle(cssTarget(in.end[0], in), in.time);
  h.stopAfter = in.exactStop;
  if (in.exactStop) {
    stop();
    return;
  }
  if (held_.size() > grouped_ + look_) group(true);
  if (held_.size() >= trigger_) plan(false);
}

void TimingStage::finish() {
  stop();
  report_.finish();
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

void TimingStage::onSignal(const SignalEvent& e) {
  stop();
  if (next_) next_->onSignal(e);
}

void TimingStage::onComment(const CommentEvent& e) {
  if (!t_.operationComments) {
    if (next_) next_->onComment(e);
    return;
  }
  if (held_.empty()) {
    report_.commentSeen(e.text, e.at);
    if (next_) next_->onComment(e);
    return;
  }
  marks_.push_back(Mark{heldBase_ + held_.size(), e.at, std::string(e.text)});
}

// Work zero moved: no stop (the time model does not change), but the sinks after the stage
// (the web viewer, which draws the path fixed on the machine) get it after the moves before it.
void TimingStage::onWorkOrigin(const WorkOriginEvent& e) {
  if (!next_) return;
  if (!held_.empty())
    after_.push_back(After{heldBase_ + held_.size() - 1, e});
  else
    next_->onWorkOrigin(e);
}

void TimingStage::onSkip(const SkipEvent& e) {
  stop();
  if (next_) next_->onSkip(e);
}

}  // namespace ncvm
