#pragma once
// The machine's interface signals as the macro sees them (fanuc-reference B.8): inputs
// #1000-#1031 one bit each and #1032 the word UI000-UI031, each read taking the next value the
// setup's [signals] gives; outputs #1100-#1131 one bit each, #1132 the word UO000-UO031 and
// #1133 UO100-UO131. The Executor sends those numbers here and emits the signal events.
#include <array>
#include <cstdint>
#include <string>

#include "core/value.hpp"
#include "machine/setup.hpp"

namespace ncvm {

class InterfaceSignals {
 public:
  explicit InterfaceSignals(const SignalSpec& spec) : spec_(spec) {}

  // #1000-#1032. An input the setup does not give reads 0 and sets `warning` (the first read
  // of that input only), or alarms PS with signals.missing_alarm.
  double readInput(int n, std::string& warning);
  // #1100-#1133: stores v and returns the value the output now holds (0/1 for one bit, the
  // 32-bit word for #1132/#1133). A word that does not fit 32 bits alarms.
  double writeOutput(int n, Value v);
  // #1100-#1133 as a read gives them.
  double readOutput(int n) const;
  // 0 = UO000-UO031, 1 = UO100-UO131.
  uint32_t outputs(int word) const { return out_[static_cast<size_t>(word)]; }

 private:
  double next(int n);  // the next value of input n's list (the last one repeats)

  const SignalSpec& spec_;
  std::array<uint32_t, 33> reads_{};  // reads so far of each input (its place in the list)
  std::array<bool, 33> warned_{};     // its missing-input warning was given
  std::array<uint32_t, 2> out_{};
};

}  // namespace ncvm
