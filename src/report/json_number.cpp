#include "report/json_number.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstring>

namespace ncvm {

namespace {
// GCC's and Clang's 128-bit integer (one multiply instruction on x86-64).
__extension__ typedef unsigned __int128 Uint128;

// Two digits at a time, for the integer and fraction parts.
constexpr char kDigits2[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

inline void put2(char* p, uint32_t d) {
  std::memcpy(p, kDigits2 + d * 2, 2);
}

// The digits are written backwards from the end, which is known from the digit count, so
// they go straight to `out` (no scratch buffer and no memcpy call).
[[gnu::noinline]] char* writeLongUnsigned(char* out, uint64_t u) {
  // Line numbers and feeds are below 10^7: the digit count from comparisons, no loop.
  int digits = u < 1000 ? 3 : u < 10000 ? 4 : u < 100000 ? 5 : u < 1000000 ? 6 : 7;
  if (u >= 10000000)
    for (uint64_t t = u / 10000000; t != 0; t /= 10) ++digits;
  char* const end = out + digits;
  char* p = end;
  while (u >= 100) {
    p -= 2;
    put2(p, static_cast<uint32_t>(u % 100));
    u /= 100;
  }
  if (u >= 10) {
    p -= 2;
    put2(p, static_cast<uint32_t>(u));
  } else {
    *--p = static_cast<char>('0' + u);
  }
  return end;
}

// Most integer parts of a trace number are below 1000: up to three digits, inline.
inline char* writeUnsigned(char* out, uint64_t u) {
  if (u < 10) {
    *out = static_cast<char>('0' + u);
    return out + 1;
  }
  if (u < 100) {
    put2(out, static_cast<uint32_t>(u));
    return out + 2;
  }
  if (u < 1000) {  // X and Y often reach hundreds of millimetres
    const auto hundreds = static_cast<uint32_t>(u / 100);
    *out = static_cast<char>('0' + hundreds);
    put2(out + 1, static_cast<uint32_t>(u) - hundreds * 100);
    return out + 3;
  }
  return writeLongUnsigned(out, u);
}

// The digits of a fraction come from a 57-bit fixed-point value y ~ frac / 10^k: each pair
// is the integer part of y * 100 (jeaiii's method), a multiply and a shift instead of the
// divisions by 10^6, 10^4 and 100. y is rounded up: the error, below 2^-57 * frac, is
// multiplied by 100 a pair and stays below the next pair's unit to the last digit
// (tests/unit/json_number_test.cpp checks every digit position).
constexpr int kFixedBits = 57;
constexpr uint64_t kFixedMask = (uint64_t{1} << kFixedBits) - 1;

// The next pair of digits, as two bytes '0'..'9' (the first in the low byte).
inline uint64_t nextPair(uint64_t& y) {
  y = (y & kFixedMask) * 100;
  uint16_t pair;
  std::memcpy(&pair, kDigits2 + (y >> kFixedBits) * 2, 2);
  return pair;
}

// Stores the digits of `text` (little-endian: the first in the low byte, all eight bytes
// stored) and returns the end without the trailing zeros: the last digit that is not '0'
// is the highest byte of text ^ '0'... that is not zero (one must be).
inline char* putWithoutZeros(char* p, uint64_t text, uint64_t zeros) {
  std::memcpy(p, &text, 8);
  return p + 8 - (std::countl_zero(text ^ zeros) >> 3);
}

// ".ddd" for a fraction 0 < frac < 10^6 (6 digits) with its trailing zeros dropped: three
// pairs in one word, stored at once (two bytes more are stored past them).
inline char* writeFraction6(char* out, uint32_t frac) {
  *out = '.';
  // ceil(2^57 / 10^4): y >> 57 is frac / 10^4, the first pair.
  uint64_t y = frac * uint64_t{14411518807586};
  uint16_t first;
  std::memcpy(&first, kDigits2 + (y >> kFixedBits) * 2, 2);
  uint64_t text = first;
  text |= nextPair(y) << 16;
  text |= nextPair(y) << 32;
  return putWithoutZeros(out + 1, text, 0x0000303030303030ULL);
}

// The same for 0 < frac < 10^9 (9 digits: one, then four pairs), stored one by one: a
// length or a time seldom ends in zeros, so the loop over them is cheaper than a word's.
inline char* writeFraction9(char* out, uint32_t frac) {
  *out = '.';
  // ceil(2^57 / 10^8): y >> 57 is frac / 10^8, the first digit.
  uint64_t y = frac * uint64_t{1441151881};
  out[1] = static_cast<char>('0' + (y >> kFixedBits));
  for (int k = 2; k < 10; k += 2) {
    const uint64_t pair = nextPair(y);
    std::memcpy(out + k, &pair, 2);
  }
  char* end = out + 10;
  while (end[-1] == '0') --end;
  return end;
}
// fmt's shortest form, out of line: the fast paths need no stack frame for it.
[[gnu::noinline]] char* formatShortest(char* out, double v) {
  return fmt::format_to(out, FMT_COMPILE("{}"), v);
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
      const uint64_t whole = mag / 1000000;
      const auto frac = static_cast<uint32_t>(mag - whole * 1000000);
      out = writeUnsigned(out, whole);
      return frac != 0 ? writeFraction6(out, frac) : out;
    }
  }
  return formatShortest(out, v);
}

char* formatFixed(char* out, double v) {
  static_assert(kFixedDecimals == 9, "writeFraction9 writes nine decimals");
  // q = |v| * 10^9 rounded to the nearest integer (a tie upwards), exactly: |v| is m * 2^e
  // with m < 2^53 and, below 10^6 < 2^20, e <= -32, so m * 10^9 < 2^83 fits 128 bits and
  // the shift rounds it. (The same in doubles would be off by up to 0.2 near 10^6.) When v
  // is the double nearest to a decimal d of at most nine decimals, |v - d| * 10^9 is at
  // most 10^15 * 2^-53 < 1/2, so q is d * 10^9 and the text is d, the shortest form.
  const double a = std::fabs(v);
  if (!(a < 1e6) || (v == 0 && std::signbit(v))) return formatDouble(out, v);  // NaN too
  const auto bits = std::bit_cast<uint64_t>(a);
  const auto biased = static_cast<int>(bits >> 52);
  const uint64_t m = (bits & ((uint64_t{1} << 52) - 1)) | (uint64_t{1} << 52);
  // a = m / 2^(s + 32) with s >= 1. The low 32 bits of m * 10^9 cannot move a rounding
  // that adds a whole 2^(s-1) to the rest, so they go first (one 64-bit value remains).
  const int s = 1043 - biased;
  uint64_t q = 0;
  if (biased != 0 && s < 64) {  // else (subnormals too) a * 10^9 < 2^51 / 2^64: q = 0
    const auto high = static_cast<uint64_t>((static_cast<Uint128>(m) * 1000000000u) >> 32);
    q = (high + (uint64_t{1} << (s - 1))) >> s;
  }
  if (q == 0) {  // below 5 * 10^-10 in size: "0", without a sign
    *out = '0';
    return out + 1;
  }
  if (v < 0) *out++ = '-';
  const uint64_t whole = q / 1000000000;
  const auto frac = static_cast<uint32_t>(q - whole * 1000000000);
  out = writeUnsigned(out, whole);
  return frac != 0 ? writeFraction9(out, frac) : out;
}

}  // namespace ncvm
