#pragma once
// The macro variables a program owns (fanuc-reference B.2, B.8): #0, the locals #1-#33 of
// each macro call level, the common variables #100-#199, #200-#499 (an option) and #500-#999.
// System variables (#1000 and up) read and change the machine, so the Executor answers them
// (variables.cpp); this component knows nothing of positions, offsets or the call stack.
//
// Call levels are numbered as the Executor's frames number them: 0 is the main program and
// every subprogram called from it, each G65/G66/code-call macro one level deeper.
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/value.hpp"

namespace ncvm {

class MacroVariables {
 public:
  static constexpr int kLevels = 16;  // above every control's macro nesting limit
  using Locals = std::array<Value, 33>;
  // Per local: the factor that undoes the least-increment scaling of an argument written
  // without a decimal point (ADP; 1000 for IS-B mm), 0 for any other value.
  using Scales = std::array<double, 33>;

  // common500: #500-#999, kept by the machine's persistent memory (the caller's, not copied).
  // common200: whether the option that adds #200-#499 is there; without it they alarm PS0115.
  MacroVariables(std::array<Value, 500>& common500, bool common200)
      : common500_(common500), hasCommon200_(common200) {}
  MacroVariables(const MacroVariables&) = delete;
  MacroVariables& operator=(const MacroVariables&) = delete;

  // n in #0-#999 (the caller sends #1000 and up to the system table). Alarms: PS0115 for a
  // number that is not a variable (or #200-#499 without their option).
  Value read(int64_t n, int level) const {
    if (n >= 1 && n <= 33) return locals_[index(level)][static_cast<size_t>(n - 1)];
    if (n >= 100 && n <= 199) return common100_[static_cast<size_t>(n - 100)];
    if (n >= 500 && n <= 999) return common500_[static_cast<size_t>(n - 500)];
    return readOther(n);
  }
  // Alarms: PS0116 for #0, PS0115 as read(); a value that is not finite: PS0111 (overflow).
  void write(int64_t n, Value v, int level) {
    if (!v.null && !std::isfinite(v.v)) [[unlikely]]
      overflow();
    if (n >= 1 && n <= 33) {
      const size_t L = index(level);
      locals_[L][static_cast<size_t>(n - 1)] = v;
      noPointScale_[L][static_cast<size_t>(n - 1)] = 0;  // a value the macro set is not scaled
    } else if (n >= 100 && n <= 199) {
      common100_[static_cast<size_t>(n - 100)] = v;
    } else if (n >= 500 && n <= 999) {
      common500_[static_cast<size_t>(n - 500)] = v;
    } else {
      writeOther(n, v);
    }
  }

  // A macro call enters `level` with its arguments; repeatCall starts an L repeat of the call
  // again with the same arguments (what the body did to its locals is undone).
  void enterCall(int level, const Locals& args, const Scales& scale);
  void repeatCall(int level);
  double noPointScale(int level, int n) const {
    return n >= 1 && n <= 33 ? noPointScale_[index(level)][static_cast<size_t>(n - 1)] : 0.0;
  }

  const Locals& locals(int level) const { return locals_[index(level)]; }
  const std::array<Value, 100>& common100() const { return common100_; }
  // The non-vacant locals of level 0 and the common variables, by number, for the state file.
  std::vector<std::pair<int, double>> userVariables() const;

 private:
  static size_t index(int level) { return static_cast<size_t>(level); }
  // #0, #200-#499 and the numbers that are not variables: kept out of line, off the hot path.
  Value readOther(int64_t n) const;
  void writeOther(int64_t n, Value v);
  [[noreturn]] static void overflow();
  void checkCommon200(int64_t n) const;

  std::array<Locals, kLevels> locals_{};
  std::array<Scales, kLevels> noPointScale_{};
  // What each level's call passed, for its L repeats.
  std::array<Locals, kLevels> callArgs_{};
  std::array<Scales, kLevels> callArgScale_{};
  std::array<Value, 100> common100_{};
  std::array<Value, 300> common200_{};
  std::array<Value, 500>& common500_;
  bool hasCommon200_;
};

}  // namespace ncvm
