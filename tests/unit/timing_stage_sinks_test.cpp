// The time stage between the control and the caller's sinks: the trace limit and a sink's
// failure end the run with their alarm, also for moves the stage's look-ahead still held.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

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
  std::string alarm;  // the run's alarm code, empty when none
};

Outcome runWith(const Setup& setup, const std::string& text, uint64_t maxTrace) {
  Session s(setup);
  s.addProgramText(text, "t.nc");
  TraceWriter writer(s.files(), nullptr, maxTrace, s.setup().reportedAxes());
  Session::Result r = s.run(&writer);
  return Outcome{writer.buffer(), r.state.dump(), r.alarm ? r.alarm->code : std::string()};
}

Setup withModel(bool dynamic) {
  Setup s = defaultSetup();
  s.timing.dynamic = dynamic;
  return s;
}

}  // namespace

// The trace limit ends the run with PS9006 right after the line that passed it, in both models
// (the dynamic one holds moves back in its look-ahead).
TEST(TimingStageSinks, TraceLimitEndsTheRun) {
  const std::string text = mixedProgram(3000);
  for (bool dynamic : {false, true}) {
    for (uint64_t limit : {300ull, 20000ull, 400000ull}) {
      Outcome o = runWith(withModel(dynamic), text, limit);
      EXPECT_EQ(o.alarm, "PS9006") << "dynamic " << dynamic << " limit " << limit;
      // The line that passes the limit and the alarm's line are the last ones written.
      EXPECT_LT(o.trace.size(), limit + 1000) << "dynamic " << dynamic;
      EXPECT_GT(o.trace.size(), limit) << "dynamic " << dynamic;
      const size_t last = o.trace.rfind('\n', o.trace.size() - 2);
      EXPECT_NE(o.trace.find("PS9006", last == std::string::npos ? 0 : last), std::string::npos);
    }
  }
}

namespace {
// A sink that fails (as an output error would) at its nth move.
struct FailingSink final : EventSink {
  explicit FailingSink(int n) : failAt(n) {}
  int failAt, moves = 0;
  bool alarmSeen = false;
  void onMove(const MoveEvent&) override {
    if (++moves == failAt) throw AlarmError(AlarmId::OutputError, "test sink");
  }
  void onAlarm(const AlarmEvent&) override { alarmSeen = true; }
};
}  // namespace

// A sink's exception stops the control with that alarm.
TEST(TimingStageSinks, SinkFailureEndsTheRun) {
  const std::string text = mixedProgram(20000);
  Session s(withModel(true));
  s.addProgramText(text, "t.nc");
  FailingSink sink(1000);
  Session::Result r = s.run(&sink);
  ASSERT_TRUE(r.alarm);
  EXPECT_EQ(r.alarm->code, alarmCode(AlarmId::OutputError));
  EXPECT_EQ(r.end, EndReason::Alarm);
  EXPECT_TRUE(sink.alarmSeen);
  // The control ran at most the look-ahead past the failing move.
  EXPECT_LT(r.stats.moves, 1000u + 200u);
}

// A sink that fails after the control has sent its last event: the alarm of the run.
TEST(TimingStageSinks, SinkFailureAfterTheLastBlock) {
  const std::string text = mixedProgram(300);
  Session s(withModel(true));
  s.addProgramText(text, "t.nc");
  FailingSink sink(300);  // among the last moves the stage holds
  Session::Result r = s.run(&sink);
  ASSERT_TRUE(r.alarm);
  EXPECT_EQ(r.alarm->code, alarmCode(AlarmId::OutputError));
}
