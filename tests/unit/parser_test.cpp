#include "lang/parser.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <string>
#include <vector>

using namespace ncvm;

namespace {
Program one(const char* text) {
  auto f = parseProgramText(text, 0, "t");
  EXPECT_EQ(f.programs.size(), 1u);
  return f.programs.front();
}
}  // namespace

TEST(Parser, ProgramHeaderAndWords) {
  Program p = one("%\nO0012 (TITLE)\nN10 G01 X1.5 Y-2 F100.\nM30\n%\n");
  EXPECT_EQ(p.number, 12);
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.blocks[0].n, 10);
  EXPECT_EQ(p.blocks[0].nWords, 4);
  const Word& x = p.words[p.blocks[0].firstWord + 1];
  EXPECT_EQ(x.letter, 'X');
  EXPECT_DOUBLE_EQ(x.value, 1.5);
  EXPECT_TRUE(x.flags & kHasPoint);
  const Word& y = p.words[p.blocks[0].firstWord + 2];
  EXPECT_FALSE(y.flags & kHasPoint);
  EXPECT_EQ(p.blocks[0].loc.line, 3u);
}

TEST(Parser, LowerCaseAddressIsAnErrorBlock) {
  Program p = one("O1\ng01 X1.\n");
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_EQ(p.blocks[0].kind, BlockKind::Error);
  EXPECT_EQ(p.errors[0].code, "PS0009");
}

TEST(Parser, DecimalPointForbiddenInP) {
  Program p = one("O1\nG04 P1.\n");
  EXPECT_EQ(p.errors.at(0).code, "PS0007");
}

TEST(Parser, NcAndMacroInOneBlock) {
  Program p = one("O1\nG01 X10 #1=5\n");
  EXPECT_EQ(p.errors.at(0).code, "PS0127");
}

TEST(Parser, WhileEndResolved) {
  Program p = one("O1\n#1=0\nWHILE[#1LT3]DO1\n#1=#1+1\nEND1\nM30\n");
  ASSERT_EQ(p.blocks[1].kind, BlockKind::While);
  EXPECT_EQ(p.ops(p.blocks[1]).target, 4);  // the block after END1
  EXPECT_EQ(p.ops(p.blocks[3]).target, 1);  // END jumps back to WHILE
  EXPECT_TRUE(p.structural.empty());
}

TEST(Parser, MissingEndIsStructural) {
  Program p = one("O1\nWHILE[1LT2]DO1\nM30\n");
  ASSERT_FALSE(p.structural.empty());
  EXPECT_EQ(p.structural[0].code, "PS0124");
}

TEST(Parser, TooManyBrackets) {
  Program p = one("O1\n#1=[[[[[[1]]]]]]\n");
  EXPECT_EQ(p.errors.at(0).code, "PS0118");
  Program ok = one("O1\n#1=[[[[[1]]]]]\n");
  EXPECT_TRUE(ok.errors.empty());
}

TEST(Parser, SemicolonEndsABlock) {
  Program p = one("O1;\nG00 X1.; G01 X2. F1.;\n");
  EXPECT_EQ(p.blocks.size(), 2u);
}

TEST(Parser, PercentWithProgramOnSameLine) {
  Program p = one("%O1200(TOKARKA)\nN10 G21\n%\n");
  EXPECT_EQ(p.number, 1200);
  EXPECT_EQ(p.blocks.size(), 1u);
}

// The one-pass number reader must give the very double std::from_chars gives, for the
// short numbers it computes itself and the long ones it hands to from_chars.
TEST(Parser, NumbersMatchFromChars) {
  std::vector<std::string> texts = {"0",
                                    "-0",
                                    "0.",
                                    ".5",
                                    "-.5",
                                    "5.",
                                    "+3.25",
                                    "0.1",
                                    "0.3",
                                    "-120.005",
                                    "99999.999",
                                    "0.000001",
                                    "123456789.",
                                    "1.7976931",
                                    "2.2250738585072014",
                                    "9.007199254740993",
                                    "123456789.123456789123",
                                    "0.1000000000000000055511151231257827",
                                    "000000123.4500000",
                                    "4.5035996273704975"};
  uint64_t k = 12345;
  for (int i = 0; i < 20000; ++i) {
    k = k * 6364136223846793005ULL + 1442695040888963407ULL;
    int ip = static_cast<int>((k >> 20) % 1000000);
    int fd = static_cast<int>((k >> 8) % 8);  // 0..7 fraction digits
    std::string frac = std::to_string((k >> 40) % 100000000).substr(0, static_cast<size_t>(fd));
    texts.push_back(((k & 1) ? "-" : "") + std::to_string(ip) + "." + frac);
  }
  std::string text = "O1\n";
  for (const auto& t : texts) text += "X" + t + "\n";
  Program p = one(text.c_str());
  ASSERT_EQ(p.words.size(), texts.size());
  for (size_t i = 0; i < texts.size(); ++i) {
    std::string t = texts[i];
    if (t[0] == '+') t.erase(0, 1);
    if (t.back() == '.') t += "0";
    double want = 0;
    std::from_chars(t.data(), t.data() + t.size(), want);
    EXPECT_EQ(std::bit_cast<uint64_t>(p.words[i].value), std::bit_cast<uint64_t>(want)) << texts[i];
  }
}

// Literal dimension words of 999.99999 and more are marked for the run-time digit check
// (PS0003); the layout stays at 16 bytes a word.
TEST(Parser, LongNumberFlag) {
  Program p = one("G01 X999.99 Y999.99999 Z-1000. F12345. R123456789 M12345\n");
  ASSERT_EQ(p.blocks.size(), 1u);
  const Word* w = p.words.data() + p.blocks[0].firstWord;
  EXPECT_FALSE(w[1].flags & kLongNumber);  // X999.99
  EXPECT_TRUE(w[2].flags & kLongNumber);   // Y999.99999
  EXPECT_TRUE(w[3].flags & kLongNumber);   // Z-1000.
  EXPECT_FALSE(w[4].flags & kLongNumber);  // F is not a dimension word
  EXPECT_TRUE(w[5].flags & kLongNumber);   // R123456789
  EXPECT_FALSE(w[6].flags & kLongNumber);  // M
  static_assert(sizeof(Word) == 16);       // the IR's memory per word
  static_assert(sizeof(Block) <= 36);      // and per block
}

// The compiler marks the blocks the executor's plain-motion path may read directly.
TEST(Parser, PlainBlockFlag) {
  auto flagged = [](const char* line) {
    Program p = one(line);
    EXPECT_EQ(p.blocks.size(), 1u) << line;
    return p.blocks.empty() ? false : (p.blocks[0].flags & kPlainBlock) != 0;
  };
  EXPECT_TRUE(flagged("X1. Y2. Z-3.\n"));
  EXPECT_TRUE(flagged("G01 X1.5 Y-2 F100.\n"));
  EXPECT_TRUE(flagged("N10 G02 X10. Y0 I5. J0\n"));
  EXPECT_TRUE(flagged("G3 X1. R5.\n"));
  EXPECT_FALSE(flagged("G01 X#1\n"));           // a variable
  EXPECT_FALSE(flagged("G01 X[1+2]\n"));        // an expression
  EXPECT_FALSE(flagged("G01 X1. X2.\n"));       // a letter twice
  EXPECT_FALSE(flagged("G01 G90 X1.\n"));       // two G codes
  EXPECT_FALSE(flagged("G04 X1.\n"));           // not G00-G03
  EXPECT_FALSE(flagged("G01 X1. M08\n"));       // an M code
  EXPECT_FALSE(flagged("G01 X1. ,R2.\n"));      // a corner word
  EXPECT_FALSE(flagged("G01 X1000. F100.\n"));  // long enough for the digit check
  EXPECT_FALSE(flagged("#1=2\n"));
}

namespace {
// The compiled code and constants of a program's expressions, for comparing two spellings.
std::vector<std::pair<int, int32_t>> codeOf(const Program& p) {
  std::vector<std::pair<int, int32_t>> out;
  for (const Instr& i : p.code)
    out.emplace_back(static_cast<int>(i.op) * 100 + static_cast<int>(i.fn),
                     i.op == Op::Const ? static_cast<int32_t>(p.consts[i.arg] * 1000) : i.arg);
  return out;
}
}  // namespace

// Issue 24.6: an operator run together with the function name after it is that operator.
TEST(Parser, OperatorRunTogetherWithAFunction) {
  const std::pair<const char*, const char*> same[] = {
      {"O1\nIF[ABS[#10]LEABS[#11]]GOTO5\nN5\n", "O1\nIF[ABS[#10] LE ABS[#11]]GOTO5\nN5\n"},
      {"O1\n#12=#10ANDABS[#11]\n", "O1\n#12=#10 AND ABS[#11]\n"},
      {"O1\nIF[1EQFIX[1.5]]GOTO5\nN5\n", "O1\nIF[1 EQ FIX[1.5]]GOTO5\nN5\n"},
      {"O1\nIF[3GTSQRT[4]]GOTO5\nN5\n", "O1\nIF[3 GT SQRT[4]]GOTO5\nN5\n"},
      {"O1\n#1=7MODABS[#2]\n", "O1\n#1=7 MOD ABS[#2]\n"},
      {"O1\n#1=4ORFIX[#2]\n", "O1\n#1=4 OR FIX[#2]\n"},
      {"O1\n#1=4XORROUND[#2]\n", "O1\n#1=4 XOR ROUND[#2]\n"},
  };
  for (const auto& [joined, spaced] : same) {
    SCOPED_TRACE(joined);
    Program a = one(joined), b = one(spaced);
    EXPECT_TRUE(a.errors.empty()) << (a.errors.empty() ? "" : a.errors[0].text);
    EXPECT_EQ(codeOf(a), codeOf(b));
  }
  // A run of letters that is an operator and something else is still an error.
  EXPECT_EQ(one("O1\n#1=4ORFOO[#2]\n").errors.size(), 1u);
  EXPECT_EQ(one("O1\n#1=4ANDX\n").errors.size(), 1u);
}

// Issue 24.7: spaces after ',' of ,R/,C and between a sign and its value.
TEST(Parser, SpacesAfterCommaAndSign) {
  Program p = one("O1\nG01 X50., R5.\nZ - [#26]\nZ- 5.\nX + 1.5\n");
  EXPECT_TRUE(p.errors.empty()) << (p.errors.empty() ? "" : p.errors[0].text);
  ASSERT_EQ(p.blocks.size(), 4u);
  const Word& r = p.words[p.blocks[0].firstWord + 2];
  EXPECT_EQ(r.letter, 'r');
  EXPECT_EQ(r.value, 5.0);
  EXPECT_EQ(p.words[p.blocks[2].firstWord].value, -5.0);
  EXPECT_EQ(p.words[p.blocks[3].firstWord].value, 1.5);
  EXPECT_EQ(p.words[p.blocks[1].firstWord].kind, WordKind::Expr);
}

// Issue 24.9: D H M S T in a G65/G66 block are signed arguments; elsewhere PS0006.
TEST(Parser, MinusOnIntegerLettersOnlyInMacroCalls) {
  EXPECT_TRUE(one("O1\nG65 P9 H-2. D-1 M-3. S-4 T-#1\n").errors.empty());
  EXPECT_TRUE(one("O1\nG66 P9 H-2.\n").errors.empty());
  for (const char* bad : {"O1\nM98 P9 H-2\n", "O1\nG65 P-9\n", "O1\nG65 P9 L-2\n", "O1\nS-100\n",
                          "O1\nG43 H-#1 Z5.\n"}) {
    Program p = one(bad);
    ASSERT_EQ(p.errors.size(), 1u) << bad;
    EXPECT_EQ(p.errors[0].code, "PS0006") << bad;
  }
}

// Issue 26.14: a number beyond a double's range is PS0003 where a shorter over-long one is.
TEST(Parser, NumbersBeyondADoubleAreTooManyDigits) {
  for (const std::string& digits : {std::string(20, '9'), std::string(308, '9'),
                                    std::string(309, '9'), std::string(400, '9')}) {
    Program c = one(("O1\n#1=" + digits + "\n").c_str());
    ASSERT_EQ(c.errors.size(), 1u);
    EXPECT_EQ(c.errors[0].code, "PS0003");
    EXPECT_EQ(c.errors[0].loc.col, 4u);
    Program w = one(("O1\nG00 X" + digits + "\n").c_str());
    ASSERT_EQ(w.errors.size(), 1u);
    EXPECT_EQ(w.errors[0].code, "PS0003");
    EXPECT_EQ(w.errors[0].loc.col, 5u);
  }
  Program f = one(("O1\n#1=." + std::string(400, '0') + "1\n").c_str());
  ASSERT_EQ(f.errors.size(), 1u);
  EXPECT_EQ(f.errors[0].code, "PS0003");
}
