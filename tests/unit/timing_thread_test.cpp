// The time stage on a worker thread (src/timing/timing_thread) against the same run on the
// control's thread: the same trace bytes, the same state (times, alarms, where they came),
// and a sink's exception on the worker ending the run.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "app/session.hpp"
#include "core/alarm.hpp"
#include "report/trace_writer.hpp"

using namespace ncvm;

namespace {

// A CAM-like program with everything the stage holds or stops at: a raster of short
// segments with arcs, rapids, M codes, a tool change, a dwell, operation comments, a
// message, an offset write and G96 on a lathe-like feed.
std::string mixedProgram(int lines) {
  std::string s =
      "O0003\nG90 G21 G17 G94\n(ROUGH)\nT1 M06\nS8000 M03\nG00 X0 Y0 Z5.\nG01 Z0 F3000.\n";
  const int perRow = 200;
  for (int k = 0; k < lines; ++k) {
    int row = k / perRow, col = k % perRow;
    double x = (row % 2 ? perRow - col : col) * 0.2, y = row * 0.5;
    double z = -1.0 + 0.5 * std::sin(x * 0.05) * std::cos(y * 0.07);
    if (col % 25 == 12)
      s += fmt::format("G{} X{:.3f} Y{:.3f} Z{:.3f} R5.\n", (k / 25) % 2 ? 2 : 3, x, y, z);
    else if (col % 25 == 13)
      s += fmt::format("G1 X{:.3f} Y{:.3f} Z{:.3f}\n", x, y, z);
    else
      s += fmt::format("X{:.3f} Y{:.3f} Z{:.3f}\n", x, y, z);
    if (col == perRow - 1) {
      s += fmt::format("(ROW {})\nG00 Z5.\nM08\nG04 X0.2\n#3006=1 (NEXT ROW)\n", row);
      s += fmt::format("G10 L2 P1 X{:.1f}\nG00 X{:.3f} Y{:.3f}\nG01 Z0 F3000.\n", 0.0, x, y + 0.5);
    }
  }
  s += "G00 Z50.\nM05\nM30\n";
  return s;
}

struct Outcome {
  std::string trace;
  std::string state;
  bool threaded = false;
  std::string alarm;  // the run's alarm code, empty when none
};

Outcome runWith(const Setup& setup, const std::string& text, int threads, bool trace,
                uint64_t maxTrace = 1ull << 30) {
  Session s(setup);
  s.setTimingThreads(threads);
  s.addProgramText(text, "t.nc");
  TraceWriter writer(s.files(), nullptr, maxTrace, s.setup().reportedAxes());
  Session::Result r = s.run(trace ? &writer : nullptr);
  return Outcome{writer.buffer(), r.state.dump(), s.usedTimingThread(),
                 r.alarm ? r.alarm->code : std::string()};
}

Setup withModel(bool dynamic) {
  Setup s = defaultSetup();
  s.timing.dynamic = dynamic;
  return s;
}

bool twoThreads() {
  return std::thread::hardware_concurrency() > 1;
}

}  // namespace

TEST(TimingThread, SameTraceAndStateAsOnTheControlsThread) {
  const std::string text = mixedProgram(3000);
  for (bool dynamic : {false, true}) {
    for (bool trace : {false, true}) {
      Outcome sync = runWith(withModel(dynamic), text, 0, trace);
      Outcome worker = runWith(withModel(dynamic), text, 1, trace);
      EXPECT_FALSE(sync.threaded);
      EXPECT_EQ(worker.threaded, twoThreads());
      EXPECT_EQ(sync.state, worker.state) << "dynamic " << dynamic << " trace " << trace;
      EXPECT_EQ(sync.trace, worker.trace) << "dynamic " << dynamic;
      if (trace) {
        EXPECT_GT(worker.trace.size(), 100000u);
      }
    }
  }
}

// Without a sink after the stage the worker gets compact records (only what the stage
// reads): every field of them must come through. A machine with A and C (six-axis records),
// inch blocks, arcs in all three planes, exact stop, peck drilling; a lathe with G96 and
// feed per revolution (the spindle fields), a G50 clamp and G32 threads.
std::string fiveAxisProgram(int rows) {
  std::string s = "O0011\nG90 G17 G21 G94\nG00 X0 Y0 Z5. A0 C0\nG01 Z-1. F800.\n";
  for (int k = 0; k < rows; ++k) {
    double x = k % 2 ? 0.0 : 40.0, y = k * 1.5;
    s += fmt::format("X{:.3f} Y{:.3f} A{:.1f} C{:.1f}\n", x, y, (k % 7) * 5.0, (k % 5) * -3.0);
    s +=
        fmt::format("G18 G02 X{:.3f} Z-1.5 R3.\nG19 G03 Y{:.3f} Z-1. R2.\nG17\n", x + 2.0, y + 1.0);
    s += fmt::format("G09 G01 X{:.3f}\nG61 Y{:.3f}\nG01 X{:.3f} Y{:.3f}\nG64\n", x + 1.0, y + 1.2,
                     x + 0.5, y + 1.4);
    if (k % 4 == 0) s += fmt::format("G20 G01 X{:.4f} F20.\nG21 F800.\n", (x + 1.0) / 25.4);
    if (k % 5 == 0)
      s += fmt::format("G00 Z5.\nG83 X{:.1f} Y{:.1f} Z-12. R2. Q3. F200.\nG80\nG01 Z-1. F800.\n", x,
                       y);
  }
  s += "G00 Z50. A0 C0\nM30\n";
  return s;
}

std::string latheProgram(int passes) {
  std::string s = "O0012\nG50 S2500\nT0101\nG00 X60. Z5.\nG96 S180 M03\n";
  for (int k = 0; k < passes; ++k) {
    double d = 58.0 - (k % 10) * 2.0;
    s += fmt::format("G00 X{:.1f} Z2.\nG99 G01 Z-30. F0.2\nG02 X{:.1f} Z-35. R5.\n", d, d + 10.0);
    s += fmt::format("G98 G01 X{:.1f} F300.\nG00 X80. Z5.\n", d + 14.0);
    if (k % 3 == 0)
      s += "G97 S800 M03\nG00 X48. Z5.\nG32 Z-20. F1.5\nG00 X60.\nZ5.\nG96 S180 M03\n";
  }
  s += "G00 X100. Z50.\nM05\nM30\n";
  return s;
}

// A three-axis mill (three-axis records) whose moves do not all follow on from the one
// before: work offsets (G54, G55, G92, G52) and tool lengths (G43) change between moves and
// during them, N numbers, a loop and a subprogram call (lines out of order, another
// program), feed changes. The compact records leave out only what did not change.
std::string offsetProgram() {
  return "O0013\n"
         "G90 G21 G17 G94\n"
         "G10 L2 P1 X-100. Y-50. Z-200.\n"
         "G10 L2 P2 X-300.5 Y-75.25 Z-210.\n"
         "G10 L10 P1 R120.\n"
         "G10 L10 P2 R95.5\n"
         "G54 G00 X0 Y0 Z5.\n"
         "G43 H1 Z5.\n"
         "N10 G01 Z-1. F1200.\n"
         "N20 X1. Y0.5\n"
         "N30 X2. Y1.\n"
         "#1=0\n"
         "WHILE[#1LT3]DO1\n"
         "X[3.+#1] Y1.5\n"
         "X[3.5+#1] Y2. F1500.\n"
         "#1=#1+1\n"
         "END1\n"
         "G55 X1. Y1.\n"
         "X2. Y2.\n"
         "G43 H2 X3. Z-1.\n"
         "X4. Y3.\n"
         "G92 X0 Y0\n"
         "X1. Y1.\n"
         "X2. Y1.5\n"
         "G52 X5. Y5.\n"
         "X1. Y1. F900.\n"
         "X2. Y2.\n"
         "G52 X0 Y0\n"
         "M98 P0014\n"
         "X-1. Y-1.\n"
         "G49 X0 Y0\n"
         "G00 Z50.\n"
         "M30\n"
         "O0014\n"
         "N100 G01 X0.5 Y0.5\n"
         "N110 X1. Y0.7\n"
         "N120 X1.5 Y0.9 F700.\n"
         "M99\n";
}

TEST(TimingThread, CompactRecordsCarryWhatTheStageReads) {
  ncvm::Setup mill = withModel(true);
  applySetting(mill, "axes.A.rotary=true");
  applySetting(mill, "axes.C.rotary=true");
  ncvm::Setup lathe = defaultSetup(MachineKind::Lathe);
  lathe.timing.dynamic = true;
  ncvm::Setup latheSimple = lathe;
  latheSimple.timing.dynamic = false;
  struct Case {
    const ncvm::Setup* setup;
    std::string text;
  };
  const ncvm::Setup three = withModel(true), threeSimple = withModel(false);
  for (const Case& c : {Case{&mill, fiveAxisProgram(120)}, Case{&lathe, latheProgram(60)},
                        Case{&latheSimple, latheProgram(20)}, Case{&three, offsetProgram()},
                        Case{&threeSimple, offsetProgram()}}) {
    for (bool trace : {false, true}) {
      Outcome sync = runWith(*c.setup, c.text, 0, trace);
      Outcome worker = runWith(*c.setup, c.text, 1, trace);
      EXPECT_EQ(worker.threaded, twoThreads());
      EXPECT_EQ(sync.state, worker.state) << c.text.substr(0, 5) << " trace " << trace;
      EXPECT_EQ(sync.trace, worker.trace);
      // The programs run to their end (a program that stopped early would test little).
      EXPECT_EQ(sync.alarm, "") << c.text.substr(0, 5);
      EXPECT_EQ(worker.alarm, "");
    }
  }
}

TEST(TimingThread, SetupKeySelectsTheThread) {
  ncvm::Setup s = withModel(true);
  applySetting(s, "timing.threads=0");
  EXPECT_EQ(s.timing.threads, 0);
  EXPECT_FALSE(runWith(s, mixedProgram(10), -1, false).threaded);
  applySetting(s, "timing.threads=1");
  EXPECT_EQ(runWith(s, mixedProgram(10), -1, false).threaded, twoThreads());
  EXPECT_THROW(applySetting(s, "timing.threads=2"), SetupError);
}

// The trace limit is reached at the same event with the worker as without it: the worker
// hands the stage back to the control's thread before the events in flight could pass it.
TEST(TimingThread, TraceLimitAtTheSameEvent) {
  const std::string text = mixedProgram(3000);
  for (bool dynamic : {false, true}) {
    for (uint64_t limit : {300ull, 20000ull, 400000ull}) {
      Outcome sync = runWith(withModel(dynamic), text, 0, true, limit);
      Outcome worker = runWith(withModel(dynamic), text, 1, true, limit);
      EXPECT_NE(sync.state.find("PS9006"), std::string::npos) << limit;
      EXPECT_EQ(sync.state, worker.state) << "dynamic " << dynamic << " limit " << limit;
      EXPECT_EQ(sync.trace, worker.trace) << "dynamic " << dynamic << " limit " << limit;
    }
  }
}

namespace {
// A sink that may run on the worker and fails (as an output error would) at its nth move.
struct FailingSink final : EventSink {
  explicit FailingSink(int n) : failAt(n) {}
  int failAt, moves = 0;
  bool alarmSeen = false;
  void onMove(const MoveEvent&) override {
    if (++moves == failAt) throw AlarmError(AlarmId::OutputError, "test sink");
  }
  void onAlarm(const AlarmEvent&) override { alarmSeen = true; }
  bool runsOnAnyThread() const override { return true; }
};
}  // namespace

// A sink's exception on the worker stops the control at its next event with that alarm.
TEST(TimingThread, SinkFailureEndsTheRun) {
  const std::string text = mixedProgram(20000);
  for (int threads : {0, 1}) {
    Session s(withModel(true));
    s.setTimingThreads(threads);
    s.addProgramText(text, "t.nc");
    FailingSink sink(1000);
    Session::Result r = s.run(&sink);
    ASSERT_TRUE(r.alarm) << threads;
    EXPECT_EQ(r.alarm->code, alarmCode(AlarmId::OutputError));
    EXPECT_EQ(r.end, EndReason::Alarm);
    EXPECT_TRUE(sink.alarmSeen);
    // The control ran at most the ring's capacity and the look-ahead past the failing move.
    EXPECT_LT(r.stats.moves, 1000u + 512u + 200u) << threads;
  }
}

// A sink that fails after the control has sent its last event: the alarm of the run.
TEST(TimingThread, SinkFailureAfterTheLastBlock) {
  const std::string text = mixedProgram(300);
  for (int threads : {0, 1}) {
    Session s(withModel(true));
    s.setTimingThreads(threads);
    s.addProgramText(text, "t.nc");
    FailingSink sink(300);  // among the last moves the stage holds
    Session::Result r = s.run(&sink);
    ASSERT_TRUE(r.alarm) << threads;
    EXPECT_EQ(r.alarm->code, alarmCode(AlarmId::OutputError));
  }
}

// Sinks that read the control (the viewer's inspector) or do not say they may run anywhere
// keep everything on the control's thread.
TEST(TimingThread, OnlyWhereItCanBe) {
  struct Plain final : EventSink {
    int moves = 0;
    void onMove(const MoveEvent&) override { ++moves; }
  } plain;
  Session a(withModel(true));
  a.addProgramText(mixedProgram(50), "t.nc");
  a.run(&plain);
  EXPECT_FALSE(a.usedTimingThread());
  EXPECT_GT(plain.moves, 50);

  Session b(withModel(true));
  b.addProgramText(mixedProgram(50), "t.nc");
  bool inspected = false;
  b.setInspector([&](Executor&) { inspected = true; });
  b.run(nullptr);
  EXPECT_TRUE(inspected);
  EXPECT_FALSE(b.usedTimingThread());
}
