// The loader reads a file in pieces of whole lines through one reused buffer
// (lang/line_chunks.hpp): every piece size must compile to exactly the Program of the whole
// text, wherever the buffer cuts a line, and whatever the text's last line, CR LF ends, leader
// before a '%' or line longer than the buffer.
#include "lang/line_chunks.hpp"

#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "lang/parser.hpp"
#include "program_compare.hpp"

using namespace ncvm;
using namespace ncvm::test;

namespace {

// The pieces of `text` read through a buffer of `chunk` bytes.
std::vector<std::string> piecesOf(const std::string& text, size_t chunk, uint64_t size) {
  std::istringstream in(text);
  StreamChunks chunks(in, size, chunk);
  std::vector<std::string> out;
  for (std::string_view p = chunks.next(); !p.empty(); p = chunks.next()) out.emplace_back(p);
  return out;
}

ParsedFile parseChunked(const std::string& text, size_t chunk, const ParseOptions& options) {
  std::istringstream in(text);
  StreamChunks chunks(in, text.size(), chunk);
  return parseProgramChunks(chunks, 3, "stem", options);
}

// Every buffer size from one byte to the whole text (and then some) against the whole text.
void expectSameForEveryChunk(const std::string& text, ParseOptions options = {}) {
  const ParsedFile whole = parseProgramText(text, 3, "stem", options);
  for (size_t chunk = 1; chunk <= text.size() + 2; ++chunk) {
    SCOPED_TRACE("chunk " + std::to_string(chunk));
    const ParsedFile cut = parseChunked(text, chunk, options);
    EXPECT_EQ(cut.fastLines, whole.fastLines);
    ASSERT_EQ(cut.programs.size(), whole.programs.size());
    for (size_t k = 0; k < whole.programs.size(); ++k)
      expectSamePrograms(cut.programs[k], whole.programs[k], text);
    if (::testing::Test::HasFailure()) return;  // one failing size tells enough
  }
}

}  // namespace

TEST(LineChunks, PiecesAreWholeLinesThatMakeTheText) {
  const std::vector<std::string> texts = {"",
                                          "\n",
                                          "X1.",
                                          "X1.\n",
                                          "\n\n\nX1.\r\nY2.\r\n",
                                          "G01 X1. Y2.\nX3.\nlast line without newline",
                                          std::string(100, 'X') + "\nY\n" + std::string(40, 'Z')};
  for (const std::string& text : texts)
    for (size_t chunk = 1; chunk <= text.size() + 2; ++chunk) {
      SCOPED_TRACE("text '" + text + "' chunk " + std::to_string(chunk));
      std::string joined;
      const auto pieces = piecesOf(text, chunk, text.size());
      for (size_t k = 0; k < pieces.size(); ++k) {
        EXPECT_FALSE(pieces[k].empty());
        // Each piece ends a line; only the last may end without '\n'.
        if (k + 1 < pieces.size()) {
          EXPECT_EQ(pieces[k].back(), '\n');
        }
        joined += pieces[k];
      }
      EXPECT_EQ(joined, text);
    }
}

TEST(LineChunks, ReadsNoMoreThanTheSizeItWasGiven) {
  // The file's size when it was opened: bytes appended since are not read...
  const auto grown = piecesOf("X1.\nY2.\nZ3.\n", 3, 8);
  ASSERT_EQ(grown.size(), 2u);
  EXPECT_EQ(grown[0] + grown[1], "X1.\nY2.\n");
  // ... and a file that shrank is read as far as it goes.
  const auto shrunk = piecesOf("X1.\nY2", 4, 100);
  ASSERT_EQ(shrunk.size(), 2u);
  EXPECT_EQ(shrunk[1], "Y2");
}

TEST(LineChunks, LineHintCountsASmallTextAndScalesALargeOne) {
  std::istringstream small("X1.\nY2.\nZ3.");
  StreamChunks whole(small, 11, 64);
  whole.next();
  EXPECT_EQ(whole.lineHint(), 3u);  // as the whole text's newlines + 1
  std::string text;
  for (int k = 0; k < 1000; ++k) text += "X1.234 Y5.678\n";
  std::istringstream big(text);
  StreamChunks scaled(big, text.size(), 1400);
  scaled.next();
  EXPECT_GE(scaled.lineHint(), 1000u);
  EXPECT_LE(scaled.lineHint(), 1100u);
}

// Lines cut at every offset: plain lines (the fast path), lines the general compiler takes,
// CR LF, blank lines, a last line without '\n'.
TEST(LineChunks, EveryBufferSizeCompilesTheSameProgram) {
  expectSameForEveryChunk(
      "%\nO0001 (T)\nG90 G21 G01 F100.\nN10 X1.25 Y-2.5\nX3. (C) Y4.\n\n"
      "#1=2\nX#1\nWHILE[#1LT4]DO1\n#1=#1+1\nEND1\nGOTO 20\nN20 X5.\r\nY6.\r\n"
      "M30\n%\n");
  expectSameForEveryChunk("G90 G21\nG01 X1. Y2. F300.\nX3.\n  \nY4.");  // no '%', no final '\n'
  expectSameForEveryChunk("O1\r\nG01 X1. F100.\r\nX2.\r\nM30\r\n");
  expectSameForEveryChunk("%O1200(TITLE)\nX1.\nX2.;Y3.%\nO1300\nX4.\n");
}

// Text before the first '%' is leader: it may compile to anything (programs, alarms) before
// the piece with the '%' is read, and must all go.
TEST(LineChunks, LeaderBeforeALaterPercentIsDropped) {
  std::string leader = "O0005 LEADER TEXT\nG01 X1. Y2.\nWHILE[1]DO1\nN7 X3.\n(NOTE)\nX1 O2\n";
  for (int k = 0; k < 5; ++k) leader += "G01 X" + std::to_string(k) + ".5 Y2.\n";
  expectSameForEveryChunk(leader + "%\nO0001\nG01 X1. F100.\nX2.\nM30\n%\n");
  expectSameForEveryChunk(leader + "X1. (50%)\nO0001\nX2.\n");  // the '%' inside a comment
  expectSameForEveryChunk(leader + "LINE%O0002\nX9.\n");
}

// The tape marks (issue 24.1), comments before the O number (24.2) and a byte-order mark
// (26.13): every piece size compiles them as the whole text does.
TEST(LineChunks, TapeMarksLeaderCommentsAndByteOrderMark) {
  for (const std::string& text :
       {std::string("O0001\nG01 X1. F100.\nX2.\nM30\n%\n"),     // only a trailing '%'
        std::string("O0001\nX1.\nM30\n%\x1a"),                  // and a DOS EOF after it
        std::string("%\nO0001\nX1.\nM30\n%\nO0002\nX3.\n%\n"),  // text after the closing '%'
        std::string("%\n(PART NAME)\n(REV B)\nO0001 (T)\nX1.\nM30\n%\n"),
        std::string("% (PART NAME)\nO0001\nX1.\n%\n"),
        std::string("(PART)\nO0001\nX1.\n(NOT A LEADER)\nO0002\nX2.\n"),
        std::string("O0001\n(STEPOVER 50%)\nX1.\n"), std::string("\xEF\xBB\xBFO0001\nX1. Y2.\n"),
        std::string(""), std::string("%\n"), std::string("\n\n%\n\n"),
        std::string("(ONLY A COMMENT)\n"), std::string("O0001\nX1.\n%\n(END)\n"),
        std::string("(A)\n%\n(B)\n")}) {
    SCOPED_TRACE(text);
    expectSameForEveryChunk(text);
  }
}

TEST(LineChunks, TapeMarksDecideWhatIsTheProgram) {
  auto parse = [](const std::string& text) { return parseProgramText(text, 3, "stem"); };
  // Only a trailing '%' (and a DOS EOF after it): the text before it is the program.
  for (const char* text : {"O0001\nX1.\nM30\n%\n", "O0001\nX1.\nM30\n%\x1a", "X1.\n%\n\x1a\n"}) {
    ParsedFile f = parse(text);
    ASSERT_EQ(f.programs.size(), 1u) << text;
    EXPECT_TRUE(f.programs[0].errors.empty()) << text;
    EXPECT_EQ(f.programs[0].blocks.size(), text[0] == 'O' ? 2u : 1u) << text;
  }
  // A comment after the file's only '%' does not make it a leading one.
  ParsedFile commented = parse("O0001\nX1.\nM30\n%\n(END)\n");
  ASSERT_EQ(commented.programs.size(), 1u);
  EXPECT_EQ(commented.programs[0].number, 1);
  // With a leading '%', what comes before it is leader, whatever follows.
  ParsedFile led = parse("LEADER X1.\n%\nO0002\nX1.\n");
  ASSERT_EQ(led.programs.size(), 1u);
  EXPECT_EQ(led.programs[0].number, 2);
  // The closing '%' ends the text; the first line after it holding something is noted.
  ParsedFile closed = parse("%\nO0001\nX1.\n%\n\n(LATER)\nO0002\n");
  ASSERT_EQ(closed.programs.size(), 1u);
  EXPECT_EQ(closed.unreadLine, 6u);
  EXPECT_EQ(parse("%\nO0001\nX1.\n%\x1a\n\x1a").unreadLine, 0u);
  // Comments before the O number are no program of their own; after it they are blocks.
  ParsedFile titled = parse("%\n(PART NAME)\nO0001\n(FIRST BLOCK)\nX1.\n%\n");
  ASSERT_EQ(titled.programs.size(), 1u);
  EXPECT_EQ(titled.programs[0].number, 1);
  EXPECT_EQ(titled.programs[0].blocks.size(), 2u);
  // A header-less program that starts with a comment and then has blocks keeps both.
  ParsedFile headerless = parse("(PART)\nX1.\nO0002\nX2.\n");
  ASSERT_EQ(headerless.programs.size(), 2u);
  EXPECT_EQ(headerless.programs[0].number, -1);
  EXPECT_EQ(headerless.programs[0].blocks.size(), 2u);
  // No program text: one program whose only block is PS9008, at the '%' line or line 1.
  const std::pair<const char*, uint32_t> none[] = {{"", 1},
                                                   {"%\n", 1},
                                                   {"\n\n%\n", 3},
                                                   {"(ONLY A COMMENT)\n", 1},
                                                   {"\xEF\xBB\xBF", 1},
                                                   {"(A)\n%\n", 2},
                                                   {"(A)\n%\n(B)\n", 2}};
  for (const auto& [text, line] : none) {
    ParsedFile f = parse(text);
    ASSERT_EQ(f.programs.size(), 1u) << text;
    ASSERT_EQ(f.programs[0].errors.size(), 1u) << text;
    EXPECT_EQ(f.programs[0].errors[0].code, "PS9008") << text;
    EXPECT_EQ(f.programs[0].errors[0].loc.line, line) << text;
  }
  // The byte-order mark is skipped: columns count from after it.
  ParsedFile bom = parse("\xEF\xBB\xBFO0001\nX1. Q\n");
  ASSERT_EQ(bom.programs.size(), 1u);
  EXPECT_EQ(bom.programs[0].number, 1);
  ASSERT_EQ(bom.programs[0].errors.size(), 1u);
  EXPECT_EQ(bom.programs[0].errors[0].loc.col, 5u);
}

// A text that is one long line: the buffer grows to hold it; with a line length limit it
// becomes PS9004 Error blocks as in the whole text.
TEST(LineChunks, OneHugeLineAndTheLineLengthAlarm) {
  std::string line = "O1\nG01";
  for (int k = 0; k < 300; ++k) line += " X" + std::to_string(k) + ".5";
  std::string split = "O1\n";
  for (int k = 0; k < 60; ++k) split += "X" + std::to_string(k) + ".;";
  ParseOptions limit;
  limit.maxLineLength = 64;
  for (const std::string& text : {line, line + "\n", split + "\nX1.\n"}) {
    expectSameForEveryChunk(text);
    expectSameForEveryChunk(text, limit);
  }
  const ParsedFile f = parseChunked(line + "\n", 7, limit);
  ASSERT_EQ(f.programs.size(), 1u);
  ASSERT_EQ(f.programs[0].errors.size(), 1u);
  EXPECT_EQ(f.programs[0].errors[0].code, "PS9004");
}

// A generated CAM-like program with random plain and other lines, against a few buffer sizes.
TEST(LineChunks, LongProgramAtSeveralBufferSizes) {
  std::mt19937 rng(6);
  std::string text = "%\nO0001\nG90 G21 G17\n";
  for (int k = 0; k < 3000; ++k) {
    text += (rng() % 7 == 0 ? "G02 X" : "G01 X") + std::to_string(rng() % 1000) + "." +
            std::to_string(rng() % 1000) + " Y-" + std::to_string(rng() % 100) + ".5";
    if (rng() % 11 == 0) text += " (C" + std::to_string(k) + ")";
    if (rng() % 13 == 0) text += "\r";
    text += "\n";
  }
  text += "M30\n%\n";
  const ParsedFile whole = parseProgramText(text, 3, "stem");
  for (size_t chunk : {size_t{5}, size_t{64}, size_t{1000}, size_t{4096}, size_t{65536}}) {
    SCOPED_TRACE("chunk " + std::to_string(chunk));
    const ParsedFile cut = parseChunked(text, chunk, {});
    EXPECT_EQ(cut.fastLines, whole.fastLines);
    ASSERT_EQ(cut.programs.size(), 1u);
    expectSamePrograms(cut.programs[0], whole.programs[0], "long program");
  }
}

// Random texts of tape marks, comments, headers, filler bytes and blocks: every piece size
// compiles them as the whole text does (the tape state carries across pieces).
TEST(LineChunks, RandomTapeTextsCompileAlikeInPieces) {
  const char* const kParts[] = {"%",     "%\n",    "\n",    "(T)",    "(50%)",        "O0001",
                                "O0002", "X1.",    " ",     "\x1a",   "\r\n",         "#1=2",
                                "N5",    ";",      "<SUB>", "G01 Y2", "\xEF\xBB\xBF", "(",
                                ")",     "%O0003", "M30"};
  std::mt19937 rng(2426);
  for (int k = 0; k < 300; ++k) {
    std::string text;
    const int n = 1 + static_cast<int>(rng() % 14);
    for (int p = 0; p < n; ++p) text += kParts[rng() % (sizeof kParts / sizeof kParts[0])];
    SCOPED_TRACE(text);
    expectSameForEveryChunk(text);
    if (::testing::Test::HasFailure()) return;
  }
}
