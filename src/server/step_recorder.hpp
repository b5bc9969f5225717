#pragma once
// The viewer's timeline as JSON (POST /api/run): every event of a run as its trace line
// (docs/trace-format.md), and beside each one what changed in the control since the previous
// event (state_diff.hpp), so a client can rebuild the control's state at any step. The page
// itself reads the binary form (viewer_stream.hpp).
#include <nlohmann/json.hpp>
#include <string>

#include "canon/events.hpp"
#include "core/source.hpp"
#include "report/trace_writer.hpp"
#include "server/state_diff.hpp"

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

  TraceWriter trace_;
  StateDiff diff_;
  nlohmann::json steps_ = nlohmann::json::array();
};

}  // namespace ncvm::server
