// Where the stock sits (stock.frame, sim/stock_frame.hpp): the shift from the work
// coordinates in use to the stock's, as work zero moves.
#include "sim/stock_frame.hpp"

#include <gtest/gtest.h>

using namespace ncvm;

namespace {
WorkOriginEvent origin(double x, double y, double z) {
  WorkOriginEvent e;
  e.mm = {x, y, z};
  return e;
}
MoveEvent move(MoveMode mode) {
  MoveEvent e;
  e.mode = mode;
  e.start = {10, 0, 0, 0, 0, 0};
  e.end = {20, 0, -5, 0, 0, 0};
  return e;
}
}  // namespace

TEST(StockFrame, WorkFollowsWorkZeroUntilTheFirstFeedMoveThenStaysOnTheMachine) {
  StockFrame f(StockFrame::Kind::Work, 1.0, false);
  f.origin(origin(100, 0, 0));
  f.move(move(MoveMode::Rapid));  // a rapid does not fix it
  f.origin(origin(120, 0, -10));  // e.g. G55 or G50 before the first cut
  EXPECT_FALSE(f.shifted());
  f.move(move(MoveMode::Linear));  // the first cut: fixed in the work system it runs in
  f.origin(origin(125, 0, -10));   // #5221 written after cutting: work zero moved +5 in X
  ASSERT_TRUE(f.shifted());
  EXPECT_DOUBLE_EQ(f.shift()[0], 5);  // work X0 is stock X5 now
  EXPECT_DOUBLE_EQ(f.shift()[2], 0);
  MoveEvent scratch;
  const MoveEvent& placed = f.place(move(MoveMode::Linear), scratch);
  EXPECT_DOUBLE_EQ(placed.start[0], 15);
  EXPECT_DOUBLE_EQ(placed.end[0], 25);
  EXPECT_DOUBLE_EQ(placed.end[2], -5);
  f.origin(origin(120, 0, -10));  // back: nothing shifted, the move itself comes back
  EXPECT_FALSE(f.shifted());
  MoveEvent m = move(MoveMode::Linear);
  EXPECT_EQ(&f.place(m, scratch), &m);
}

TEST(StockFrame, MachineCountsFromMachineZeroInProgramUnits) {
  // An inch stock on a lathe: work zero at machine X radius 25.4 mm, Z -50.8 mm is 1 in and
  // -2 in; MoveEvent X is a diameter, so X moves by 2 in, the arc centre and the compensated
  // points with it; machine coordinates stay.
  StockFrame f(StockFrame::Kind::Machine, 1 / 25.4, true);
  f.origin(origin(25.4, 0, -50.8));
  ASSERT_TRUE(f.shifted());
  MoveEvent e = move(MoveMode::Cw);
  e.arc = true;
  e.center = {15, 0, -2};
  e.compensated = true;
  e.programmedEnd = {19, 0, -5, 0, 0, 0};
  e.mend = {7, 0, 7, 0, 0, 0};
  MoveEvent scratch;
  const MoveEvent& p = f.place(e, scratch);
  EXPECT_DOUBLE_EQ(p.start[0], 12);
  EXPECT_DOUBLE_EQ(p.end[2], -7);
  EXPECT_DOUBLE_EQ(p.center[0], 17);
  EXPECT_DOUBLE_EQ(p.center[2], -4);
  EXPECT_DOUBLE_EQ(p.programmedEnd[0], 21);
  EXPECT_DOUBLE_EQ(p.mend[0], 7);
}

TEST(StockFrame, ProgramFollowsEveryChangeOfWorkZero) {
  StockFrame f(StockFrame::Kind::Program, 1.0, false);
  f.move(move(MoveMode::Linear));
  f.origin(origin(5, 6, 7));
  EXPECT_FALSE(f.shifted());
}

TEST(StockFrame, NamesTheSetupTakes) {
  StockFrame::Kind k{};
  EXPECT_TRUE(StockFrame::parse("work", k));
  EXPECT_EQ(k, StockFrame::Kind::Work);
  EXPECT_TRUE(StockFrame::parse("machine", k));
  EXPECT_EQ(k, StockFrame::Kind::Machine);
  EXPECT_TRUE(StockFrame::parse("program", k));
  EXPECT_EQ(k, StockFrame::Kind::Program);
  EXPECT_FALSE(StockFrame::parse("G54", k));
}
