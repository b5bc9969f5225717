// The executor's straight path for plain G01 blocks (src/exec/straight_move.cpp) against the
// general path it bypasses: the same programs on the same setups, run with the path on and
// off, give the same trace and state byte for byte, alarms included.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/session.hpp"
#include "exec/straight_path.hpp"
#include "report/trace_writer.hpp"

using namespace ncvm;

namespace {

struct Outcome {
  std::string trace, state;
  uint64_t straight = 0;  // blocks the straight path ran
};

Outcome run(const ncvm::Setup& setup, const std::string& text, bool straight) {
  straightPathEnabled = straight;
  const uint64_t before = straightPathMoves;
  Session s(setup);
  s.addProgramText(text, "t.nc");
  TraceWriter writer(s.files(), nullptr, uint64_t{1} << 30, s.setup().reportedAxes());
  Session::Result r = s.run(&writer);
  straightPathEnabled = true;
  return Outcome{writer.buffer(), r.state.dump(), straightPathMoves - before};
}

void expectSame(const ncvm::Setup& setup, const std::string& text, const std::string& what,
                bool straightRuns = true) {
  const Outcome fast = run(setup, text, true), general = run(setup, text, false);
  EXPECT_EQ(fast.state, general.state) << what;
  EXPECT_EQ(fast.trace, general.trace) << what;
  if (straightRuns) {
    EXPECT_GT(fast.straight, 0u) << what;
  }
  EXPECT_EQ(general.straight, 0u) << what;
}

ncvm::Setup fromToml(const std::string& toml) {
  return parseSetup(toml, "straight.toml");
}

// Plain blocks in every state the straight path must either take exactly or leave alone:
// offsets and their changes, G91, no-point values, F with and without a point, G61, feed per
// revolution, rotary axes moved by other blocks, comments, N numbers, block skip, macro
// writes of the work offset, arcs and rapids in between.
const char* kStates =
    "O0001\n"
    "G90 G21 G17 G40 G49 G80 G54 G94\n"
    "G10 L2 P1 X100. Y50. Z-20.\n"
    "G10 L2 P2 X-30.5 Y12.25 Z3.\n"
    "G10 L10 P1 R50.\n"
    "S1000 M03\n"
    "G00 X0 Y0 Z5.\n"
    "G01 Z0 F3000.\n"
    "X10.5 Y3.25 Z-1.\n"
    "X11 Y4\n"                   // no point: increments
    "N100 X12.001 Y4.5 F2500\n"  // F without a point
    "/X13. Y5.\n"
    "G1 X14.123 Y-6.789 Z-2.5\n"
    "(OPERATION TWO)\n"
    "G55\n"
    "X1. Y2. Z3.\n"
    "X1.5 Y2.5\n"
    "#5221=7.5\n"
    "X2. Y3.\n"
    "G54 X2.5 Y3.5\n"
    "G91 X1. Y-1. Z0.5\n"
    "X0.001 Y0.002\n"
    "G90 X20. Y20.\n"
    "G61 X21. Y21.\n"
    "X22. Y22.\n"
    "G64 X23.\n"
    "G02 X25. Y20. R5.\n"
    "X26. Y19.\n"
    "G01 X27. Y18.\n"
    "G00 X30. Y10.\n"
    "G01 X31. Y11. F1500.\n"
    "G43 H1 Z10.\n"
    "X32. Y12. Z9.\n"
    "G49 Z20.\n"
    "X33.\n"
    "G92 X0 Y0\n"
    "X1. Y1.\n"
    "G52 X5. Y5.\n"
    "X2. Y2.\n"
    "G52 X0 Y0\n"
    "G95 F0.1\n"
    "X3. Y3.\n"
    "F.2 X4. Y4.\n"
    "G94 F1000.\n"
    "X5. Y5.\n"
    "M30\n";

}  // namespace

TEST(StraightMove, SameAsTheGeneralPathInEveryMillState) {
  ncvm::Setup setup = defaultSetup();
  expectSame(setup, kStates, "mill mm");
  ncvm::Setup inch = fromToml("[machine]\nunits = \"inch\"\n");
  expectSame(inch, kStates, "mill inch");
  ncvm::Setup isc = fromToml("[machine]\nincrement = \"IS-C\"\n");
  expectSame(isc, kStates, "IS-C");
  ncvm::Setup dpi = fromToml("DPI = 1\n");
  expectSame(dpi, kStates, "DPI");
}

TEST(StraightMove, UnitChangesAndRotaryAxesMovedByOtherBlocks) {
  ncvm::Setup setup = fromToml("[axes.A]\nrapid = 3600\n[axes.C]\nrotary = false\n");
  const std::string text =
      "O0002\nG90 G21 G54\nG01 X1. Y1. F1000.\nG00 A90.\nG01 X2. Y2.\nX3. Y3. Z-1.\n"
      "G10 L2 P1 A10. C2.\nX4.\nG01 A45. C1. X5.\nX6. Y6.\nG20\nX0.5 Y0.5\nX0.6\nG21\nX7. Y7.\n"
      "M30\n";
  expectSame(setup, text, "rotary and unit changes");
}

TEST(StraightMove, StrokeLimitsAlarmAtTheSameBlock) {
  for (const char* unit : {"mm", "inch"}) {
    ncvm::Setup setup = fromToml(fmt::format(
        "[machine]\nunits = \"{}\"\n[axes.X]\nmin = -10.0\nmax = 25.4\n[axes.Y]\nmax = 0.001\n",
        unit));
    // Exactly at the limit passes; one increment beyond alarms.
    expectSame(setup, "O0003\nG90 G01 F100.\nX1.\nX1.0000\nY0.001\nX25.4\nX25.401\nM30\n",
               std::string("at the limit, ") + unit);
    expectSame(setup, "O0003\nG90 G20 G01 F10.\nX1.\nX0.9999\nX1.0001\nM30\n",
               std::string("inch limit, ") + unit);
    expectSame(setup,
               "O0003\nG90 G01 F100.\nX-0.39\nX-0.3937\nX-0.3938\nX-9.999\nX-10.\nX-10.001\nM30\n",
               std::string("min limit, ") + unit);
  }
}

TEST(StraightMove, FeedAlarmsAndMissingAxes) {
  ncvm::Setup setup = defaultSetup();
  expectSame(setup, "O0004\nG90 G00 X1.\nG01 X2. Y2.\nM30\n", "no F", false);
  expectSame(setup, "O0004\nG90\nG01 F100. X1.\nX2. F-5.\nM30\n", "negative F");
  ncvm::Setup noY = fromToml("[axes.Y]\npresent = false\n");
  expectSame(noY, "O0004\nG90 G01 F100. X1.\nX2. Z1.\nZ2.\nM30\n", "no Y axis");
}

// Arcs in G17: I/J, R (short and long way), a full circle, helices, modal G02/G03, incremental,
// inch, no-point values, and the alarms of the general path (radius tolerance, R too small,
// the centre on the start point, no R/I/J, F missing), plus what it must leave alone (G18,
// K, a zero-length R arc).
TEST(StraightMove, ArcsAsTheGeneralPathCutsThem) {
  const std::string arcs =
      "O0005\nG90 G21 G17 G54 G94\nG10 L2 P1 X10. Y-5. Z2.\nG00 X0 Y0 Z1.\nG01 Z0 F800.\n"
      "G02 X10. Y0 I5. J0\nG03 X0 Y0 I-5.\nX10. R5.\nG02 X0 Y0 R-5.\nG02 I5.\n"
      "G03 X5. Y5. Z-2. I0 J5.\nG02 X10. Y0 R5.0001 F600\nG01 X12.\nG03 X14. Y2. J2.\n"
      "X12. Y4. I-2. F700.\nG91 G02 X2. Y-2. R2.\nG03 X-2. Y2. I0 J2.\nG90\n"
      "G02 X20000 Y0 R5000\nG18 G02 X25. Z-5. R5.\nG17\nG02 X30. Y0 Z-4. I2.5 K1.\n"
      "G02 X30. Y0 R5.\nG01 X40. Y10.\nM30\n";
  expectSame(defaultSetup(), arcs, "arcs mm");
  expectSame(fromToml("[machine]\nunits = \"inch\"\n"), arcs, "arcs inch");
  expectSame(fromToml("DPI = 1\n"), arcs, "arcs DPI");
  ncvm::Setup setup = defaultSetup();
  expectSame(setup, "O0006\nG90 G01 X0 Y0 F100.\nG02 X10. Y0 I5.2\nM30\n", "radius tolerance",
             false);
  expectSame(setup, "O0006\nG90 G01 X0 Y0 F100.\nG02 X10. Y0 R4.\nM30\n", "R too small", false);
  expectSame(setup, "O0006\nG90 G01 X0 Y0 F100.\nG02 X10. Y0 I0 J0\nM30\n", "centre on start",
             false);
  expectSame(setup, "O0006\nG90 G01 X0 Y0 F100.\nG02 X10. Y0\nM30\n", "no R, I or J", false);
  expectSame(setup, "O0006\nG90 G00 X0 Y0\nG02 X10. Y0 R5.\nM30\n", "no F", false);
  expectSame(fromToml("[axes.X]\nmax = 8.0\n"),
             "O0006\nG90 G01 X0 Y0 F100.\nG02 X10. Y0 R5.\nM30\n", "arc over travel", false);
  expectSame(
      setup,
      "O0006\nG90 G01 X0 Y0 F100.\nG02 X10. Y0 R5.\nG02 X10. Y0 Z-1. R5.\nX20. Y0 R5.\nM30\n",
      "zero-length R arc");
}

// Rapids: dog-leg (LRP = 0, the default) with axes at different rates, equal times, one axis,
// G91, offsets, inch, a rotary axis standing elsewhere, straight-line rapids (LRP = 1), a
// rapid's stroke alarm, F in a G00 block (no feed alarm for a rapid), and moves after a
// dog-leg (its corner points must not stay in the reused event).
TEST(StraightMove, RapidsAsTheGeneralPathMovesThem) {
  const std::string rapids =
      "O0007\nG90 G21 G17 G54 G94\nG10 L2 P1 X10. Y-5. Z2.\nG00 X0 Y0 Z1.\nX100. Y30. Z-20.\n"
      "X50. Y80.\nX60.\nY10. Z10.\nX-20. Y-20. Z-20.\nG01 X-19. F500.\nG00 X10. Y10. F800.\n"
      "G02 X20. Y10. R5.\nG00 X0 Y0 Z50.\nG91 X12.5 Y-3.25 Z-1.\nX0.001\nG90\nG55 X1. Y1.\n"
      "G54\nG00 A30.\nX3. Y4. Z5.\nG20 X1. Y1.\nX0.5 Y2.\nG21\nG00 X5 Y7\n"
      "S1000 M03\nG95 F0.2\nG00 X7. Y8.\nG01 X8. F.1\nG00 X9.\nG94 F500.\nM30\n";
  ncvm::Setup rates =
      fromToml("[axes.X]\nrapid = 30000\n[axes.Y]\nrapid = 24000\n[axes.Z]\nrapid = 15000\n");
  expectSame(rates, rapids, "dog-leg, different rates");
  expectSame(defaultSetup(), rapids, "dog-leg, default rates");
  expectSame(fromToml("LRP = 1\n"), rapids, "linear rapids");
  expectSame(fromToml("[machine]\nunits = \"inch\"\n"), rapids, "rapids inch");
  ncvm::Setup dynamic = fromToml("[timing]\nmodel = \"dynamic\"\n");
  expectSame(dynamic, rapids, "rapids, dynamic time model");
  ncvm::Setup noZRate = fromToml("[axes.Z]\nrapid = 0\n");
  expectSame(noZRate, rapids, "an axis without a rapid rate");
  expectSame(fromToml("[axes.Y]\nmax = 50.0\n"), rapids, "rapid over travel", false);
  expectSame(defaultSetup(), "O0008\nG90 G00 X1. F0\nX2. Y3.\nG00 F-1. X3.\nM30\n", "F in rapids");
}

// Blocks whose words are #variables or expressions, as macros write them: the straight path
// reads them as gatherWords does (a vacant variable drops its word, a value counts as given
// with a decimal point, -#1, [expressions]), and leaves G#1, repeated letters and K to the
// general path. Alarms: a value out of range, a bad variable number, a division by zero.
TEST(StraightMove, VariableWordsAsTheGeneralPathReadsThem) {
  const std::string vars =
      "O0009\nG90 G21 G17 G54 G94\n#1=12.3456789\n#2=-4.5\n#3=1500\n#4=5.\n#5=2\n"
      "G00 X#1 Y#2 Z5.\nG01 Z-#4 F#3\nX[#1+1] Y[#2*2]\nX#30 Y3.\nX#30\nG#5 X20. Y0 R#4\n"
      "G03 X[#4*2.8] Y0 I-3. J#30\nG01 X-#1 Y-#2 F[#3/2]\n#6=0\nWHILE[#6LT20]DO1\n"
      "#7=#6*18\nG01 X[10*COS[#7]] Y[10*SIN[#7]] Z-1.\nG02 X[10*COS[#7+9]] Y[10*SIN[#7+9]] R10.\n"
      "#6=#6+1\nEND1\nG00 X0 Y0 Z#4\nG01 X#1 X#2 F100.\nG01 X1. K#4\nG01 X#1 Y5. ,R1.\nX30.\n"
      "G91 X#5 Y#5\nG90 G20 X#5 Y1.\nG21 G01 X1 F#3\nM30\n";
  expectSame(defaultSetup(), vars, "variable words mm");
  expectSame(fromToml("[machine]\nunits = \"inch\"\n"), vars, "variable words inch");
  expectSame(fromToml("DPI = 1\n"), vars, "variable words DPI");
  const Outcome fast = run(defaultSetup(), vars, true);
  EXPECT_GT(fast.straight, 45u) << "the loop's G01 and G02 blocks take the straight path";
  ncvm::Setup setup = defaultSetup();
  expectSame(setup, "O0010\nG90 G01 F100.\n#1=10000000*1000000\nX1.\nX#1\nM30\n",
             "value out of range");
  expectSame(setup, "O0010\nG90 G01 F100.\n#1=0\nX1.\nX[1/#1]\nM30\n", "division by zero");
  expectSame(setup, "O0010\nG90 G01 F100.\nX1.\nY#[-5]\nM30\n", "bad variable number");
  expectSame(setup, "O0010\nG90 G01 F100.\n#1=-5\nX1.\nF#1 X2.\nM30\n", "negative F");
}

// A run of straight blocks (Executor::straightRun) keeps step()'s bookkeeping per block: the
// block and time limits alarm at the same block, block skip is decided as before, and a plain
// block the straight path refuses in the middle of a run (K, G18) runs the
// general way, the run going on after it.
TEST(StraightMove, RunsOfStraightBlocksKeepTheBlockBookkeeping) {
  const std::string run =
      "O0011\nG90 G21 G17 G54 G94 G01 F1000.\nN10 X1. Y1.\nX2.\nN30 X3. Y2.\n#101=#4114\n/X4. "
      "Y3.\n/2 X5.\n"
      "X6. Y4.\nG18 G02 X8. Z0 R1.\nG17\nX9.\nX10. K1.\nX11. Y5.\nG00 X0 Y0\nM30\n";
  expectSame(defaultSetup(), run, "a run");
  expectSame(fromToml("[block_skip]\n1 = true\n"), run, "block skip 1");
  expectSame(fromToml("[block_skip]\n2 = true\n"), run, "block skip 2");
  for (int limit : {3, 4, 5, 6, 9, 12})
    expectSame(fromToml(fmt::format("[limits]\nmax_blocks = {}\n", limit)), run,
               fmt::format("max_blocks {}", limit), false);
  for (double seconds : {0.05, 0.2, 0.5})
    expectSame(fromToml(fmt::format("[limits]\nmax_time_s = {}\n", seconds)), run,
               fmt::format("max_time_s {}", seconds), false);
}
