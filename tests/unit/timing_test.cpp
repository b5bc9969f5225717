// The cycle-time model: velocity profiles (src/timing/profile) and the planner stage
// (src/timing/timing_stage) through the session, against hand-computed values.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "app/session.hpp"
#include "timing/profile.hpp"
#include "timing/time_report.hpp"

using namespace ncvm;
using namespace ncvm::timing;

namespace {

struct MoveTimes final : EventSink {
  std::vector<double> time, simple;
  void onMove(const MoveEvent& e) override {
    time.push_back(e.time);
    simple.push_back(e.timeSimple >= 0 ? e.timeSimple : e.time);
  }
};

Setup dynamicSetup(std::initializer_list<const char*> sets = {}) {
  ncvm::Setup s = defaultSetup();
  for (const char* kv :
       {"timing.model=dynamic", "timing.accel=1000", "timing.accel_change_time=0",
        "timing.block_time=0", "timing.in_position_time=0.02", "timing.arc_clamp_feed=0"})
    applySetting(s, kv);
  for (const char* kv : sets) applySetting(s, kv);
  return s;
}

Session::Result run(const std::string& text, const Setup& setup, MoveTimes* sink = nullptr) {
  Session s(setup);
  s.addProgramText(text, "t.nc");
  return s.run(sink);
}

double total(const Session::Result& r) {
  return r.timing->total().model;
}

std::string chain(int blocks, double step, const char* feed = "F6000.") {
  std::string s = fmt::format("O1\nG90 G21 G94 G01 X{:.4f} {}\n", step, feed);
  for (int k = 2; k <= blocks; ++k) s += fmt::format("X{:.4f}\n", step * k);
  return s + "M30\n";
}

}  // namespace

TEST(Profile, RampTimes) {
  Ramp trap{1000, 0}, bell{1000, 20000};
  EXPECT_DOUBLE_EQ(rampTime(100, trap), 0.1);
  EXPECT_DOUBLE_EQ(rampTime(100, bell), 0.15);                          // 0.1 + a/j
  EXPECT_NEAR(rampTime(20, bell), 2 * std::sqrt(20.0 / 20000), 1e-15);  // below a^2/j = 50
  EXPECT_DOUBLE_EQ(rampDistance(0, 100, trap), 5);
  EXPECT_DOUBLE_EQ(rampDistance(100, 0, bell), 7.5);
}

TEST(Profile, ReachableInvertsRampDistance) {
  for (Ramp r : {Ramp{1000, 0}, Ramp{1000, 20000}, Ramp{300, 1e6}, Ramp{5000, 2000}}) {
    for (double v0 : {0.0, 3.0, 40.0}) {
      for (double d : {0.01, 0.5, 2.0, 10.0, 400.0}) {
        double v1 = reachable(v0, d, r);
        EXPECT_NEAR(rampDistance(v0, v1, r), d, 1e-9 * std::max(1.0, d))
            << r.a << " " << r.j << " " << v0 << " " << d;
      }
    }
  }
}

TEST(Profile, BlockTimes) {
  Ramp trap{1000, 0}, bell{1000, 20000};
  EXPECT_DOUBLE_EQ(blockTime(0, 0, 100, 100, trap), 1.1);
  EXPECT_NEAR(blockTime(0, 0, 100, 100, bell), 1.15, 1e-12);
  EXPECT_NEAR(blockTime(0, 0, 100, 2, trap), 2 * std::sqrt(2.0 / 1000), 1e-12);
  // Short S-curve block: peak dv = (L sqrt(j) / 2)^(2/3), time 4 sqrt(dv / j).
  double dv = std::pow(2 * std::sqrt(20000.0) / 2, 2.0 / 3.0);
  EXPECT_NEAR(blockTime(0, 0, 100, 2, bell), 4 * std::sqrt(dv / 20000), 1e-9);
  // Entry and exit speeds: symmetric in time, cruise at vmax.
  EXPECT_NEAR(blockTime(10, 50, 100, 100, bell), blockTime(50, 10, 100, 100, bell), 1e-12);
  EXPECT_DOUBLE_EQ(blockTime(100, 100, 100, 10, trap), 0.1);
  EXPECT_DOUBLE_EQ(blockTime(0, 0, 100, 0, trap), 0);
}

TEST(TimingStage, SimpleModelKeepsLengthOverFeed) {
  MoveTimes m;
  auto r = run(chain(5, 1), defaultSetup(), &m);
  ASSERT_EQ(m.time.size(), 5u);
  for (size_t k = 0; k < 5; ++k) EXPECT_DOUBLE_EQ(m.time[k], m.simple[k]);
  EXPECT_DOUBLE_EQ(total(r), r.stats.time);
  EXPECT_DOUBLE_EQ(r.state["cycle_time"].get<double>(), r.stats.time);
}

TEST(TimingStage, CollinearChainRunsAsOneMove) {
  // Trapezoid: five 1 mm blocks take as long as one 5 mm move.
  double one = total(run(chain(1, 5), dynamicSetup()));
  EXPECT_NEAR(total(run(chain(5, 1), dynamicSetup())), one, 1e-12);
  EXPECT_NEAR(one, 2 * std::sqrt(5.0 / 1000), 1e-12);
  // S-curve: blocks long enough to finish each ramp in the first and last block.
  ncvm::Setup bell = dynamicSetup({"timing.accel_change_time=50"});
  EXPECT_NEAR(total(run(chain(5, 20), bell)), total(run(chain(1, 100), bell)), 1e-9);
  // S-curve over blocks shorter than a ramp: the acceleration carries on across the joints.
  ncvm::Setup deep = dynamicSetup({"timing.accel_change_time=50", "timing.lookahead_blocks=100"});
  EXPECT_NEAR(total(run(chain(50, 0.1), deep)), blockTime(0, 0, 100, 5, Ramp{1000, 20000}), 1e-9);
}

TEST(Profile, TimeAtInsideEachPhaseOfAnSCurveRamp) {
  // From rest to 100 mm/s with a = 1000, j = 20000: jerk phase 0.05 s (0.4167 mm), constant
  // acceleration 0.05 s, jerk phase 0.05 s; 7.5 mm in all, then a long cruise.
  Ramp r{1000, 20000};
  Profile p = makeProfile(0, 0, 100, 50, r);
  ASSERT_NEAR(p.dUp, 7.5, 1e-12);
  // First phase: s = j t^3 / 6.
  EXPECT_NEAR(p.timeAt(0.2), std::cbrt(6 * 0.2 / 20000), 1e-12);
  // Middle: after 0.05 s at 25 mm/s and 0.4167 mm, s = da + 25 tau + 500 tau^2.
  double da = 20000 * 0.05 * 0.05 * 0.05 / 6, tau = 0.02;
  EXPECT_NEAR(p.timeAt(da + 25 * tau + 500 * tau * tau), 0.05 + tau, 1e-12);
  // Last phase, by the ramp's symmetry: 0.01 s before its end it is vp t - j t^3 / 6 short.
  double t = 0.01;
  EXPECT_NEAR(p.timeAt(7.5 - (100 * t - 20000 * t * t * t / 6)), 0.15 - t, 1e-12);
  // Cruise: 100 mm/s after the ramp.
  EXPECT_NEAR(p.timeAt(10), 0.15 + 2.5 / 100, 1e-12);
}

TEST(Profile, TimeAtSplitsTheProfile) {
  for (Ramp r : {Ramp{1000, 0}, Ramp{1000, 20000}}) {
    Profile p = makeProfile(0, 10, 100, 50, r);
    EXPECT_NEAR(p.total(), blockTime(0, 10, 100, 50, r), 1e-12);
    double prev = 0;
    for (int k = 1; k <= 50; ++k) {
      double t = p.timeAt(k);
      EXPECT_GT(t, prev);
      prev = t;
    }
    EXPECT_NEAR(prev, p.total(), 1e-12);
    // Up-ramp from rest: 0.5 a t^2 (trapezoid) at 1 mm.
    if (r.j <= 0) {
      EXPECT_NEAR(p.timeAt(1), std::sqrt(2.0 / 1000), 1e-12);
    }
  }
}

TEST(TimingStage, LookaheadOfOneBlockStopsAtEveryJoint) {
  double one = total(run(chain(1, 1), dynamicSetup()));
  EXPECT_NEAR(total(run(chain(5, 1), dynamicSetup({"timing.lookahead_blocks=1"}))), 5 * one, 1e-12);
}

TEST(TimingStage, LookaheadDepthLimitsSpeedOnTinyBlocks) {
  // 200 blocks of 0.1 mm, 5 blocks read ahead: the control sees 0.4 mm past each block end and
  // must be able to stop there: v <= sqrt(2 a 0.4) = 28.28 mm/s instead of 100 mm/s.
  auto r = run(chain(200, 0.1), dynamicSetup({"timing.lookahead_blocks=5"}));
  double cruise = 20.0 / std::sqrt(2 * 1000 * 0.4);
  EXPECT_GT(total(r), cruise);
  EXPECT_LT(total(r), cruise + 0.1);
  // With a deep look-ahead the same path is one 20 mm move.
  EXPECT_NEAR(total(run(chain(200, 0.1), dynamicSetup({"timing.lookahead_blocks=1000"}))),
              blockTime(0, 0, 100, 20, Ramp{1000, 0}), 1e-9);
}

TEST(TimingStage, LongProgramsArePlannedInWindows) {
  // 400 blocks of 10 mm with a 10-block look-ahead: planned and forwarded in parts, still
  // one 4000 mm move (the look-ahead never limits: stopping from 100 mm/s needs 5 mm).
  auto r = run(chain(400, 10), dynamicSetup({"timing.lookahead_blocks=10"}));
  EXPECT_NEAR(total(r), blockTime(0, 0, 100, 4000, Ramp{1000, 0}), 1e-9);
}

TEST(TimingStage, ExactStopG09AndG61) {
  double two = total(run(chain(1, 2), dynamicSetup())),
         three = total(run(chain(1, 3), dynamicSetup()));
  std::string g09 = "O1\nG90 G21 G94 G01 X1. F6000.\nX2.\nG09 X3.\nX4.\nX5.\nM30\n";
  EXPECT_NEAR(total(run(g09, dynamicSetup())), three + 0.02 + two, 1e-12);
  std::string g61 = "O1\nG61\nG90 G21 G94 G01 X1. F6000.\nX2.\nM30\n";
  double one = total(run(chain(1, 1), dynamicSetup()));
  EXPECT_NEAR(total(run(g61, dynamicSetup())), 2 * (one + 0.02), 1e-12);
}

TEST(TimingStage, MinimumBlockTime) {
  // 0.01 mm blocks at 2 ms each: at most 5 mm/s, whatever F says.
  MoveTimes m;
  auto r = run(chain(50, 0.01), dynamicSetup({"timing.block_time=2"}), &m);
  for (double t : m.time) EXPECT_GE(t, 0.002 - 1e-15);
  // As one 0.5 mm move at 5 mm/s: 0.5 / 5 + 5 / a = 0.105 s (F6000 alone: 0.0447 s).
  EXPECT_NEAR(total(r), 0.105, 1e-9);
}

TEST(TimingStage, ArcFeedClamp) {
  // 1730 = 6000 mm/min at 1731 = 4 mm: a = 100^2 / 4 = 2500 mm/s^2; on R1 v = sqrt(2500) = 50 mm/s.
  ncvm::Setup s =
      dynamicSetup({"timing.arc_clamp_feed=6000", "timing.arc_clamp_radius=4", "timing.accel=1e6"});
  MoveTimes m;
  run("O1\nG90 G21 G17 G94 G00 X1. Y0\nG02 I-1. F6000.\nM30\n", s, &m);
  ASSERT_EQ(m.time.size(), 2u);
  EXPECT_NEAR(m.time[1], 2 * M_PI / 50 + 50 / 1e6, 1e-9);
  EXPECT_NEAR(m.simple[1], 2 * M_PI / 100, 1e-9);
}

TEST(TimingStage, FeedOverride) {
  double full = total(run(chain(1, 100), dynamicSetup()));
  double half = total(run(chain(1, 100), dynamicSetup({"timing.feed_override=50"})));
  // 100 mm/s: 1.1 s. 50 mm/s: 0.05 s ramps over 1.25 mm each, 97.5 mm / 50 = 1.95 s: 2.05 s.
  EXPECT_NEAR(full, 1.1, 1e-12);
  EXPECT_NEAR(half, 2.05, 1e-12);
}

TEST(TimingStage, ToolChangesSplitOperations) {
  ncvm::Setup s = dynamicSetup(
      {"timing.tool_change_time=3", "timing.m_code_time=0", "timing.coolant_time=0.5"});
  auto r = run("O1\nT1 M06\nG90 G21 G94 G01 X100. F6000.\nM08\nT2 M06\nG01 X0\nM09\nM30\n", s);
  const auto& ops = r.timing->operations();
  ASSERT_EQ(ops.size(), 2u);
  EXPECT_EQ(ops[0].tool, 1);
  EXPECT_EQ(ops[1].tool, 2);
  EXPECT_NEAR(ops[0].time.model, 3 + 1.1 + 0.5, 1e-12);
  EXPECT_NEAR(ops[1].time.model, 3 + 1.1 + 0.5, 1e-12);
  EXPECT_NEAR(r.timing->byKind(TimeKind::Auxiliary).model, 7, 1e-12);
  auto tools = r.timing->byTool();
  ASSERT_EQ(tools.size(), 2u);
  EXPECT_EQ(r.state["timing"]["operations"][1]["start"]["line"], 5);
  EXPECT_EQ(r.state["timing"]["top_blocks"][0]["line"], 2);  // T1 M06: 3 s
}

TEST(TimingStage, PeckCounting) {
  // G83 Q5 from R2 to Z-20: pecks to -3, -8, -13, -18, -20; full retracts between them.
  auto r = run("O1\nG90 G21 G94 G00 X0 Y0 Z10.\nG98 G83 Z-20. R2. Q5. F300.\nG80\nM30\n",
               dynamicSetup());
  EXPECT_EQ(r.timing->drilling().holes, 1u);
  EXPECT_EQ(r.timing->drilling().pecks, 5u);
  EXPECT_EQ(r.timing->drilling().fullRetracts, 4u);
  // G73 (small retracts only): pecks but no full retract.
  auto h = run("O1\nG90 G21 G94 G00 X0 Y0 Z10.\nG98 G73 Z-20. R2. Q5. F300.\nG80\nM30\n",
               dynamicSetup());
  EXPECT_EQ(h.timing->drilling().pecks, 5u);
  EXPECT_EQ(h.timing->drilling().fullRetracts, 0u);
}

TEST(TimingSetupKeys, ParseAndReject) {
  ncvm::Setup s = defaultSetup();
  applySetting(s, "timing.model=dynamic");
  applySetting(s, "timing.accel=2000");
  applySetting(s, "timing.axes.Z.accel=800");
  applySetting(s, "timing.lookahead_blocks=200");
  EXPECT_TRUE(s.timing.dynamic);
  EXPECT_EQ(s.timing.accel[0], 2000);
  EXPECT_EQ(s.timing.accel[2], 800);
  EXPECT_EQ(s.timing.lookaheadBlocks, 200);
  EXPECT_THROW(applySetting(s, "timing.model=fast"), SetupError);
  EXPECT_THROW(applySetting(s, "timing.accel=-1"), SetupError);
  EXPECT_THROW(applySetting(s, "timing.axes.Q.accel=1"), SetupError);
  EXPECT_THROW(applySetting(s, "timing.no_such_key=1"), SetupError);
  EXPECT_THROW(applySetting(s, "timing.lookahead_blocks=2.5"), SetupError);
}

TEST(TimingStage, OperationsByComment) {
  // Each comment alone on its line starts an operation; the look-ahead runs through it (the
  // two 50 mm blocks are one 100 mm move: 0.55 s each). The title after O names nothing.
  ncvm::Setup s = dynamicSetup({"timing.tool_change_time=3", "timing.m_code_time=0"});
  std::string prog =
      "O1 (TITLE)\n(ROUGH)\nT1 M06\nG90 G21 G94 G01 X50. F6000.\n( FINISH )\nX100.\nT2 M06\n"
      "G01 X0\nM30\n";
  auto r = run(prog, s);
  const auto& ops = r.timing->operations();
  ASSERT_EQ(ops.size(), 3u);
  EXPECT_EQ(ops[0].label, "ROUGH");
  EXPECT_EQ(ops[1].label, "FINISH");  // trimmed
  EXPECT_EQ(ops[2].label, "");        // the tool change after moves starts an unnamed one
  EXPECT_EQ(ops[2].tool, 2);
  EXPECT_NEAR(ops[0].time.model, 3 + 0.55, 1e-12);
  EXPECT_NEAR(ops[1].time.model, 0.55, 1e-12);
  EXPECT_NEAR(ops[2].time.model, 3 + 1.1, 1e-12);
  EXPECT_EQ(r.state["timing"]["operations"][1]["start"]["line"], 5);
  EXPECT_TRUE(r.state["timing"]["operations"][2]["label"].is_null());
  // Off: operations by tool change only, the same total.
  ncvm::Setup off = s;
  applySetting(off, "timing.operation_comments=false");
  auto o = run(prog, off);
  ASSERT_EQ(o.timing->operations().size(), 2u);
  EXPECT_NEAR(o.timing->operations()[0].time.model, 3 + 1.1, 1e-12);
  EXPECT_NEAR(total(o), total(r), 1e-12);
  // The simple model splits the same way, with length / feed.
  auto simple = run(prog, defaultSetup());
  ASSERT_EQ(simple.timing->operations().size(), 3u);
  EXPECT_NEAR(simple.timing->operations()[1].time.model, 0.5, 1e-12);
}

// An operation is a place in the program: passing it again (an M99 loop, a bar feeder's
// next part) goes on with the same operation, so the list stays as long as the program.
TEST(TimeReport, LoopsGoOnWithTheOperationOfTheirPlace) {
  for (bool dynamic : {false, true}) {
    ncvm::Setup s = dynamic ? dynamicSetup() : defaultSetup();
    applySetting(s, "limits.max_blocks=4003");
    auto r = run(
        "O1\n(ROUGH)\nT1 M06\nG91 G01 X1. F600.\n(FINISH)\nG04 X0.5\nT2 M06\nG01 Y1.\nM99\n", s);
    const auto& ops = r.timing->operations();
    ASSERT_EQ(ops.size(), 3u) << "dynamic " << dynamic;
    EXPECT_EQ(ops[0].label, "ROUGH");
    EXPECT_EQ(ops[0].tool, 1);
    EXPECT_EQ(ops[1].label, "FINISH");
    EXPECT_EQ(ops[2].tool, 2);
    // 8 blocks a pass: 500 passes, and the 501st stopped after (ROUGH) T1 G01.
    EXPECT_EQ(ops[0].runs, 501u);
    EXPECT_EQ(ops[1].runs, 500u);
    EXPECT_EQ(ops[2].runs, 500u);
    EXPECT_NEAR(ops[1].time.model, 500 * 0.5, 1e-9);
    double sum = 0;
    for (const auto& o : ops) sum += o.time.model;
    EXPECT_NEAR(sum, total(r), 1e-9);
  }
}

// Operations start at tool changes and at the main program's comments outside loops: a
// comment in a WHILE body, an M98 subprogram or a G65 macro describes a step, not an
// operation (a drilling macro's "(END OF THE PECK)" started 14 operations in O9503).
TEST(TimeReport, CommentsInLoopsAndCallsStartNoOperation) {
  auto r =
      run("O1\n(FACE)\nT1 M06\nG90 G21 G94 G01 X10. F600.\n#1=0\nWHILE[#1LT3]DO1\n(PASS)\n"
          "G91 X1.\n#1=#1+1\nEND1\nG90\nM98 P100\nG65 P200\n(FINISH)\nG90 G01 X0\nM30\n"
          "O100\n(SUB STEP)\nG91 G01 Y1.\nM99\nO200\n(MACRO STEP)\nG91 G01 Y-1.\nM99\n",
          defaultSetup());
  const auto& ops = r.timing->operations();
  ASSERT_EQ(ops.size(), 2u);
  EXPECT_EQ(ops[0].label, "FACE");
  EXPECT_EQ(ops[1].label, "FINISH");
  // F600 = 10 mm/s: X10, three X1 in the loop, Y1 in O100, Y-1 in O200; then X13 -> X0.
  EXPECT_NEAR(ops[0].time.model, 1.5, 1e-12);
  EXPECT_NEAR(ops[1].time.model, 1.3, 1e-12);
}

// A hole: a feed along -Z, then a retract along Z at the same X Y. A pocket's plunge, left
// sideways at depth, is none; a hole drilled in one feed (G81) has no pecks; a peck is a
// feed after a retract within the hole. Its time runs from the first feed to the retract to
// the level the first feed started from after the last feed (what follows is not the hole's).
TEST(TimeReport, HolesPecksAndTheirTime) {
  auto pocket = run("O1\nG90 G21 G94 G00 X0 Y0 Z5.\nG01 Z-2. F300.\nX20.\nY20.\nG00 Z5.\nM30\n",
                    defaultSetup());
  EXPECT_EQ(pocket.timing->drilling().holes, 0u);
  EXPECT_EQ(pocket.timing->drilling().pecks, 0u);
  EXPECT_TRUE(pocket.timing->holes().empty());
  auto g81 = run("O1\nG90 G21 G94 G00 X0 Y0 Z10.\nG98 G81 X0 Y0 Z-10. R2. F300.\nX10.\nG80\nM30\n",
                 defaultSetup());
  EXPECT_EQ(g81.timing->drilling().holes, 2u);
  EXPECT_EQ(g81.timing->drilling().pecks, 0u);
  ASSERT_EQ(g81.timing->holes().size(), 2u);
  EXPECT_EQ(g81.timing->holes()[1].x, 10.0);

  MoveTimes m;
  auto r =
      run("O1\nG90 G21 G94 G00 X0 Y0 Z2.\nG01 Z-10. F600.\nG00 Z2.\nZ-9.\nG01 Z-20.\nG04 X1.\n"
          "G00 Z2.\nZ50.\nX10.\nM30\n",
          defaultSetup(), &m);
  ASSERT_EQ(m.time.size(), 8u);
  EXPECT_EQ(r.timing->drilling().holes, 1u);
  EXPECT_EQ(r.timing->drilling().pecks, 2u);
  EXPECT_EQ(r.timing->drilling().fullRetracts, 1u);
  ASSERT_EQ(r.timing->holes().size(), 1u);
  const HoleTime& h = r.timing->holes()[0];
  EXPECT_EQ(h.pecks, 2u);
  EXPECT_EQ(h.runs, 1u);
  // Feed, retract, back down, feed, dwell 1 s, retract to Z2; not Z50 nor X10.
  EXPECT_NEAR(h.time.model, m.time[1] + m.time[2] + m.time[3] + m.time[4] + 1 + m.time[5], 1e-12);
  // The same in the dynamic model (the feeds are planned after they arrive).
  MoveTimes d;
  auto dyn =
      run("O1\nG90 G21 G94 G00 X0 Y0 Z2.\nG01 Z-10. F600.\nG00 Z2.\nZ-9.\nG01 Z-20.\nG04 X1.\n"
          "G00 Z2.\nZ50.\nX10.\nM30\n",
          dynamicSetup(), &d);
  ASSERT_EQ(dyn.timing->holes().size(), 1u);
  EXPECT_NEAR(dyn.timing->holes()[0].time.model,
              d.time[1] + d.time[2] + d.time[3] + d.time[4] + 1 + d.time[5], 1e-12);
}

// The per-line table keeps times only: the top blocks' program and N come from the block on
// the line (a subprogram's line run three times, then the main program's).
TEST(TimeReport, TopBlocksNameTheirProgramAndN) {
  auto r =
      run("O1\nN10 G90 G21 G94 G01 X10. F600.\nM98 P100 L3\nM30\nO100\nN20 G91 G01 X20. "
          "F600.\nX1.\nM99\n",
          defaultSetup());
  const auto& top = r.state["timing"]["top_blocks"];
  ASSERT_GE(top.size(), 3u);
  EXPECT_EQ(top[0]["line"], 6);
  EXPECT_EQ(top[0]["prog"], "O0100");
  EXPECT_EQ(top[0]["n"], 20);
  EXPECT_EQ(top[0]["count"], 3);
  EXPECT_NEAR(top[0]["time"].get<double>(), 6.0, 1e-12);
  EXPECT_EQ(top[1]["line"], 2);
  EXPECT_EQ(top[1]["prog"], "O0001");
  EXPECT_EQ(top[1]["n"], 10);
  EXPECT_EQ(top[1]["count"], 1);
  EXPECT_EQ(top[2]["line"], 7);
  EXPECT_TRUE(top[2]["n"].is_null());
}

// The per-line table stores the simple time only once it differs from the model time (the
// simple model never does): the line sums must be those of two full columns either way.
TEST(TimeReport, LineSimpleTimesSplitFromTheModelOnlyWhenTheyDiffer) {
  TimeReport rep;
  const EventOrigin l1{0, 1, -1, nullptr}, l2{0, 2, -1, nullptr}, l3{0, 3, -1, nullptr};
  rep.addLineTime(l1, 0.1, 0.1);
  rep.addLineTime(l2, 0.3, 0.3);
  rep.addLineTime(l1, 0.2, 0.2);
  auto same = rep.topLines(3);
  ASSERT_EQ(same.size(), 2u);
  EXPECT_EQ(same[0].time.model, 0.1 + 0.2);
  EXPECT_EQ(same[0].time.simple, 0.1 + 0.2);
  EXPECT_EQ(same[1].time.simple, 0.3);
  rep.addLineTime(l2, 0.5, 0.25);  // the first difference
  rep.addLineTime(l3, 0.7, 0.7);
  rep.addLineTime(l1, 0.4, 0.4);
  rep.addLineTime(EventOrigin{0, 40, -1, nullptr}, 0.05, 0.01);  // past the table: it grows
  auto split = rep.topLines(4);
  ASSERT_EQ(split.size(), 4u);
  EXPECT_EQ(split[0].at.line, 2u);
  EXPECT_EQ(split[0].time.model, 0.3 + 0.5);
  EXPECT_EQ(split[0].time.simple, 0.3 + 0.25);
  EXPECT_EQ(split[1].at.line, 1u);
  EXPECT_EQ(split[1].time.model, 0.1 + 0.2 + 0.4);
  EXPECT_EQ(split[1].time.simple, 0.1 + 0.2 + 0.4);
  EXPECT_EQ(split[1].count, 3u);
  EXPECT_EQ(split[2].at.line, 3u);
  EXPECT_EQ(split[2].time.simple, 0.7);
  EXPECT_EQ(split[3].at.line, 40u);
  EXPECT_EQ(split[3].time.model, 0.05);
  EXPECT_EQ(split[3].time.simple, 0.01);
}
