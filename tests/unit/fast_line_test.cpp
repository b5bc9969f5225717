// The plain-line fast path (lang/fast_block.cpp) and the number scanner (lang/decimal_scan.hpp)
// must give exactly what the general compiler and strtod give: the same Program, field by
// field and bit for bit, for plain lines and for every line the fast path must refuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "lang/count_lines.hpp"
#include "lang/decimal_scan.hpp"
#include "lang/parser.hpp"
#include "program_compare.hpp"

using namespace ncvm;
using namespace ncvm::test;

namespace {

// Compiles `text` with the fast path on and off and checks the results are the same; returns
// how many lines the fast path took.
uint32_t expectSameBothWays(const std::string& text, ParseOptions options = {}) {
  options.fastLines = true;
  ParsedFile fast = parseProgramText(text, 3, "stem", options);
  options.fastLines = false;
  ParsedFile general = parseProgramText(text, 3, "stem", options);
  EXPECT_EQ(general.fastLines, 0u);
  EXPECT_EQ(fast.programs.size(), general.programs.size());
  for (size_t k = 0; k < std::min(fast.programs.size(), general.programs.size()); ++k)
    expectSamePrograms(fast.programs[k], general.programs[k], text);
  return fast.fastLines;
}

std::string digits(std::mt19937& rng, int n, bool leadingZeros) {
  std::string s;
  for (int k = 0; k < n; ++k) {
    char d = static_cast<char>('0' + rng() % 10);
    if (k == 0 && !leadingZeros && n > 1 && d == '0') d = '1';
    s += d;
  }
  return s;
}

// A random decimal: sign, 0-9 (sometimes up to 12) digits before and after the point, with and
// without the point, sometimes with leading zeros.
std::string randomNumber(std::mt19937& rng) {
  std::string s;
  switch (rng() % 4) {
    case 0:
      s += '-';
      break;
    case 1:
      if (rng() % 4 == 0) s += '+';
      break;
    default:
      break;
  }
  int maxDigits = rng() % 10 == 0 ? 13 : 10;
  int before = static_cast<int>(rng() % static_cast<unsigned>(maxDigits));
  int after = static_cast<int>(rng() % static_cast<unsigned>(maxDigits));
  s += digits(rng, before, rng() % 5 == 0);
  if (rng() % 5 != 0) s += '.' + digits(rng, after, true);
  if (s.empty() || s == "-" || s == "+") s += digits(rng, 1 + static_cast<int>(rng() % 3), false);
  return s;
}

std::string spaces(std::mt19937& rng) {
  switch (rng() % 8) {
    case 0:
      return "  ";
    case 1:
      return "\t";
    case 2:
      return " ";
    default:
      return "";
  }
}

// A line the fast path should take (if its numbers are short enough) ...
std::string plainLine(std::mt19937& rng) {
  static const char kLetters[] = "GGXXXYYYZZIJKRFABCUVWQEMSTHDLP";
  std::string s = spaces(rng);
  if (rng() % 3 == 0)
    s += "N" + digits(rng, 1 + static_cast<int>(rng() % 9), rng() % 4 == 0) + spaces(rng);
  int words = static_cast<int>(rng() % 6);
  for (int k = 0; k < words; ++k) {
    char letter = kLetters[rng() % (sizeof kLetters - 1)];
    s += letter;
    s += spaces(rng);
    if (letter == 'G' && rng() % 2)
      s += "0" + std::to_string(rng() % 4);
    else if (letter != 'G' && rng() % 3 == 0)
      s += std::to_string(rng() % 100);  // no point
    else
      s += randomNumber(rng);
    s += rng() % 4 == 0 ? "" : " ";
  }
  if (rng() % 10 == 0) s += '\r';
  return s;
}

// ... and lines it must refuse (comments, macros, alarms, odd bytes).
std::string otherLine(std::mt19937& rng) {
  static const char* kOther[] = {
      "G01 X1. (COMMENT) Y2.",
      "X1.;Y2.",
      "#1=2.5",
      "#100=#1+[2*3]",
      "X#1 Y-#2",
      "X[1+2] Y2.",
      "x1.",
      "G-1",
      "M3.5",
      "X1.2.3",
      "X. Y.",
      "X- Y1",
      "X-. Z.5",
      "/X1.",
      "/2 G01 X1.",
      "N1.5 X1.",
      "X1 O2",
      "X1 N2",
      "N",
      "NX1",
      "IF[#1GT2]GOTO10",
      "WHILE[#1LT3]DO1",
      "END1",
      "GOTO 20",
      "X123456789012345678901.",
      "X0.00000000000000000000001",
      "X12345678901",
      "X1234567890.5",
      "G65 P9010 A1. D5.0 M2.",
      "G65 P1 L2.",
      "G66.1 P1 S2.",
      "D5.0",
      "X1-2",
      "X1+2",
      "GX1.",
      "X1,Y2",
      ",C1.",
      "X1 ,R2.",
      "X1 <NAME>",
      "X\xc3\xa9",
      "X1 \x01",
      "DPRNT[X#1[53]]",
      "POPEN",
      "X1. Y2. X3.",
      "G04 X1.",
      "M30",
      "S1000 M03",
      "T0101",
      "G43 H1 Z5.",
      "%",
      "X99999.999",
      "X1000.",
      "X999.99999",
      "X-999.99999",
      "Y999.99998",
      "F99999.",
      "G1.0 X1.",
      "G4.0 X2.",
      "G00.5 X1",
      "+X1",
      "X+#1",
      "X 1. Y 2.",
      "N12345678 X1.",
      "N123456789 X1.",
      "N0 X1",
      "N00000001",
      "X00000000001.5",
      "X0000000001.5",
      "X0.",
      "X-0",
      "X-0.0",
      "Z+.5",
      "Z- 5.",
      "X - 1.5 Y+ 2",
      "Z - [#26]",
      "G1 X50., R5.",
      "G65 P9 H-2. D- 1 S-4",
      "H-2",
      "\xEF\xBB\xBFX1.",
  };
  return kOther[rng() % (sizeof kOther / sizeof kOther[0])];
}

}  // namespace

TEST(FastLines, SameProgramAsTheGeneralCompiler) {
  std::mt19937 rng(20261202);
  uint32_t taken = 0;
  for (int file = 0; file < 60; ++file) {
    std::string text;
    switch (file % 3) {
      case 0:
        text = "%\nO0001 (TEST)\n";
        break;
      case 1:
        text = "G90 G21\n";
        break;  // no header: the first line opens the program
      default:
        text = "O0002\n";
        break;
    }
    for (int line = 0; line < 400; ++line) {
      text += rng() % 4 == 0 ? otherLine(rng) : plainLine(rng);
      if (rng() % 50 == 0) text += "\n\n   ";  // blank lines
      text += '\n';
    }
    if (file % 4 == 0)
      text += "M30\n%\n";
    else if (file % 4 == 1)
      text += "X1. Y2.";  // last line without '\n'
    else if (file % 4 == 2)
      text += "O0003\nX1.\nWHILE[#1LT2]DO1\n#1=#1+1\nEND1\nGOTO 5\nN5 X2.\n";
    SCOPED_TRACE("file " + std::to_string(file));
    taken += expectSameBothWays(text);
    ParseOptions shortLines;
    shortLines.maxLineLength = 24;  // PS9004 on some of the lines
    taken += expectSameBothWays(text, shortLines);
  }
  EXPECT_GT(taken, 60u * 400u / 2);  // a good share of the lines are plain
}

TEST(FastLines, TakesPlainLinesAndRefusesOthers) {
  EXPECT_EQ(expectSameBothWays("O1\nN10 G01 X1.5 Y-2 F100.\n  G02 X1. Y2. I-3. J.5\n\nX1\n"), 4u);
  EXPECT_EQ(expectSameBothWays("O1\nX1. (C)\n#1=1\nG-1\nX.\nX1"), 0u);  // last line: no '\n'
  ParsedFile f = parseProgramText("O1\nG01 X1. Y2.\nG01 X1. X2.\nG04 X1.\nX1000.\n", 0, "t");
  ASSERT_EQ(f.fastLines, 4u);
  const Program& p = f.programs[0];
  EXPECT_TRUE(p.blocks[0].flags & kPlainBlock);
  EXPECT_FALSE(p.blocks[1].flags & kPlainBlock);  // X twice
  EXPECT_FALSE(p.blocks[2].flags & kPlainBlock);  // G04
  EXPECT_FALSE(p.blocks[3].flags & kPlainBlock);  // long number
  EXPECT_TRUE(p.words[p.blocks[3].firstWord].flags & kLongNumber);
}

TEST(FastLines, ControlFlowStillResolved) {
  // A program with loops is resolved; one without has no loop parents (nothing to resolve).
  ParsedFile f = parseProgramText("O1\nWHILE[#1LT2]DO1\nX1.\nEND1\nX2.\nO2\nX1.\nEND1\n", 0, "t");
  ASSERT_EQ(f.programs.size(), 2u);
  EXPECT_EQ(f.programs[0].loopParent(1), 0);
  EXPECT_EQ(f.programs[0].loopParent(0), -1);
  EXPECT_TRUE(parseProgramText("O1\nX1.\nX2.\n", 0, "t").programs[0].loopParents.empty());
  EXPECT_EQ(f.programs[0].macroOps[0].target, 3);
  ASSERT_EQ(f.programs[1].structural.size(), 1u);  // END without DO
}

// strtod on the same text, as the reference.
double reference(const std::string& s) {
  return std::strtod(s.c_str(), nullptr);
}

TEST(DecimalScan, MatchesStrtodBitForBit) {
  std::mt19937_64 rng(7);
  int fast = 0, slow = 0;
  for (int k = 0; k < 120000; ++k) {
    std::string s;
    if (rng() % 3 == 0) s += '-';
    int total = 1 + static_cast<int>(rng() % 20);                                // 1-20 digits
    int point = static_cast<int>(rng() % static_cast<uint64_t>(total + 2)) - 1;  // -1: none
    for (int d = 0; d < total; ++d) {
      if (d == point) s += '.';
      s += static_cast<char>('0' + rng() % 10);
    }
    if (point == total) s += '.';
    DecimalText out;
    std::string padded = s + "\n";
    if (scanDecimal(s.data(), s.data() + s.size(), out)) {
      ++fast;
      ASSERT_EQ(bits(out.value), bits(reference(s))) << s;
      ASSERT_EQ(out.end, s.data() + s.size()) << s;
      ASSERT_EQ(out.hasPoint, point >= 0) << s;
      DecimalText sentinel;  // the unbounded scan (fast path) reads the same
      ASSERT_TRUE(scanDecimalIn<false>(padded.data(), nullptr, sentinel)) << s;
      ASSERT_EQ(bits(sentinel.value), bits(out.value)) << s;
    } else {
      ++slow;
      ASSERT_FALSE(scanDecimalIn<false>(padded.data(), nullptr, out)) << s;
    }
    // The whole compiler (the scanner or its slow path) reads it as strtod does: as a
    // constant (up to 15 integer digits) and, through the fast path or not, as X.
    std::string unsignedText = s[0] == '-' ? s.substr(1) : s;
    if (unsignedText.find('.') == std::string::npos ? unsignedText.size() <= 15
                                                    : unsignedText.find('.') <= 15) {
      ParsedFile f = parseProgramText("O1\n#1=" + unsignedText + "\n", 0, "t");
      ASSERT_EQ(f.programs[0].consts.size(), 1u) << s;
      ASSERT_EQ(bits(f.programs[0].consts[0]), bits(reference(unsignedText))) << s;
    }
    ParsedFile x = parseProgramText("O1\nX" + s + "\n", 0, "t");
    const Program& p = x.programs[0];
    if (p.errors.empty()) {
      ASSERT_EQ(p.words.size(), 1u) << s;
      ASSERT_EQ(bits(p.words[0].value), bits(reference(s))) << s;
    }
  }
  EXPECT_GT(fast, 40000);
  EXPECT_GT(slow, 4000);  // the 20-digit ones
}

TEST(DecimalScan, EdgeCases) {
  DecimalText d;
  const char* t = "-.";
  ASSERT_TRUE(scanDecimal(t, t + 2, d));
  EXPECT_EQ(d.digits, 0);
  EXPECT_EQ(bits(d.value), bits(0.0));  // "X-." reads as +0, as before
  t = "-0";
  ASSERT_TRUE(scanDecimal(t, t + 2, d));
  EXPECT_EQ(bits(d.value), bits(-0.0));
  t = "9007199254740993";  // 2^53 + 1: not exact in the fast scan
  EXPECT_FALSE(scanDecimal(t, t + 16, d));
  t = "1.2.";
  EXPECT_FALSE(scanDecimal(t, t + 4, d));
  t = "000000123.5";
  ASSERT_TRUE(scanDecimal(t, t + 11, d));
  EXPECT_EQ(d.intDigits, 3);
  EXPECT_EQ(d.digits, 10);
}

TEST(CountNewlines, MatchesStdCount) {
  std::mt19937 rng(11);
  for (size_t size : {0u, 1u, 15u, 16u, 17u, 255u * 16u, 255u * 16u + 5u, 10000u, 70000u}) {
    std::string text(size, 'x');
    for (char& c : text) c = rng() % 3 == 0 ? '\n' : static_cast<char>(rng());
    EXPECT_EQ(countNewlines(text), static_cast<size_t>(std::count(text.begin(), text.end(), '\n')))
        << size;
  }
  EXPECT_EQ(countNewlines(std::string(5000, '\n')),
            5000u);  // every byte: the counters must not wrap
}
