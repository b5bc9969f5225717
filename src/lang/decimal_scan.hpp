#pragma once
// The common decimal number of a program ([+|-]digits[.digits], at most 19 digits), scanned in
// one pass and converted exactly. Shared by the general compiler (parseNumberText) and the
// plain-line fast path (fast_block.cpp), so both read every number to the same double.
#include <cstdint>

namespace ncvm {

struct DecimalText {
  double value = 0.0;
  const char* end = nullptr;  // first character after the number
  int digits = 0;             // digits before and after the point
  int intDigits = 0;          // integer digits, leading zeros not counted
  bool hasPoint = false;
};

// Scans the number at p. Returns false, with `out` unspecified, when this scan cannot give the
// exact result: more than 19 digits, a mantissa above 2^53, or a second decimal point (the
// caller's slow path reads those, or raises the alarm). Otherwise the value is
// mantissa / 10^(fraction digits): both are exact doubles (10^k is exact up to 10^22), so the
// one division is correctly rounded, the same double strtod and from_chars return (Clinger's
// fast path). A number without digits ("." or "-") reads as +0.0 with digits = 0.
//
// kBounded: stop at e. Otherwise e is ignored and the text must hold a character that is no
// part of a number (a '\n') at or after p: the plain-line fast path knows one is there and
// saves the bounds test per character.
template <bool kBounded>
inline bool scanDecimalIn(const char* p, const char* e, DecimalText& out) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,
                                      1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19};
  auto more = [e](const char* at) { return !kBounded || at < e; };
  // The digit value as an unsigned byte difference: no sign extension in the digit loops.
  auto value = [](const char* at) {
    return static_cast<unsigned>(static_cast<unsigned char>(*at)) - '0';
  };
  bool neg = false;
  if (more(p) && (*p == '+' || *p == '-')) neg = *p == '-', ++p;
  const char* const intBegin = p;
  uint64_t mantissa = 0;
  for (unsigned d; more(p) && (d = value(p)) < 10u; ++p) mantissa = mantissa * 10 + d;
  const char* const intEnd = p;
  const char* fracBegin = p;
  bool point = false;
  if (more(p) && *p == '.') {
    point = true;
    fracBegin = ++p;
    for (unsigned d; more(p) && (d = value(p)) < 10u; ++p) mantissa = mantissa * 10 + d;
  }
  const auto intLen = intEnd - intBegin, fracLen = p - fracBegin;
  // More than 19 digits may have wrapped the mantissa: the digit count is tested first.
  if (intLen + fracLen > 19 || mantissa > (uint64_t{1} << 53) || (point && more(p) && *p == '.'))
    return false;
  const char* lead = intBegin;
  while (lead < intEnd && *lead == '0') ++lead;
  out.end = p;
  out.digits = static_cast<int>(intLen + fracLen);
  out.intDigits = static_cast<int>(intEnd - lead);
  out.hasPoint = point;
  if (out.digits == 0) {
    out.value = 0.0;  // "X." reads as zero
  } else {
    double v = static_cast<double>(mantissa) / kPow10[fracLen];
    out.value = neg ? -v : v;
  }
  return true;
}

// The number at p, the text ending at e.
inline bool scanDecimal(const char* p, const char* e, DecimalText& out) {
  return scanDecimalIn<true>(p, e, out);
}

}  // namespace ncvm
