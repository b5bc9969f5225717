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
  bool dynamic() const { return t_.dynamic; }

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

  // One cutting block as the planner sees it (mm, s).
  struct Segment {
    double length = 0;       // 0: a block without motion, transparent to the planner
    double vmax = 0;         // feed after clamps (arc, block time, override)
    timing::Ramp ramp;       // path acceleration and jerk from the axes' limits
    double vJunction = 0;    // limit at the start (corner with the previous block)
    bool stopAfter = false;  // exact stop at the end
    // Results.
    double vEntry = 0, vExit = 0, time = 0;
  };

 private:
  // A held cutting move: what the planner and the report need, about 200 bytes (the event
  // itself, about 650, is kept in events_ only when a sink follows).
  struct Held {
    Segment s;
    EventOrigin at;
    double length = 0;      // program units, for the report
    double timeSimple = 0;  // length / feed
    MoveMode mode = MoveMode::Linear;
  };
  // A G96 rpm event the control sent after the held move number seq (heldBase_ counts).
  struct After {
    size_t seq = 0;
    SpindleEvent e;
  };
  // A stretch of held blocks planned as one profile: the joints inside it do not limit the
  // speed, so the acceleration carries on across them (as it does on the control).
  struct Run {
    size_t first = 0, last = 0;  // held_ indexes, inclusive
    double length = 0, vmax = 0, vJunction = 0;
    timing::Ramp ramp;
    bool stopAfter = false;
    double exitCap = 0;  // look-ahead depth: the speed from which it can stop in what is read
    double vEntry = 0, vExit = 0;
  };
  void stop() { plan(true); }
  void plan(bool toStop);
  void buildRuns(size_t look);
  void commit(const Run& run);
  Segment segmentFor(const MoveEvent& e, AxisArray& dirIn, AxisArray& dirOut);
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
  size_t heldBase_ = 0;  // sequence number of held_.front()
  double entry_ = 0;     // velocity at the start of held_.front()
  AxisArray lastDir_{};
  bool haveDir_ = false;
  // Axis data, mm (deg for rotary axes).
  AxisArray scaleMm_{}, scaleInch_{};
  AxisArray accel_{}, jerk_{}, cornerDiff_{};
  double tMin_ = 0;
  // Spindle model.
  double rpm_ = 0;
  SpindleDir dir_ = SpindleDir::Stop;
  std::vector<double> lengths_, vEntryMax_, vExitMax_;
  std::vector<Run> runs_;
};

}  // namespace ncvm
