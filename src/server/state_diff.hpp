#pragma once
// What changed in the control since the last look, for the viewer's timeline: macro variables
// (locals of the current level, common, a set of system variables), modal state, offsets,
// block count and time. Both forms of the run answer use it: the JSON one (step_recorder.hpp)
// and the binary stream (viewer_stream.hpp).
//
// The state is read from the control when the event reaches the viewer. Under cutter
// compensation a move leaves the control's look-ahead buffer after the blocks read ahead,
// so its snapshot already holds what those blocks did (as on a real control's screen).
#include <array>
#include <nlohmann/json.hpp>
#include <vector>

#include "canon/events.hpp"
#include "exec/executor.hpp"

namespace ncvm {
struct Setup;
}

namespace ncvm::server {

class StateDiff {
 public:
  // positionsApart: #5001-, #5021- and #5041- (block end, machine and work position, which
  // change with nearly every move) are kept out of the "s" delta and read into positions().
  StateDiff(const Setup& setup, bool positionsApart);
  void attach(Executor* exec) { exec_ = exec; }
  bool attached() const { return exec_ != nullptr && exec_->stats().blocks > 0; }

  // The delta since the last call: {"l", "c", "s": {"#n": value or null}, "m": the modal
  // entries that changed (all of them the first time), "o": offsets}, each only when it
  // changed ("o" also on the first call). Null when nothing changed, and before the first
  // block (an alarm in the main program's structure: no call level to read yet).
  nlohmann::json next(bool offsetsChanged);
  uint64_t blocks() const { return exec_ ? exec_->stats().blocks : 0; }
  double time() const { return exec_ ? exec_->stats().time : 0; }
  // #5001.., #5021.., #5041.. (axes each) as read by the last next(), with positionsApart.
  const std::vector<double>& positions() const { return positions_; }

 private:
  const Setup& setup_;
  const bool positionsApart_;
  Executor* exec_ = nullptr;
  std::vector<int> system_numbers_;
  // Adds "#number": now to step[key] (a change from `was`, which becomes now).
  void changed(nlohmann::json& step, const char* key, int number, const Value& now, Value& was);
  // changed() for each variable of `now` (numbered from `first`) that differs from was[].
  template <size_t N>
  void compareAll(nlohmann::json& step, const char* key, int first, const std::array<Value, N>& now,
                  Value* was);

  // Locals, common (#100-#199, #500-#999) and system variables as last read.
  std::array<Value, 33> locals_{};
  std::array<Value, 600> common_{};
  std::vector<Value> system_;
  std::vector<bool> systemReadable_;
  std::vector<double> positions_;
  bool first_ = true;
  bool haveModal_ = false;
  ModalState lastModal_{};
  nlohmann::json modal_;
};

}  // namespace ncvm::server
