#include "server/step_recorder.hpp"

namespace ncvm::server {

StepRecorder::StepRecorder(const SourceFiles& files, const Setup& setup, uint64_t maxTraceBytes)
    : trace_(files, nullptr, maxTraceBytes, setup.reportedAxes()), diff_(setup, false) {}

void StepRecorder::attach(Executor* exec) {
  diff_.attach(exec);
}

template <class Write>
void StepRecorder::record(Write write, bool offsetsChanged) {
  // The trace line is written before a limit alarm is thrown: its step must exist too, so the
  // trace and the steps stay line for line.
  try {
    write();
  } catch (...) {
    snapshot(offsetsChanged);
    throw;
  }
  snapshot(offsetsChanged);
}

void StepRecorder::snapshot(bool offsetsChanged) {
  nlohmann::json step = diff_.next(offsetsChanged);
  if (step.is_null()) step = nlohmann::json::object();
  if (diff_.attached()) {
    step["b"] = diff_.blocks();
    step["t"] = diff_.time();
  }
  steps_.push_back(std::move(step));
}

void StepRecorder::onMove(const MoveEvent& e) {
  record([&] { trace_.onMove(e); }, false);
}
void StepRecorder::onDwell(const DwellEvent& e) {
  record([&] { trace_.onDwell(e); }, false);
}
void StepRecorder::onMessage(const MessageEvent& e) {
  record([&] { trace_.onMessage(e); }, false);
}
void StepRecorder::onAlarm(const AlarmEvent& e) {
  record([&] { trace_.onAlarm(e); }, false);
}
void StepRecorder::onTool(const ToolEvent& e) {
  record([&] { trace_.onTool(e); }, false);
}
void StepRecorder::onSpindle(const SpindleEvent& e) {
  record([&] { trace_.onSpindle(e); }, false);
}
void StepRecorder::onCoolant(const CoolantEvent& e) {
  record([&] { trace_.onCoolant(e); }, false);
}
void StepRecorder::onAux(const AuxEvent& e) {
  record([&] { trace_.onAux(e); }, false);
}
void StepRecorder::onSignal(const SignalEvent& e) {
  record([&] { trace_.onSignal(e); }, false);
}
void StepRecorder::onOffset(const OffsetEvent& e) {
  record([&] { trace_.onOffset(e); }, true);
}
void StepRecorder::onSkip(const SkipEvent& e) {
  record([&] { trace_.onSkip(e); }, false);
}

}  // namespace ncvm::server
