// The system variables of fanuc-reference B.8-B.10 (#1000 and up), which read and change the
// machine; #0-#999 are the MacroVariables component's (macro_variables.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "exec/executor.hpp"

namespace ncvm {

int Executor::axisByNumber(int n) const {
  // Controlled axis numbers count only the axes the machine has: on a lathe #5002 is Z.
  int seen = 0;
  for (int k = 0; k < kMaxAxes; ++k) {
    if (!setup_.axes[static_cast<size_t>(k)].present) continue;
    if (++seen == n) return k;
  }
  return -1;
}

// PS0115 for a number ncvm does not know: the Fanuc range it is in when there is one, so a
// user knows whether to configure it or to ask for it.
static AlarmError unknownVariable(int64_t n) {
  struct Range {
    int64_t from, to;
    const char* name;
  };
  static const Range known[] = {
      {1033, 1035, "interface signal inputs UI100-UI131, UI200-UI231, UI300-UI331 as words"},
      {1134, 1135, "interface signal outputs UO200-UO231, UO300-UO331 as words"},
      {1100, 1199, "interface signal outputs"},
      {1000, 1099, "interface signal inputs"},
      {2000, 2999, "tool offsets"},
      {3100, 3199, "system constants"},
      {3000, 3999, "alarm, clock, automatic operation control, part count"},
      {4000, 4999, "modal information"},
      {5000, 5999, "position information, work offsets"},
      {7000, 7999, "additional work offsets G54.1 P1-P48 (mill)"},
      {10000, 19999, "tool offsets, additional work offsets G54.1 P1-P300"},
      // Real 30i programs use these as common variables (#900000-) and to read parameters
      // (#100000-); no Fanuc manual found gives them (docs/real-programs.md).
      {100000, 199999, "#100000-#199999, outside the Fanuc variable tables ncvm models"},
      {900000, 999999, "#900000-#999999, outside the Fanuc variable tables ncvm models"},
  };
  for (const Range& r : known)
    if (n >= r.from && n <= r.to)
      return AlarmError(AlarmId::VariableOutOfRange,
                        fmt::format("#{} ({}): not supported by ncvm", n, r.name));
  return AlarmError(AlarmId::VariableOutOfRange, fmt::format("#{}", n));
}

// #0-#999 belong to the macro variables (macro_variables.hpp); the rest is the system's.
Value Executor::readVar(int64_t n) {
  if (n < 1000) return vars_.read(n, frames_.back().level);
  return readSystem(n);
}

void Executor::writeVar(int64_t n, Value v) {
  if (n < 1000) return vars_.write(n, v, localLevel());
  if (!v.null && !std::isfinite(v.v)) throw AlarmError(AlarmId::FloatOverflow);
  writeSystem(n, v);
}

Value Executor::readSystem(int64_t n) {
  auto posVar = [&](int64_t base, const std::array<int64_t, kMaxAxes>& nm, bool work) -> Value {
    int slot = axisByNumber(static_cast<int>(n - base));
    if (slot < 0)
      throw AlarmError(AlarmId::VariableOutOfRange, fmt::format("#{}: no such axis", n));
    (void)work;
    return Value::num(toProgramUnits(nm[static_cast<size_t>(slot)], slot, true));
  };
  if (n >= 5001 && n <= 5020) return posVar(5000, programmed_, true);
  if (n >= 5021 && n <= 5040) return posVar(5020, machine_, false);
  if (n >= 5041 && n <= 5060) {
    std::array<int64_t, kMaxAxes> work{};
    for (size_t k = 0; k < kMaxAxes; ++k) work[k] = machine_[k] - offset_[k];
    return posVar(5040, work, true);
  }
  if (n >= 5061 && n <= 5080) return posVar(5060, skip_, true);
  if (n >= 5081 && n <= 5100) return posVar(5080, toolShift_, false);
  if (n >= 5101 && n <= 5120) return Value::num(0.0);  // servo deviation: none in a simulation
  // Manual handle interruption: no handle on a simulated machine.
  if (n >= 5121 && n <= 5140) {
    if (axisByNumber(static_cast<int>(n - 5120)) < 0)
      throw AlarmError(AlarmId::VariableOutOfRange, fmt::format("#{}: no such axis", n));
    return Value::num(0.0);
  }
  if (n >= 1000 && n <= 1032) {
    std::string warning;
    const double x = signals_.readInput(static_cast<int>(n), warning);
    if (!warning.empty()) warn("W006", std::move(warning));
    return Value::num(x);
  }
  if (n >= 1100 && n <= 1133) return Value::num(signals_.readOutput(static_cast<int>(n)));
  if ((n >= 4001 && n <= 4030) || (n >= 4201 && n <= 4230)) {
    // Parameter 0001#1 (FCV) = 1, the Series 15 program format: the modal groups are read by
    // their FS15 numbers, where the work coordinate system G54-G59 is group 12 (#4012) and the
    // macro modal call G66/G67 group 14 (docs/fanuc-decisions.md, "FS15 program format").
    size_t group = static_cast<size_t>(n % 100);
    if ((group == 12 || group == 14) && setup_.bit("0001#1")) group = group == 12 ? 14 : 12;
    return Value::num(modal_.g[group] / 10.0);
  }
  if ((n >= 4102 && n <= 4130) || (n >= 4302 && n <= 4330)) {
    int64_t k = n >= 4300 ? n - 200 : n;
    switch (k) {
      case 4102:
        return Value::num(modal_.b);
      case 4107:
        return Value::num(modal_.dOffset);
      case 4108:
        return Value::num(modal_.e);
      case 4109:
        return Value::num(modal_.feed);
      case 4111:
        return Value::num(modal_.hOffset);
      case 4113:
        return Value::num(modal_.lastM);
      case 4114:
        return Value::num(lastN_);
      case 4115:
        return Value::num(frames_.back().prog->number >= 0 ? frames_.back().prog->number : 0);
      case 4119:
        return Value::num(modal_.speed);
      case 4120:
        return Value::num(modal_.tool);
      case 4130:
        return Value::num(modal_.workP);
      default:
        return Value::vacant();
    }
  }
  switch (n) {
    case 3000:
      return Value::vacant();
    case 3001:
      return Value::num(std::floor(simTime_ * 1000.0 + timerMsOffset_));
    case 3002:
      return Value::num(simTime_ / 3600.0 + timerHourOffset_);
    case 3003:
      return Value::num(sys3003_);
    case 3004:
      return Value::num(sys3004_);
    case 3005:
      return Value::num(sys3005_);
    case 3006:
      return Value::vacant();
    case 3007:
      return Value::num(0);  // mirror image status: none
    case 3011:
      return Value::num(static_cast<double>(setup_.date));
    case 3012: {
      // Start time plus simulated time, as HHMMSS.
      int64_t start = setup_.time;
      int64_t secs = (start / 10000) * 3600 + (start / 100 % 100) * 60 + start % 100 +
                     static_cast<int64_t>(simTime_);
      secs %= 86400;
      return Value::num(
          static_cast<double>(secs / 3600 * 10000 + secs / 60 % 60 * 100 + secs % 60));
    }
    // System constants (30i, 0i-F): pi and e.
    case 3100:
      return Value::num(3.14159265358979323846);
    case 3101:
      return Value::num(2.71828182845904523536);
    case 3901:
      return Value::num(mem_.parts3901);
    case 3902:
      return Value::num(mem_.parts3902);
    case 4000: {
      const Program* main = frames_.front().prog;
      return Value::num(main->number >= 0 ? main->number : 0);
    }
    default:
      break;
  }
  Value out;
  if (offsetVariable(n, &out, nullptr)) return out;
  throw unknownVariable(n);
}

void Executor::writeSystem(int64_t n, Value v) {
  std::string comment = block_ && block_->comment >= 0
                            ? frames_.back().prog->strings[static_cast<size_t>(block_->comment)]
                            : "";
  switch (n) {
    case 3000: {
      // Macro alarm 3000+n with the block's comment as its message.
      int64_t k = std::llround(v.asNumber());
      if (k < 0 || k > 999) throw AlarmError(AlarmId::ArgumentOutOfRange, "#3000 takes 0-999");
      throw AlarmError(fmt::format("MC{}", 3000 + k), comment);
    }
    case 3001:
      timerMsOffset_ = v.asNumber() - simTime_ * 1000.0;
      return;
    case 3002:
      timerHourOffset_ = v.asNumber() - simTime_ / 3600.0;
      return;
    case 3003:
      sys3003_ = v.asNumber();
      return;
    case 3004:
      sys3004_ = v.asNumber();
      return;
    case 3005:
      sys3005_ = v.asNumber();
      return;
    case 3006: {
      // Message stop: recorded; the run continues as if cycle start were pressed.
      sink().onMessage(MessageEvent{origin_, comment, "#3006"});
      return;
    }
    case 3901:
      mem_.parts3901 = v.asNumber();
      return;
    case 3902:
      mem_.parts3902 = v.asNumber();
      return;
    default:
      break;
  }
  if (n >= 1100 && n <= 1133) {
    const double stored = signals_.writeOutput(static_cast<int>(n), v);
    sink().onSignal(SignalEvent{origin_, static_cast<int>(n), stored});
    return;
  }
  if (n == 3007 || n == 3011 || n == 3012 || n == 4000 || (n >= 4001 && n <= 4330) ||
      (n >= 5001 && n <= 5140) || (n >= 1000 && n <= 1032) || n == 3100 || n == 3101)
    throw AlarmError(AlarmId::WriteProtectedVariable, fmt::format("#{}", n));
  if (offsetVariable(n, nullptr, &v)) return;
  throw unknownVariable(n);
}

}  // namespace ncvm
