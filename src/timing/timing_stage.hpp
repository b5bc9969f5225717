#pragma once
// The cycle-time model as an event stage: it sits between the control and the other sinks
// (trace, statistics), holds the cutting moves the control's look-ahead would hold, plans
// their velocities the way Fanuc's look-ahead acc/dec before interpolation does, and
// forwards every event in order with the modelled time in MoveEvent::time (the plain
// length / feed time in MoveEvent::timeSimple). The control never depends on it.
//
// What is modelled (each value from the setup's [timing], docs/setup-format.md):
// rapids per axis (1420 rates, 1620/1621 time constants; linear path when 1401#1 LRP = 1,
// each axis on its own otherwise) with the in-position check at their end; cutting feed
// with acceleration and jerk limits (1660, 1772), corner speeds from the permissible speed
// difference (1783), the arc feed clamp (1730-1732), a look-ahead of N blocks, the block
// processing time, exact stop (G09, G61); dwell in seconds or revolutions; M, S and T
// function times, the spindle ramps and G96 following X with the spindle acceleration.
#include <string>
#include <variant>
#include <vector>

#include "canon/events.hpp"
#include "machine/setup.hpp"
#include "timing/profile.hpp"
#include "timing/time_report.hpp"

namespace ncvm {

class TimingStage final : public EventSink {
 public:
  TimingStage(const Setup& setup, EventSink& next) : TimingStage(setup, &next) {}
  // next nullptr: nothing listens after the stage (only the report is wanted), so the
  // look-ahead keeps compact records and no copy of the events.
  TimingStage(const Setup& setup, EventSink* next);
  // Plans and forwards the moves still held (the program ended or stopped).
  void finish();
  const TimeReport& report() const { return report_; }
  TimeReport takeReport() { return std::move(report_); }
  // Lines per file (TimeReport::setLineCounts); before the first event.
  void setLineCounts(std::vector<uint32_t> counts) { report_.setLineCounts(std::move(counts)); }
  bool dynamic() const { return t_.dynamic; }
  // True while the stage holds events it has not forwarded yet (the look-ahead).
  bool holding() const { return !held_.empty() || !after_.empty() || !marks_.empty(); }

  void onMove(const MoveEvent& e) override;
  void onDwell(const DwellEvent& e) override;
  void onMessage(const MessageEvent& e) override;
  void onAlarm(const AlarmEvent& e) override;
  void onTool(const ToolEvent& e) override;
  void onSpindle(const SpindleEvent& e) override;
  void onCoolant(const CoolantEvent& e) override;
  void onAux(const AuxEvent& e) override;
  void onOffset(const OffsetEvent& e) override;
  void onSkip(const SkipEvent& e) override;
  void onSignal(const SignalEvent& e) override;
  void onComment(const CommentEvent& e) override;
  void onWorkOrigin(const WorkOriginEvent& e) override;

 private:
  // A held cutting block: what the planner and the report need (mm, s), about 140 bytes (the
  // event itself, about 650, is kept in events_ only when a sink follows).
  struct Held {
    double len = 0;        // mm; 0: a block without motion, transparent to the planner
    double vmax = 0;       // feed after clamps (arc, block time, override)
    timing::Ramp ramp;     // path acceleration and jerk from the axes' limits
    double vJunction = 0;  // limit at the start (corner with the previous block)
    double cum = 0;        // mm from the start of the stretch held since the last stop
    EventOrigin at;
    double length = 0;       // program units, for the report
    double timeSimple = 0;   // length / feed
    bool stopAfter = false;  // exact stop at the end
    DrillMove drill;         // for the report's holes, with the time once planned
  };
  // An event the control sent after the held move number seq (heldBase_ counts) that does
  // not stop the look-ahead: a G96 rpm, or where work zero now is (a macro writing #5221,
  // G10, G92 between cutting moves); forwarded right after that move, in order.
  struct After {
    size_t seq = 0;
    std::variant<SpindleEvent, WorkOriginEvent> e;
  };
  // A comment that starts an operation before the held move number seq: the moves before it
  // belong to the operation before (the comment does not stop the look-ahead).
  struct Mark {
    size_t seq = 0;
    EventOrigin at;
    std::string text;
  };
  void applyMark(const Mark& m);
  // A stretch of held blocks planned as one profile: the joints inside it do not limit the
  // speed, so the acceleration carries on across them (as it does on the control).
  struct Run {
    size_t first = 0, last = 0;  // held_ indexes, inclusive
    double length = 0, vmax = 0, vJunction = 0;
    timing::Ramp ramp;
    bool stopAfter = false;
    double exitCap = 0;     // look-ahead depth: 0 when nothing is read after the run's end
    size_t realBlocks = 0;  // blocks with motion
    // Backward pass: the highest exit and entry speeds from which the control can still stop
    // where it must; `planned` when they were computed for a run that can no longer change.
    double vExitMax = 0, vEntryMax = 0;
    bool planned = false;
    double vEntry = 0, vExit = 0;  // forward pass
  };
  void stop() { plan(true); }
  void plan(bool toStop);
  // Adds held_[grouped_] to the runs; capped: the look-ahead window after it is known.
  void group(bool capped);
  void commit(const Run& run);
  void setSegment(const MoveEvent& e, Held& h);
  template <size_t N>
  void segment(const MoveEvent& e, Held& h);
  void setJunction(Held& h);
  void forwardMove(const MoveEvent& e) {
    if (next_) next_->onMove(e);
  }
  double rapidTime(const MoveEvent& e) const;
  double spindleFeed(const MoveEvent& e, double lengthMm);
  double cssTarget(double x, const MoveEvent& e) const;
  void followSpindle(double target, double seconds);

  const Setup& setup_;
  TimingSetup t_;
  EventSink* next_;
  TimeReport report_;
  std::vector<Held> held_;         // a vector reused as a queue: no allocation per move
  std::vector<MoveEvent> events_;  // held_'s events, in step with it, when next_ is set
  std::vector<After> after_;
  std::vector<Mark> marks_;
  size_t heldBase_ = 0;  // sequence number of held_.front()
  double entry_ = 0;     // velocity at the start of held_.front()
  // Unit tangents of the newest block at its start and end, and at the end of the one before.
  AxisArray tanIn_{}, tanOut_{}, lastDir_{};
  bool haveDir_ = false;
  // Axis data, mm (deg for rotary axes).
  AxisArray scaleMm_{}, scaleInch_{};
  AxisArray accel_{}, jerk_{}, cornerDiff_{};
  // Every axis with the same limits (the usual setup): the path limits follow from the
  // largest direction component alone, one division instead of one per axis.
  bool uniform_ = false;
  bool threeAxes_ = false;  // no A, B, C axis: they never move
  // The slowest ramp of any axis: no block stops in a longer distance than with it, so the
  // look-ahead cap needs its exact test only where this bound exceeds the window.
  timing::Ramp slowest_;
  bool slowestValid_ = false;
  double boundV_ = -1, boundD_ = 0;  // the last bound computed (the feed rarely changes)
  double tMin_ = 0;
  size_t look_ = 1;     // look-ahead depth in blocks
  size_t trigger_ = 0;  // plan when this many blocks are held
  // Spindle model.
  double rpm_ = 0;
  SpindleDir dir_ = SpindleDir::Stop;
  std::vector<Run> runs_;  // runs of held_[0, grouped_), oldest first
  size_t grouped_ = 0;     // held_[0, grouped_) are in runs_ (their look-ahead cap is known)
};

}  // namespace ncvm
