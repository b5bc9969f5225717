#include "exec/interface_signals.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/alarm.hpp"

namespace ncvm {

double InterfaceSignals::next(int n) {
  const std::vector<double>& values = spec_.inputs.at(n);
  uint32_t& k = reads_[static_cast<size_t>(n - 1000)];
  double x = values[std::min<size_t>(k, values.size() - 1)];
  if (k < values.size()) ++k;
  return x;
}

// A bit the setup does not give comes from #1032's word when that is given; #1032 not given is
// made of the bits that are (the others 0).
double InterfaceSignals::readInput(int n, std::string& warning) {
  const auto& inputs = spec_.inputs;
  if (inputs.count(n)) return next(n);
  if (n < 1032) {
    if (inputs.count(1032))
      return static_cast<double>((static_cast<uint32_t>(next(1032)) >> (n - 1000)) & 1u);
  } else {
    bool any = false;
    uint32_t word = 0;
    for (int k = 0; k < 32; ++k)
      if (inputs.count(1000 + k)) {
        any = true;
        if (next(1000 + k) != 0) word |= 1u << k;
      }
    if (any) return static_cast<double>(word);
  }
  const std::string what = n < 1032 ? fmt::format("#{} (input signal UI{:03d})", n, n - 1000)
                                    : std::string("#1032 (input signals UI000-UI031)");
  if (spec_.missingAlarm) throw AlarmError(AlarmId::SignalNotGiven, what);
  if (!warned_[static_cast<size_t>(n - 1000)]) {
    warned_[static_cast<size_t>(n - 1000)] = true;
    warning = what + " is not in the setup's [signals]: it reads 0";
  }
  return 0;
}

// #1100-#1131 set one output (0 off, any other value on; vacant is 0); #1132 and #1133 set 32
// at once (a negative value is its 32-bit two's complement).
double InterfaceSignals::writeOutput(int n, Value v) {
  const double x = v.null ? 0.0 : v.v;
  if (n <= 1131) {
    const uint32_t bit = 1u << (n - 1100);
    const bool on = x != 0;
    out_[0] = on ? out_[0] | bit : out_[0] & ~bit;
    return on ? 1 : 0;
  }
  const double r = std::nearbyint(x);
  if (!(r >= -2147483648.0 && r <= 4294967295.0))
    throw AlarmError(AlarmId::IntegerOverflow, fmt::format("#{} takes a 32-bit value", n));
  const auto word = static_cast<uint32_t>(static_cast<int64_t>(r));
  out_[static_cast<size_t>(n - 1132)] = word;
  return static_cast<double>(word);
}

double InterfaceSignals::readOutput(int n) const {
  if (n <= 1131) return static_cast<double>((out_[0] >> (n - 1100)) & 1u);
  return static_cast<double>(out_[static_cast<size_t>(n - 1132)]);
}

}  // namespace ncvm
