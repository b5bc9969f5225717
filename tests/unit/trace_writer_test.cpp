// The trace writer's move lines against a plain reference formatter written here from the
// same events: positions in fmt's shortest form, feed, length and times rounded to nine
// decimals (docs/trace-format.md). The program has offsets (work, G52, G92, tool length),
// arcs, dog-leg rapids and inch units, so the writer's reuse of the last move's text
// (start = last end, mend = end) is checked where it must not apply too.
#include "report/trace_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "app/session.hpp"

using namespace ncvm;

namespace {

std::string shortest(double v) {
  return fmt::format("{}", v);
}

std::string nineDecimals(double v) {
  if (!(std::fabs(v) < 1e6) || (v == 0 && std::signbit(v))) return shortest(v);
  std::string s = fmt::format("{:.9f}", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string positions(const double* a, int n) {
  std::string s = "[";
  for (int k = 0; k < n; ++k) s += (k ? "," : "") + shortest(a[k]);
  return s + "]";
}

// Passes every event to the writer and keeps the line each move should have.
struct Reference final : EventSink {
  Reference(TraceWriter& w, const SourceFiles& f, int n) : writer(w), files(f), axes(n) {}
  TraceWriter& writer;
  const SourceFiles& files;
  int axes;
  std::vector<std::string> moves;
  int arcs = 0, doglegs = 0, inch = 0, offsetMoves = 0;

  void onMove(const MoveEvent& e) override {
    std::string s =
        fmt::format(R"({{"type":"move","file":"{}","line":{},"n":{},"prog":{})",
                    files.name(e.at.file), e.at.line, e.at.n >= 0 ? std::to_string(e.at.n) : "null",
                    e.at.programName ? "\"" + *e.at.programName + "\"" : "null");
    const double simple = e.timeSimple >= 0 ? e.timeSimple : e.time;
    s += fmt::format(
        R"(,"mode":"{}","start":{},"end":{},"mstart":{},"mend":{},"feed":{},"length":{},"time":{},"time_simple":{})",
        moveModeName(e.mode), positions(e.start.data(), axes), positions(e.end.data(), axes),
        positions(e.mstart.data(), axes), positions(e.mend.data(), axes), nineDecimals(e.feed),
        nineDecimals(e.length), nineDecimals(e.time), nineDecimals(simple));
    if (e.arc)
      s += fmt::format(R"(,"center":{},"plane":{})", positions(e.center.data(), 3), e.plane);
    if (e.compensated) s += R"(,"prog_end":)" + positions(e.programmedEnd.data(), axes);
    if (e.nose) s += R"(,"nose_end":)" + positions(e.noseEnd.data(), axes);
    if (e.thread) s += R"(,"thread":true)";
    if (e.pathPoints > 0) {
      s += R"(,"path":[)";
      for (int k = 0; k < e.pathPoints; ++k)
        s += (k ? "," : "") + positions(e.path[static_cast<size_t>(k)].data(), 3);
      s += "]";
    }
    moves.push_back(s + "}");
    arcs += e.arc;
    doglegs += e.pathPoints > 0;
    inch += e.inch;
    offsetMoves += e.mend != e.end;
    writer.onMove(e);
  }
  void onDwell(const DwellEvent& e) override { writer.onDwell(e); }
  void onMessage(const MessageEvent& e) override { writer.onMessage(e); }
  void onAlarm(const AlarmEvent& e) override { writer.onAlarm(e); }
  void onTool(const ToolEvent& e) override { writer.onTool(e); }
  void onSpindle(const SpindleEvent& e) override { writer.onSpindle(e); }
  void onCoolant(const CoolantEvent& e) override { writer.onCoolant(e); }
  void onAux(const AuxEvent& e) override { writer.onAux(e); }
  void onOffset(const OffsetEvent& e) override { writer.onOffset(e); }
  void onSkip(const SkipEvent& e) override { writer.onSkip(e); }
};

const char* kProgram = R"(O0100
G90 G21 G17 G94
G10 L2 P1 X100. Y50. Z-20.
G10 L10 P1 R35.5
G54 G00 X10. Y20. Z30.
N10 G01 X12.5 Y20. F250.
G02 X17.5 Y20. R2.5
G03 X12.5 Y20. I-2.5 J0
G18 G02 X14. Z28.5 R1.5
G17 G52 X1.5 Y-2.
G01 X3. Y4. Z-1.
G00 X7.25 Y-3.125 Z2.
G92 X0 Y0
G01 X1. Y1. F1234.5
G52 X0 Y0
G43 H1 Z5.
G01 X-0.000001 Y1.000001
G20
G01 X0.5 Y0.25 F10.
G00 X1.2 Y0.7 Z0.1
G02 X1.7 Y0.2 R0.5 F7.5
G91 G01 X0.0001 Y-0.3333 Z-0.001
X0 Y0 Z0.01
G90 G49 G00 Z1.
M30
)";

void runProgram(const std::string& fileName, bool dynamicTiming, std::vector<std::string>& written,
                std::vector<std::string>& expected, int& arcs, int& doglegs, int& inch,
                int& offsetMoves) {
  Setup setup = defaultSetup();
  setup.timing.dynamic = dynamicTiming;
  Session s(setup);
  s.addProgramText(kProgram, fileName);
  TraceWriter writer(s.files(), nullptr, 1ull << 30, s.setup().reportedAxes());
  Reference ref(writer, s.files(), s.setup().reportedAxes());
  Session::Result r = s.run(&ref);
  EXPECT_TRUE(r.state["alarm"].is_null()) << r.state["alarm"].dump();
  std::istringstream in(writer.buffer());
  for (std::string l; std::getline(in, l);)
    if (l.rfind(R"({"type":"move")", 0) == 0) written.push_back(l);
  expected = ref.moves;
  arcs = ref.arcs;
  doglegs = ref.doglegs;
  inch = ref.inch;
  offsetMoves = ref.offsetMoves;
}

}  // namespace

TEST(TraceWriter, MoveLinesAsTheReferenceFormatterWritesThem) {
  for (bool dynamic : {false, true}) {
    // A file name past the 2048 bytes of the fast head takes the general way.
    for (const std::string& name : {std::string("t.nc"), std::string(3000, 'a') + ".nc"}) {
      std::vector<std::string> written, expected;
      int arcs = 0, doglegs = 0, inch = 0, offsetMoves = 0;
      runProgram(name, dynamic, written, expected, arcs, doglegs, inch, offsetMoves);
      ASSERT_EQ(written.size(), expected.size());
      for (size_t i = 0; i < written.size(); ++i)
        EXPECT_EQ(written[i], expected[i]) << "move " << i;
      // The program reaches every case the writer treats apart.
      EXPECT_EQ(written.size(), 16u);  // the moves of kProgram (G10, G52, G92 and G20 make none)
      EXPECT_GE(arcs, 4);
      EXPECT_GE(doglegs, 2);
      EXPECT_GE(inch, 6);
      EXPECT_GE(offsetMoves, 15);
    }
  }
}

namespace {
// Moves of three programs in two files: the head's texts (file, program, mode) change
// between moves, and a coolant event of O0200 comes between a move of O0100 and one of
// O0200 (the writer's cache of the last program escaped is not the last move's program).
const char* kMain = R"(O0100
G90 G21 G17 G94
G01 X1. Y1. Z0 F100.
M98 P0200
G01 X2. Y2.
N5 G00 X3.
M98 P0300
G01 X4. Y4.
N7 X5.
N7 X6.
M30
O0200
M08
G01 X1.5 Y1.5
G00 Z2.
M99
)";
const char* kOther = R"(O0300
G01 X3.5 F200.
G02 X3.5 Y5. R2.
M09
G01 X3.6
M99
)";

// The moves the writer wrote and the reference's, of the text the writer wrote to `out`
// (nullptr: its buffer).
void runSubprograms(std::FILE* out, std::vector<std::string>& written,
                    std::vector<std::string>& expected, const std::string& extra = "") {
  Session s(defaultSetup());
  s.addProgramText(extra.empty() ? kMain : extra, "main.nc");
  s.addProgramText(kOther, "other.nc");
  TraceWriter writer(s.files(), out, 1ull << 32, s.setup().reportedAxes());
  Reference ref(writer, s.files(), s.setup().reportedAxes());
  Session::Result r = s.run(&ref);
  EXPECT_TRUE(r.state["alarm"].is_null()) << r.state["alarm"].dump();
  std::string text = writer.buffer();
  if (out) {
    writer.flush();
    text.clear();
    std::rewind(out);
    char chunk[4096];
    for (size_t got; (got = std::fread(chunk, 1, sizeof chunk, out)) > 0;) text.append(chunk, got);
  }
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);)
    if (l.rfind(R"({"type":"move")", 0) == 0) written.push_back(l);
  expected = ref.moves;
}
}  // namespace

TEST(TraceWriter, MoveHeadsFollowFileProgramModeAndN) {
  std::vector<std::string> written, expected;
  runSubprograms(nullptr, written, expected);
  ASSERT_EQ(written.size(), expected.size());
  ASSERT_EQ(written.size(), 11u);
  for (size_t i = 0; i < written.size(); ++i) EXPECT_EQ(written[i], expected[i]) << "move " << i;
  // The case above: O0200's first move follows O0100's move and O0200's coolant event.
  EXPECT_NE(written[1].find(R"("prog":"O0200")"), std::string::npos) << written[1];
  EXPECT_NE(written[5].find(R"("file":"other.nc")"), std::string::npos) << written[5];
}

// More than a chunk (1 MB) of trace to a FILE: lines after a flush are the same as without
// one, and in memory the buffer grows past its first size with the same text.
TEST(TraceWriter, SameTextAcrossFlushesAndGrowth) {
  std::string big = "O0100\nG90 G21 G17 G94\nG01 X0 Y0 Z0 F500.\n";
  for (int i = 0; i < 8000; ++i)
    big += fmt::format("X{:.3f} Y{:.3f} Z{}\n", (i % 700) * 0.25, (i % 3) * 1.5, -(i % 2));
  big += "M30\n";
  for (bool toFile : {false, true}) {
    std::FILE* f = toFile ? std::tmpfile() : nullptr;
    if (toFile) {
      ASSERT_NE(f, nullptr);
    }
    std::vector<std::string> written, expected;
    runSubprograms(f, written, expected, big);
    if (f) std::fclose(f);
    ASSERT_EQ(written.size(), expected.size()) << toFile;
    ASSERT_EQ(written.size(), 8001u);
    for (size_t i = 0; i < written.size(); ++i)
      ASSERT_EQ(written[i], expected[i]) << "move " << i << (toFile ? " (file)" : "");
  }
}
