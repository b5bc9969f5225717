#include "report/json_number.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <cmath>
#include <cstring>

namespace ncvm {

namespace {
// Two digits at a time, for the integer and fraction parts.
constexpr char kDigits2[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// The digits are written backwards from the end, which is known from the digit count, so
// they go straight to `out` (no scratch buffer and no memcpy call).
char* writeUnsigned(char* out, uint64_t u) {
  int digits = 1;
  for (uint64_t t = u; t >= 10; t /= 10) ++digits;
  char* const end = out + digits;
  char* p = end;
  while (u >= 100) {
    const char* d = kDigits2 + (u % 100) * 2;
    u /= 100;
    *--p = d[1];
    *--p = d[0];
  }
  if (u >= 10) {
    const char* d = kDigits2 + u * 2;
    *--p = d[1];
    *--p = d[0];
  } else {
    *--p = static_cast<char>('0' + u);
  }
  return end;
}
}  // namespace

char* formatInt(char* out, int64_t v) {
  if (v < 0) {
    *out++ = '-';
    return writeUnsigned(out, ~static_cast<uint64_t>(v) + 1);
  }
  return writeUnsigned(out, static_cast<uint64_t>(v));
}

char* formatDouble(char* out, double v) {
  // The fast path: v is the double nearest to d = n * 10^-6 with 100 <= |n| < 10^15. A
  // decimal of at most 15 significant digits survives the trip through a double, so no
  // other decimal of 15 digits or fewer reads back as v: the shortest form is d itself.
  // fmt writes it in fixed notation, because 10^-4 <= |d| < 10^16, with trailing zeros
  // and a bare point dropped ("12.5", "-3", "0.001"). Zero is "0" ("-0" takes the slow path).
  if (std::fabs(v) < 1e9) {
    double scaled = v * 1e6;
    // Any rounding to a nearby integer will do: the test below checks that n / 10^6 is v.
    auto n = static_cast<int64_t>(scaled < 0 ? scaled - 0.5 : scaled + 0.5);
    uint64_t mag = n < 0 ? ~static_cast<uint64_t>(n) + 1 : static_cast<uint64_t>(n);
    if (static_cast<double>(n) / 1e6 == v && (mag >= 100 || (n == 0 && !std::signbit(v)))) {
      if (n < 0) *out++ = '-';
      out = writeUnsigned(out, mag / 1000000);
      auto frac = static_cast<unsigned>(mag % 1000000);
      if (frac != 0) {
        int digits = 6;
        while (frac % 10 == 0) frac /= 10, --digits;
        *out++ = '.';
        char* end = out + digits;
        for (char* p = end; p != out; frac /= 10) *--p = static_cast<char>('0' + frac % 10);
        out = end;
      }
      return out;
    }
  }
  return fmt::format_to(out, FMT_COMPILE("{}"), v);
}

}  // namespace ncvm
