#pragma once
// The viewer's timeline: every event of a run as its trace line (docs/trace-format.md), and
// beside each one what changed in the control since the previous event, so the browser can
// rebuild the control's state at any step: macro variables (locals of the current level,
// common, a set of system variables), modal state, offsets, block count and time.
//
// The state is read from the control when the event reaches the viewer. Under cutter
// compensation a move leaves the control's look-ahead buffer after the blocks read ahead,
// so its snapshot already holds what those blocks did (as on a real control's screen).
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "canon/events.hpp"
#include "core/source.hpp"
#include "report/trace_writer.hpp"

namespace ncvm {
class Executor;
struct Setup;
}  // namespace ncvm

namespace ncvm::server {

class StepRecorder final : public EventSink {
 public:
  StepRecorder(const SourceFiles& files, const Setup& setup, uint64_t maxTraceBytes);
  // The control of the run; set before the first block (Session's inspector).
  void attach(Executor* exec);

  const std::string& trace() const { return trace_.buffer(); }
  nlohmann::json& steps() { return steps_; }

  void onMove(const MoveEvent& e) override;
  void onDwell(const DwellEvent& e) override;
  void onMessage(const MessageEvent& e) override;
  void onAlarm(const AlarmEvent& e) override;
  void onTool(const ToolEvent& e) override;
  void onSpindle(const SpindleEvent& e) override;
  void onCoolant(const CoolantEvent& e) override;
  void onAux(const AuxEvent& e) override;
  void onSignal(const SignalEvent& e) override;
  void onOffset(const OffsetEvent& e) override;
  void onSkip(const SkipEvent& e) override;

 private:
  template <class Write>
  void record(Write write, bool offsetsChanged);
  void snapshot(bool offsetsChanged);
  // Adds to `delta` the entries of `now` that differ from `before`, vacant ones as null.
  static void diffInto(nlohmann::json& delta, const std::map<int, double>& before,
                       const std::map<int, double>& now);

  const Setup& setup_;
  TraceWriter trace_;
  Executor* exec_ = nullptr;
  nlohmann::json steps_ = nlohmann::json::array();
  std::map<int, double> locals_, common_, system_;
  nlohmann::json modal_;
};

}  // namespace ncvm::server
