#pragma once
// Least input increments and the integer position unit.
//
// NC positions are int64 nanometres (or micro-degrees on rotary axes). Every increment of
// IS-A/B/C in mm and inch is a whole number of nanometres (0.0001 in = 2540 nm), so
// rounding a programmed value to the control's increment and converting it is exact, and
// long chains of G91 moves accumulate no error, as on the control.
#include <cmath>
#include <cstdint>

namespace ncvm {

enum class InputUnit : uint8_t { Mm, Inch };
enum class IncrementSystem : uint8_t { IsA, IsB, IsC };

constexpr int64_t kNmPerMm = 1'000'000;
constexpr int64_t kNmPerInch = 25'400'000;

// Least input increment in units of the program (mm, inch or degree).
inline double leastIncrement(IncrementSystem is, InputUnit u) {
  double mm = is == IncrementSystem::IsA ? 0.01 : is == IncrementSystem::IsB ? 0.001 : 0.0001;
  return u == InputUnit::Inch ? mm / 10.0 : mm;
}

// Increments per program unit (1000 for IS-B mm).
inline int64_t incrementsPerUnit(IncrementSystem is, InputUnit u) {
  int64_t n = is == IncrementSystem::IsA ? 100 : is == IncrementSystem::IsB ? 1000 : 10000;
  return u == InputUnit::Inch ? n * 10 : n;
}

// std::llround (halves away from zero) without the libm call: the truncated value and the
// exact remainder x - trunc(x) decide. Values out of the int64 range (and NaN) go to llround.
inline int64_t roundHalfAway(double x) {
  if (!(std::fabs(x) < 9.0e18)) return static_cast<int64_t>(std::llround(x));
  auto i = static_cast<int64_t>(x);
  double rest = x - static_cast<double>(i);
  if (rest >= 0.5)
    ++i;
  else if (rest <= -0.5)
    --i;
  return i;
}

// Rounds a value in program units to a whole number of increments, halves away from zero.
// The nudge absorbs binary representation error (1.0005 is stored as 1.000499999...), so a
// value written with a decimal point rounds as its decimal text does.
inline int64_t roundToIncrements(double v, int64_t perUnit) {
  double x = v * static_cast<double>(perUnit);
  double nudge = 1e-9 * (1.0 + std::fabs(x) * 1e-6);
  return roundHalfAway(x + (x >= 0 ? nudge : -nudge));
}

// Nanometres (or micro-degrees) per increment.
inline int64_t nmPerIncrement(IncrementSystem is, InputUnit u, bool rotary) {
  int64_t perUnit = incrementsPerUnit(is, u);
  if (rotary) return 1'000'000 / incrementsPerUnit(is, InputUnit::Mm);
  return (u == InputUnit::Inch ? kNmPerInch : kNmPerMm) / perUnit;
}

}  // namespace ncvm
