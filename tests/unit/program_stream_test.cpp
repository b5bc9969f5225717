// A large plain program is compiled while it runs (lang/program_stream.hpp): the scan that
// decides it, the program holding one piece at a time, the whole program compiled when a
// block needs another one (M99, a lathe cycle's P/Q, a return to N, a second entry), the
// file changed meanwhile (PS9007), a second run, and the top blocks' N read back from the
// file. Every run is compared with the same program compiled whole; tests/golden_runner.cpp
// does the same for every golden case.
#include "lang/program_stream.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "app/session.hpp"
#include "lang/stream_scan.hpp"
#include "machine/setup.hpp"
#include "report/trace_writer.hpp"

using namespace ncvm;
namespace fs = std::filesystem;

namespace {

bool scans(const std::string& first, const std::string& rest) {
  StreamScan s;
  s.piece(first);
  s.piece(rest);
  return s.streamable();
}

std::string plainLines(int n, int start = 0, bool numbered = false) {
  std::string s;
  for (int k = start; k < start + n; ++k) {
    if (numbered) s += "N" + std::to_string(k + 1) + " ";
    s += "X" + std::to_string(k % 97) + "." + std::to_string(k % 1000) + " Y" +
         std::to_string(k % 13) + ".5 Z-" + std::to_string(k % 3) + ".25\n";
  }
  return s;
}

fs::path writeFile(const std::string& name, const std::string& text) {
  fs::path p =
      fs::temp_directory_path() / ("ncvm_stream_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

struct Outcome {
  std::string text;  // trace, state and printed output
  bool streamed = false;
  size_t blocksHeld = 0;  // the main program's blocks after the run
};

Outcome run(const fs::path& file, bool stream, const ncvm::Setup& setup = defaultSetup(),
            const fs::path& lib = {}, size_t piece = 200) {
  Session s(setup);
  if (stream) s.streamMainProgram({0, piece});
  s.addProgramFile(file.string());
  if (!lib.empty()) s.addLibrary(lib.string());
  Outcome o;
  o.streamed = s.main()->stream != nullptr;
  TraceWriter writer(s.files(), nullptr, 1ull << 30, s.setup().reportedAxes());
  Session::Result r = s.run(&writer);
  o.text = writer.buffer() + "\n" + r.state.dump(1) + "\n" + r.printed;
  o.blocksHeld = s.main()->blocks.size();
  return o;
}

const char* kHead =
    "%\nO0001 (STREAM TEST)\nG90 G21 G17 G40 G49 G80 G54\nG00 X0. Y0. Z5.\nG01 Z0. F3000.\n";

}  // namespace

TEST(StreamScan, AcceptsPlainBlocksAndComments) {
  EXPECT_TRUE(scans(kHead, plainLines(50)));
  EXPECT_TRUE(scans(kHead, "N10 G02 X1. Y2. I3. J4.\r\n(WHILE [#1] IS ONLY A COMMENT)\nM30\n%\n"));
  EXPECT_TRUE(scans(kHead, "X+1.\tY2.\n"));
}

TEST(StreamScan, RefusesWhatNeedsTheWholeProgram) {
  for (const char* rest :
       {"G01 X#1\n", "#1=2\n", "WHILE[#1LT2]DO1\n", "END1\n", "GOTO10\n", "IF[#1EQ1]GOTO5\n",
        "X[1+2]\n", "G01 X1. ,C2.\n", "X1.;Y2.\n", "/X1.\n", "O0002\n", "M98 <SUB>\n", "DPRNT[X]\n",
        "x1.\n", "X1.)\n", "X\xC3\xA9\n", "GX1.\n"}) {
    SCOPED_TRACE(rest);
    EXPECT_FALSE(scans(kHead, plainLines(40) + rest));
  }
  // A '%' after the first piece when the first had none: what came before it was leader.
  EXPECT_FALSE(scans("G90\n", plainLines(3) + "%\n"));
  EXPECT_TRUE(scans("%\nG90\n", plainLines(3) + "%\n"));
  // The header: one O, at the start of the first block.
  EXPECT_TRUE(scans("%\nO1234\n", "X1.\n"));
  EXPECT_FALSE(scans("%\nG90\nO1234\n", "X1.\n"));
  EXPECT_FALSE(scans("%\n(C)O1234\n", "X1.\n"));
}

TEST(StreamScan, SkipsAByteOrderMark) {
  // The compiler skips a UTF-8 BOM at the start of the file (issue 26.13); so does the scan.
  EXPECT_TRUE(scans(std::string("\xEF\xBB\xBF") + kHead, plainLines(10)));
  EXPECT_FALSE(scans(std::string(kHead) + "\xEF\xBB\xBF", plainLines(10)));  // only at the start
}

TEST(StreamScan, CountsLines) {
  StreamScan s;
  s.piece(kHead);
  s.piece(plainLines(1000));
  s.piece("(A COMMENT\n(ANOTHER)\n");
  EXPECT_EQ(s.lines(), 5u + 1000u + 2u);
}

TEST(ProgramStream, APlainProgramRunsPieceByPieceAsItRunsWhole) {
  const fs::path f =
      writeFile("plain.nc", std::string(kHead) + plainLines(3000) + "G02 X1. Y1. R5.\nM30\n%\n");
  const Outcome whole = run(f, false);
  const Outcome streamed = run(f, true);
  EXPECT_FALSE(whole.streamed);
  EXPECT_TRUE(streamed.streamed);
  EXPECT_EQ(whole.text, streamed.text);
  // One piece of 200 bytes holds a few lines, not the program's 3,000.
  EXPECT_GT(whole.blocksHeld, 3000u);
  EXPECT_LT(streamed.blocksHeld, 20u);
  fs::remove(f);
}

// A title comment before the O number (issue 24.2) and a byte-order mark (issue 26.13) in a
// streamed file: O0001 is the program, streamed, and runs as it does compiled whole.
TEST(ProgramStream, ATitleBeforeTheHeaderAndAByteOrderMarkStream) {
  const std::string body = plainLines(400) + "M30\n%\n";
  for (const std::string& head :
       {std::string("%\n(PART NAME)\n(DRAWING 12-345 REV B)\nO0001\nG90 G21 G17\n"),
        std::string("% (PART NAME)\nO0001\nG90 G21 G17\n"),
        std::string("\xEF\xBB\xBF%\nO0001 (BOM)\nG90 G21 G17\n")}) {
    SCOPED_TRACE(head);
    const fs::path f = writeFile("title.nc", head + body);
    const Outcome whole = run(f, false);
    const Outcome streamed = run(f, true, defaultSetup(), {}, 64);
    EXPECT_TRUE(streamed.streamed);
    EXPECT_EQ(whole.text, streamed.text);
    EXPECT_NE(whole.text.find("\"end\": \"M30\""), std::string::npos) << whole.text.substr(0, 400);
    Session s(defaultSetup());
    s.streamMainProgram({0, 64});
    s.addProgramFile(f.string());
    EXPECT_EQ(s.main()->number, 1);
    fs::remove(f);
  }
}

// A big file with only a trailing '%', and one with bytes after its closing '%': the stream
// scan refuses the first (compiled whole), and both keep their program.
TEST(ProgramStream, TapeEndsInBigFiles) {
  for (const std::string& text : {std::string("O0001\nG90 G21\n") + plainLines(400) + "M30\n%\n",
                                  std::string(kHead) + plainLines(400) + "M30\n%\x1a\x1a\n"}) {
    const fs::path f = writeFile("tape_end.nc", text);
    const Outcome whole = run(f, false);
    const Outcome streamed = run(f, true, defaultSetup(), {}, 64);
    EXPECT_EQ(whole.text, streamed.text);
    EXPECT_NE(whole.text.find("\"end\": \"M30\""), std::string::npos) << whole.text.substr(0, 400);
    fs::remove(f);
  }
}

TEST(ProgramStream, TheTopBlocksSequenceNumbersComeFromTheFile) {
  const fs::path f =
      writeFile("numbered.nc", std::string(kHead) + plainLines(500, 0, true) + "M30\n");
  const Outcome whole = run(f, false);
  const Outcome streamed = run(f, true);
  ASSERT_TRUE(streamed.streamed);
  EXPECT_EQ(whole.text, streamed.text);
  EXPECT_NE(whole.text.find("\"n\": 4"), std::string::npos);  // N numbers in the top blocks
  fs::remove(f);
}

TEST(ProgramStream, M99InTheMainProgramCompilesItWholeAndLoops) {
  ncvm::Setup setup = defaultSetup();
  setup.limits.maxBlocks = 700;
  const fs::path f = writeFile("loop.nc", std::string(kHead) + plainLines(300) + "M99\n");
  const Outcome whole = run(f, false, setup);
  const Outcome streamed = run(f, true, setup);
  ASSERT_TRUE(streamed.streamed);
  EXPECT_EQ(whole.text, streamed.text);
  EXPECT_NE(whole.text.find("PS9001"), std::string::npos);
  EXPECT_GT(streamed.blocksHeld, 300u);  // whole after the M99
  fs::remove(f);
}

TEST(ProgramStream, ALatheCycleReadsItsShapeFromTheWholeProgram) {
  ncvm::Setup setup = defaultSetup(MachineKind::Lathe);
  std::string text = "%\nO0002\nG21 G18 G40 G99\nT0101\nG96 S200 M03\nG00 X52. Z2.\n" +
                     std::string() + "G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n";
  for (int k = 0; k < 40; ++k) text += "(PADDING " + std::to_string(k) + ")\n";
  text +=
      "N10 G00 X20.\nG01 Z-20. F0.15\nX30. Z-30.\nN20 X50.\nG70 P10 Q20\nG00 X100. Z100.\nM30\n";
  const fs::path f = writeFile("lathe.nc", text);
  const Outcome whole = run(f, false, setup);
  const Outcome streamed = run(f, true, setup, {}, 64);
  ASSERT_TRUE(streamed.streamed);
  EXPECT_EQ(whole.text, streamed.text);
  EXPECT_EQ(streamed.blocksHeld, whole.blocksHeld);  // whole since the G71
  EXPECT_NE(whole.text.find("\"alarm\": null"), std::string::npos);
  fs::remove(f);
}

TEST(ProgramStream, AReturnToASequenceNumberOfTheStreamedCaller) {
  const fs::path dir =
      fs::temp_directory_path() / ("ncvm_stream_lib_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "O1000.nc") << "O1000\nG91 X1.\nG90\nM99 P30\n";
  const fs::path f =
      writeFile("caller.nc", std::string(kHead) + plainLines(100) + "M98 P1000\nX5.\nX6.\n" +
                                 "N30 X7.\n" + plainLines(100, 100) + "M30\n");
  const Outcome whole = run(f, false, defaultSetup(), dir);
  const Outcome streamed = run(f, true, defaultSetup(), dir);
  ASSERT_TRUE(streamed.streamed);
  EXPECT_EQ(whole.text, streamed.text);
  EXPECT_EQ(streamed.blocksHeld, whole.blocksHeld);  // whole since the M99 P30
  fs::remove_all(dir);
  fs::remove(f);
}

TEST(ProgramStream, ASecondRunStartsAgainAtTheFirstPiece) {
  const fs::path f = writeFile("twice.nc", std::string(kHead) + plainLines(400) + "M30\n");
  Session s(defaultSetup());
  s.streamMainProgram({0, 150});
  s.addProgramFile(f.string());
  ASSERT_TRUE(s.main()->stream);
  TraceWriter a(s.files(), nullptr, 1ull << 30, 3), b(s.files(), nullptr, 1ull << 30, 3);
  const auto ra = s.run(&a);
  const auto rb = s.run(&b);
  EXPECT_EQ(a.buffer(), b.buffer());
  EXPECT_EQ(ra.state.dump(), rb.state.dump());
  EXPECT_EQ(ra.stats.blocks, 404u);  // G90, G00, G01, the 400 lines and M30
  fs::remove(f);
}

TEST(ProgramStream, AFileChangedWhileItRunsIsAnAlarmWhenItMustBeReadAgain) {
  const fs::path f = writeFile("changed.nc", std::string(kHead) + plainLines(300) + "M99\n");
  Session s(defaultSetup());
  s.streamMainProgram({0, 200});
  s.addProgramFile(f.string());
  ASSERT_TRUE(s.main()->stream);
  // Another size (and mtime): the M99 needs the program whole, and the file is not the one
  // whose first piece ran.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::ofstream(f, std::ios::app) << "X1.\n";
  const auto r = s.run(nullptr);
  ASSERT_TRUE(r.alarm);
  EXPECT_EQ(r.alarm->code, "PS9007");
  fs::remove(f);
}

TEST(ProgramStream, SmallFilesAndMacroProgramsCompileWhole) {
  const fs::path plain = writeFile("small.nc", std::string(kHead) + plainLines(20) + "M30\n");
  const fs::path macro =
      writeFile("macro.nc", std::string(kHead) + plainLines(200) + "#1=5\nX#1\nM30\n");
  {
    Session s(defaultSetup());
    s.streamMainProgram({1 << 20, 64 << 10});  // the default kind of threshold
    s.addProgramFile(plain.string());
    EXPECT_FALSE(s.main()->stream);
  }
  EXPECT_FALSE(run(macro, true).streamed);
  fs::remove(plain);
  fs::remove(macro);
}
