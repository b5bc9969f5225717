#include "server/step_recorder.hpp"

#include "app/machine_state.hpp"
#include "app/session.hpp"
#include "exec/executor.hpp"

namespace ncvm::server {

namespace {
// System variables shown in the viewer's panel (fanuc-reference: #3901/#3902 part counters,
// #4001-#4022 modal G codes, #4107-#4120 D F H M N O S T of the last block, #5001- block end,
// #5021- machine, #5041- work position, #5061- skip position, #5081- tool offset), per axis
// for the axes the machine reports.
std::vector<int> systemVariables(int axes) {
  std::vector<int> v{3901, 3902};
  for (int g = 4001; g <= 4022; ++g) v.push_back(g);
  for (int n : {4107, 4109, 4111, 4113, 4114, 4115, 4119, 4120}) v.push_back(n);
  for (int base : {5000, 5020, 5040, 5060, 5080})
    for (int k = 1; k <= axes; ++k) v.push_back(base + k);
  return v;
}
}  // namespace

StepRecorder::StepRecorder(const SourceFiles& files, const Setup& setup, uint64_t maxTraceBytes)
    : setup_(setup), trace_(files, nullptr, maxTraceBytes, setup.reportedAxes()) {}

void StepRecorder::attach(Executor* exec) {
  exec_ = exec;
}

void StepRecorder::diffInto(nlohmann::json& delta, const std::map<int, double>& before,
                            const std::map<int, double>& now) {
  for (const auto& [n, v] : now) {
    auto it = before.find(n);
    if (it == before.end() || it->second != v) delta["#" + std::to_string(n)] = v;
  }
  for (const auto& [n, v] : before)
    if (!now.count(n)) delta["#" + std::to_string(n)] = nullptr;
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
  nlohmann::json step = nlohmann::json::object();
  // Before the first block (an alarm in the main program's structure) the control has no
  // call level yet, so there is nothing to read.
  if (!exec_ || exec_->stats().blocks == 0) {
    steps_.push_back(step);
    return;
  }
  const RunStats& st = exec_->stats();
  step["b"] = st.blocks;
  step["t"] = st.time;

  std::map<int, double> locals, common, system;
  for (int n = 1; n <= 33; ++n) {
    Value v = exec_->readVar(n);
    if (!v.null) locals[n] = v.v;
  }
  for (const auto& [n, v] : exec_->userVariables())
    if (n >= 100) common[n] = v;
  static thread_local std::vector<int> sys;
  if (sys.empty()) sys = systemVariables(setup_.reportedAxes());
  for (int n : sys) {
    try {
      Value v = exec_->readVar(n);
      if (!v.null) system[n] = v.v;
    } catch (const std::exception&) {
      // A variable this machine does not have (an axis, a series): left out.
    }
  }
  nlohmann::json delta = nlohmann::json::object();
  diffInto(delta, locals_, locals);
  if (!delta.empty()) step["l"] = std::move(delta);
  delta = nlohmann::json::object();
  diffInto(delta, common_, common);
  if (!delta.empty()) step["c"] = std::move(delta);
  delta = nlohmann::json::object();
  diffInto(delta, system_, system);
  if (!delta.empty()) step["s"] = std::move(delta);
  locals_ = std::move(locals);
  common_ = std::move(common);
  system_ = std::move(system);

  nlohmann::json modal = modalJson(exec_->modal(), setup_);
  if (modal != modal_) {
    step["m"] = modal;
    modal_ = std::move(modal);
  }
  if (offsetsChanged || steps_.empty())
    step["o"] = {{"work", workOffsetsJson(exec_->memory(), setup_, true)},
                 {"tool", toolOffsetsJson(exec_->memory(), setup_)}};
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
