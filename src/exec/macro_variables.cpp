#include "exec/macro_variables.hpp"

#include <fmt/format.h>

#include "core/alarm.hpp"

namespace ncvm {

// #200-#499 exist only with the option that adds common variables.
void MacroVariables::checkCommon200(int64_t n) const {
  if (!hasCommon200_)
    throw AlarmError(
        AlarmId::VariableOutOfRange,
        fmt::format("#{}: common variables #200-#499 are an option (options.common_vars_200 = true "
                    "in the setup)",
                    n));
}

Value MacroVariables::readOther(int64_t n) const {
  if (n == 0) return Value::vacant();
  if (n >= 200 && n <= 499) {
    checkCommon200(n);
    return common200_[static_cast<size_t>(n - 200)];
  }
  throw AlarmError(AlarmId::VariableOutOfRange, fmt::format("#{}", n));
}

void MacroVariables::overflow() {
  throw AlarmError(AlarmId::FloatOverflow);
}

void MacroVariables::writeOther(int64_t n, Value v) {
  if (n == 0) throw AlarmError(AlarmId::WriteProtectedVariable, "#0");
  if (n >= 200 && n <= 499) {
    checkCommon200(n);
    common200_[static_cast<size_t>(n - 200)] = v;
    return;
  }
  throw AlarmError(AlarmId::VariableOutOfRange, fmt::format("#{}", n));
}

void MacroVariables::enterCall(int level, const Locals& args, const Scales& scale) {
  const size_t L = index(level);
  locals_[L] = args;
  noPointScale_[L] = scale;
  callArgs_[L] = args;
  callArgScale_[L] = scale;
}

void MacroVariables::repeatCall(int level) {
  const size_t L = index(level);
  locals_[L] = callArgs_[L];
  noPointScale_[L] = callArgScale_[L];
}

std::vector<std::pair<int, double>> MacroVariables::userVariables() const {
  std::vector<std::pair<int, double>> out;
  auto add = [&out](int first, const auto& values) {
    for (size_t k = 0; k < values.size(); ++k)
      if (!values[k].null) out.emplace_back(first + static_cast<int>(k), values[k].v);
  };
  add(1, locals_[0]);
  add(100, common100_);
  add(200, common200_);
  add(500, common500_);
  return out;
}

}  // namespace ncvm
