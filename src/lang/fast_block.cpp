#include "lang/fast_block.hpp"

#include <array>
#include <cmath>

#include "lang/address_letters.hpp"
#include "lang/decimal_scan.hpp"

namespace ncvm {
namespace {

// The compiler's spaces (' ', '\t', '\r', '\f', '\v'): one table load instead of five compares a
// character.
constexpr std::array<bool, 256> kSpace = [] {
  std::array<bool, 256> t{};
  for (char c : {' ', '\t', '\r', '\f', '\v'}) t[static_cast<unsigned char>(c)] = true;
  return t;
}();
bool isSpace(char c) {
  return kSpace[static_cast<unsigned char>(c)];
}
bool isDigit(char c) {
  return static_cast<unsigned>(c - '0') < 10u;
}

// More words than this on one line is no CAM output: the general compiler takes the line
// (and its uint16 word count stays its business).
constexpr uint32_t kMaxWords = 64;

// What each byte allows as the letter of a word: one table load per word.
enum : uint8_t { kWordLetter = 1, kNoMinus = 2, kNoPoint = 4, kDimension = 8 };
constexpr std::array<uint8_t, 256> kLetterClass = [] {
  std::array<uint8_t, 256> t{};
  for (char c = 'A'; c <= 'Z'; ++c) {
    if (c == 'O' || c == 'N') continue;  // an alarm inside a block
    const uint32_t bit = 1u << (c - 'A');
    uint8_t k = kWordLetter;
    if (letters::kForbidsMinus & bit) k |= kNoMinus;
    if (letters::kForbidsPoint & bit) k |= kNoPoint;
    if (letters::kDimension & bit) k |= kDimension;
    t[static_cast<unsigned char>(c)] = k;
  }
  return t;
}();

}  // namespace

namespace {

// One line: the end of the line (its '\n') when it was compiled, nullptr when it is not plain.
// Inlined into the loop over a run of lines: no call, and no registers saved and restored, per
// line (about 30 instructions a line).
[[gnu::always_inline]] inline const char* fastLine(const char* b, uint32_t file, uint32_t line,
                                                   uint32_t maxLineLength, Program& p) {
  const char* q = b;
  while (isSpace(*q)) ++q;
  if (*q == '\n') return q;  // blank: the general compiler keeps nothing either
  auto col = [b](const char* at) { return static_cast<uint32_t>(at - b + 1); };

  Block blk;
  blk.loc = SourceLoc{file, line, col(q)};
  const size_t firstWord = p.words.size();
  blk.firstWord = static_cast<uint32_t>(firstWord);
  if (*q == 'N') {
    ++q;
    if (!isDigit(*q)) return nullptr;  // "N" without digits: an alarm
    uint32_t n = 0;
    const char* digits = q;
    while (isDigit(*q)) n = n * 10 + static_cast<uint32_t>(*q++ - '0');
    if (q - digits > 8 || *q == '.') return nullptr;  // alarms
    blk.n = static_cast<int32_t>(n);
  }

  // The words, with commitBlock's checks folded in. No letter the fast path accepts both
  // forbids a point and has one, so the G65/G66 argument rule never matters here.
  // The plain-block test (commitBlock's) is gathered as masks and decided once at the end.
  uint32_t seen = 0;      // letters so far
  uint32_t repeated = 0;  // letters seen twice
  uint8_t anyLong = 0;    // some word has kLongNumber
  bool plainG = true;     // every G is G00-G03
  uint32_t nWords = 0;
  while (true) {
    while (isSpace(*q)) ++q;
    if (*q == '\n') break;
    const char letter = *q;
    const uint8_t cls = kLetterClass[static_cast<unsigned char>(letter)];
    if (!(cls & kWordLetter) || nWords == kMaxWords) goto refuse;
    {
      const uint32_t at = col(q);
      ++q;
      while (isSpace(*q)) ++q;
      if (*q == '-' && (cls & kNoMinus)) goto refuse;
      DecimalText d;
      // No digits (a variable, an expression, "X." or nothing), more than 19 digits, and
      // everything the general compiler raises an alarm for go the general way.
      if (!scanDecimalIn<false>(q, nullptr, d) || d.digits == 0 || d.intDigits > 9 ||
          (d.hasPoint && (cls & kNoPoint)))
        goto refuse;
      q = d.end;
      Word w;
      w.letter = letter;
      w.col = static_cast<uint16_t>(at > 0xffff ? 0xffff : at);
      w.value = d.value;
      if (d.hasPoint) w.flags |= kHasPoint;
      // 999.99999 or more has at least three integer digits: most CAM numbers need no test.
      if ((cls & kDimension) && d.intDigits >= 3 && std::fabs(d.value) >= letters::kLongNumberFrom)
        w.flags |= kLongNumber;
      const uint32_t bit = 1u << (letter - 'A');
      repeated |= seen & bit;
      seen |= bit;
      anyLong |= w.flags & kLongNumber;
      if (letter == 'G') plainG = plainG && letters::plainWord(w);
      p.words.push_back(w);
      ++nWords;
    }
  }
  if (maxLineLength && static_cast<size_t>(q - b) > maxLineLength) goto refuse;  // PS9004

  blk.nWords = static_cast<uint16_t>(nWords);
  if (nWords > 0) {
    blk.kind = BlockKind::Nc;
    // Each letter once, only G X Y Z F I J K R, G as G00-G03, no long number: what
    // letters::plainWord asks of every word (all literals here) and commitBlock of a block.
    constexpr uint32_t kPlainLetters = letters::kPlainLetter | letters::mask("G");
    if (!repeated && !(seen & ~kPlainLetters) && !anyLong && plainG) blk.flags |= kPlainBlock;
  }
  if (blk.n >= 0) p.labels.emplace_back(blk.n, static_cast<uint32_t>(p.blocks.size()));
  p.blocks.push_back(blk);
  return q;

refuse:
  p.words.resize(firstWord);
  return nullptr;
}

}  // namespace

const char* compileFastLines(const char* b, const char* end, uint32_t file, uint32_t& line,
                             uint32_t maxLineLength, Program& p, uint32_t& compiled) {
  while (b < end) {
    const char* e = fastLine(b, file, line + 1, maxLineLength, p);
    if (!e) break;
    ++line;
    ++compiled;
    b = e + 1;
  }
  return b;
}

}  // namespace ncvm
