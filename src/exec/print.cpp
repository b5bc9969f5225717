// DPRNT and BPRNT (fanuc-reference B.11). Output goes to a memory buffer that the caller
// writes out at the end, so an interrupted run never leaves half a file.
#include <fmt/format.h>

#include <cmath>

#include "exec/executor.hpp"

namespace ncvm {

namespace {
constexpr size_t kMaxPrinted = 64u << 20;

// #v[ab]: a integer digits, b fraction digits. With PRT (6001#1) = 0 the sign position and
// leading zeros print as spaces, so columns line up; with PRT = 1 they are left out. A
// value wider than a digits prints in full.
std::string formatDprnt(double v, int a, int b, bool prt) {
  double scale = std::pow(10.0, b);
  double rounded = std::round(std::fabs(v) * scale);
  // Past 18 digits the value no longer fits the control's integer output (and would
  // overflow the conversion below).
  if (!(rounded < 9.0e18)) throw AlarmError(AlarmId::IntegerOverflow, "DPRNT value too large");
  bool negative = v < 0 && rounded != 0;
  auto whole = static_cast<int64_t>(std::floor(rounded / scale));
  auto frac = static_cast<int64_t>(rounded - static_cast<double>(whole) * scale);
  std::string digits = std::to_string(whole);
  std::string out;
  if (!prt) {
    out += negative ? '-' : ' ';
    if (static_cast<int>(digits.size()) < a)
      out.append(static_cast<size_t>(a) - digits.size(), ' ');
  } else if (negative) {
    out += '-';
  }
  out += digits;
  if (b > 0) out += fmt::format(".{:0{}d}", frac, b);
  return out;
}
}  // namespace

void Executor::print(const Block& b) {
  const Program& p = *frames_.back().prog;
  const MacroOps& o = p.ops(b);
  bool prt = setup_.prt();
  // The line is built whole first: an alarm in one of its items prints nothing of it.
  std::string line;
  for (uint32_t k = 0; k < o.nPrint; ++k) {
    const PrintItem& item = p.prints[o.firstPrint + k];
    if (!item.isVar) {
      line += item.text;
      continue;
    }
    double v = eval(item.expr).asNumber();  // a vacant variable prints as 0
    if (o.printKind == PrintKind::Dprnt) {
      line += formatDprnt(v, item.intDigits, item.fracDigits, prt);
    } else {
      // BPRNT: value x 10^b as a 32-bit binary number, high byte first.
      double scaled = std::round(v * std::pow(10.0, item.fracDigits));
      if (std::fabs(scaled) > 2147483647.0)
        throw AlarmError(AlarmId::IntegerOverflow, "BPRNT value");
      auto u = static_cast<uint32_t>(static_cast<int32_t>(scaled));
      for (int s = 24; s >= 0; s -= 8) line += static_cast<char>((u >> s) & 0xFF);
    }
  }
  printed_ += line;
  printed_ += '\n';
  if (printed_.size() > kMaxPrinted)
    throw AlarmError(AlarmId::OutputError, "DPRNT output over 64 MiB");
}

}  // namespace ncvm
