#pragma once
// What each address letter allows, shared by the general compiler (parser.cpp) and the
// plain-line fast path (fast_block.cpp) so the two can never disagree. Letter sets are bit
// masks (bit 0 = 'A'): one test per word, no strchr.
#include <cstdint>

#include "lang/ir.hpp"

namespace ncvm::letters {

constexpr uint32_t mask(const char* letters) {
  uint32_t m = 0;
  for (; *letters; ++letters) m |= 1u << (*letters - 'A');
  return m;
}
inline bool in(char letter, uint32_t m) {
  return letter >= 'A' && letter <= 'Z' && ((m >> (letter - 'A')) & 1u);
}

// Addresses that take no decimal point (fanuc-reference A.2). G is checked against the code
// table by the executor, since G54.1 and friends are legal.
constexpr uint32_t kForbidsPoint = mask("NOPMSTHDL");
// Addresses that take no sign.
constexpr uint32_t kForbidsMinus = mask("GMNOSTLHDP");
// Addresses whose values are lengths or angles, counted in least increments.
constexpr uint32_t kDimension = mask("XYZUVWABCIJKRQ");
// The letters a plain motion block may hold (besides G00-G03).
constexpr uint32_t kPlainLetter = mask("XYZFIJKR");

inline bool forbidsPoint(char letter) {
  return in(letter, kForbidsPoint);
}
inline bool forbidsMinus(char letter) {
  return in(letter, kForbidsMinus);
}
inline bool isDimension(char letter) {
  return in(letter, kDimension);
}

// A literal dimension word of 999.99999 or more may have more than 8 digits in increments
// (IS-C inch, 10^5 per inch): the executor checks it once the unit is known (kLongNumber).
constexpr double kLongNumberFrom = 999.99999;

// The words a plain motion block may hold (Executor::plainMotion): no other letter, no
// variable or expression, G only as G00-G03, nothing for the digit check.
inline bool plainWord(const Word& w) {
  if (w.kind != WordKind::Literal || (w.flags & kLongNumber)) return false;
  if (w.letter == 'G') return w.value == 0 || w.value == 1 || w.value == 2 || w.value == 3;
  return in(w.letter, kPlainLetter);
}

}  // namespace ncvm::letters
