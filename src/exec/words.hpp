#pragma once
// The evaluated words of one NC block: values after variables and expressions, with
// whether each had a decimal point. Lives on the stack; no allocation per block.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/alarm.hpp"

namespace ncvm {

struct Words {
  uint32_t present = 0;  // bit per letter A..Z
  uint32_t point = 0;    // value had a decimal point or came from a variable/expression
  uint32_t twice = 0;    // letters given more than once (the last one counts)
  std::array<double, 26> val;
  std::array<uint16_t, 26> col;
  int ng = 0;
  std::array<int16_t, 12> g;  // G codes x10 in block order
  std::array<uint16_t, 12> gcol;
  int nm = 0;
  std::array<int32_t, 3> m;
  int32_t nameIdx = -1;         // <name> word: index into Program::strings
  int32_t subCallProgram = -1;  // M code subprogram call (parameters 6071-6079)
  bool tCall = false;           // T code calls O9000 (parameter 6001#5) after the block
  // ,C (chamfer) and ,R (corner rounding), the 30i comma words.
  bool hasCommaC = false, hasCommaR = false, commaPoint = false;
  double commaValue = 0;
  uint16_t commaCol = 0;
  bool hasCorner() const { return hasCommaC || hasCommaR; }
  // ,A: the angle of a lathe direct drawing dimension (degrees from +Z, counter-clockwise).
  bool hasCommaA = false;
  double commaAngle = 0;
  uint16_t commaACol = 0;
  struct Arg {
    char letter;
    double value;
    bool point;
  };
  int nArgs = 0;
  std::array<Arg, 48> args;  // macro arguments in block order (type II needs the order)

  static constexpr uint32_t bit(char letter) { return 1u << (letter - 'A'); }
  bool has(char letter) const { return present & bit(letter); }
  bool hasPoint(char letter) const { return point & bit(letter); }
  double value(char letter) const { return val[static_cast<size_t>(letter - 'A')]; }
  bool hasM(int32_t code) const {
    for (int k = 0; k < nm; ++k)
      if (m[static_cast<size_t>(k)] == code) return true;
    return false;
  }
  // P and Q of an M98/M99 block are the call's (program, sequence number), not data of the
  // canned cycle that is active around the call.
  bool pqBelongToCall() const { return hasM(98) || hasM(99); }
  bool any(const char* letters) const {
    for (const char* c = letters; *c; ++c)
      if (has(*c)) return true;
    return false;
  }
};

// A word that must be a whole number (P of M98, L): rounded; beyond eight digits, or not
// finite, the integer-overflow alarm naming the letter.
inline int32_t integerWord(const Words& w, char letter) {
  double v = w.value(letter);
  if (!std::isfinite(v) || std::fabs(v) > 99999999.0)
    throw AlarmError(AlarmId::IntegerOverflow, std::string(1, letter));
  return static_cast<int32_t>(std::llround(v));
}

}  // namespace ncvm
