#include <gtest/gtest.h>

#include <cmath>

#include "app/session.hpp"

using namespace ncvm;

namespace {
// Runs a program and returns variable #n from the state.
double var(const std::string& program, int n, Setup setup = defaultSetup()) {
  Session s(setup);
  s.addProgramText(program, "t.nc");
  auto r = s.run(nullptr);
  EXPECT_TRUE(r.state["alarm"].is_null()) << r.state["alarm"].dump();
  return r.state["vars"]["#" + std::to_string(n)].get<double>();
}
std::string alarmOf(const std::string& program) {
  Session s(defaultSetup());
  s.addProgramText(program, "t.nc");
  auto r = s.run(nullptr);
  return r.alarm ? r.alarm->code : "";
}
}  // namespace

TEST(Eval, PrecedenceFanucGrouping) {
  EXPECT_DOUBLE_EQ(var("O1\n#100=1+2*3\nM30\n", 100), 7);
  EXPECT_DOUBLE_EQ(var("O1\n#100=6 OR 1 AND 3\nM30\n", 100), 7);  // AND binds like *
  EXPECT_DOUBLE_EQ(var("O1\n#100=10-4-3\nM30\n", 100), 3);
}

TEST(Eval, TrigExactAtQuadrants) {
  EXPECT_DOUBLE_EQ(var("O1\n#100=COS[90]\nM30\n", 100), 0.0);
  EXPECT_EQ(alarmOf("O1\n#100=TAN[90]\nM30\n"), "PS0112");
}

// Whole angles of any size are reduced exactly (multiples of 90 exact, as above); any other
// angle is the sine of its radians, the same double as with fmod's reduction.
TEST(Eval, TrigOfLargeAndFractionalAngles) {
  constexpr double kDeg = 3.14159265358979323846 / 180.0;
  struct Case {
    const char* expr;
    double want;
  };
  const Case cases[] = {
      {"SIN[450]", 1.0},
      {"SIN[-450]", -1.0},
      {"COS[-270]", 0.0},
      {"SIN[36000]", 0.0},
      {"COS[36180]", -1.0},
      {"SIN[-630]", 1.0},
      {"SIN[123456789]", std::sin(123456789.0 * kDeg)},
      {"SIN[999999999999990]", -1.0},
      {"SIN[720.5]", std::sin(720.5 * kDeg)},
      {"COS[359.999]", std::sin(449.999 * kDeg)},
      {"SIN[-0.36]", std::sin(-0.36 * kDeg)},
      {"SIN[999999999999990*9]", -1.0},
      {"SIN[999999999999990*18]", 0.0},  // past 9e15: fmod's reduction
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.expr);
    EXPECT_EQ(var(std::string("O1\n#100=") + c.expr + "\nM30\n", 100), c.want);
  }
}

TEST(Eval, AtanRangeFollowsNat) {
  EXPECT_DOUBLE_EQ(var("O1\n#100=ATAN[-1]/[-1]\nM30\n", 100), 225);
  ncvm::Setup nat = defaultSetup();
  applySetting(nat, "NAT=1");
  EXPECT_DOUBLE_EQ(var("O1\n#100=ATAN[-1]/[-1]\nM30\n", 100, nat), -135);
}

TEST(Eval, RoundFixFup) {
  EXPECT_DOUBLE_EQ(var("O1\n#100=ROUND[-2.5]\nM30\n", 100), -3);
  EXPECT_DOUBLE_EQ(var("O1\n#100=FIX[-1.7]\nM30\n", 100), -1);
  EXPECT_DOUBLE_EQ(var("O1\n#100=FUP[-1.2]\nM30\n", 100), -2);
}

TEST(Eval, DomainAlarms) {
  EXPECT_EQ(alarmOf("O1\n#100=SQRT[-1]\nM30\n"), "PS0119");
  EXPECT_EQ(alarmOf("O1\n#100=1/0\nM30\n"), "PS0112");
  EXPECT_EQ(alarmOf("O1\n#100=LN[0]\nM30\n"), "PS0119");
  EXPECT_EQ(alarmOf("O1\n#100=EXP[1000]\nM30\n"), "PS0111");
}

TEST(Eval, VacantOnlyDistinguishedByEqNe) {
  EXPECT_DOUBLE_EQ(var("O1\n#100=0\nIF[#1EQ0]GOTO5\n#100=1\nN5M30\n", 100), 1);
  EXPECT_DOUBLE_EQ(var("O1\n#100=0\nIF[#1GE0]GOTO5\n#100=1\nN5M30\n", 100), 0);
}

// A computed GOTO may not jump into a loop it is not inside (the loop parents are looked up
// at run time; the compiler checks only literal targets), but may jump within its own loop
// and out of one.
TEST(Eval, ComputedGotoIntoALoop) {
  EXPECT_EQ(alarmOf("O1\n#1=10\nGOTO#1\nWHILE[#2LT2]DO1\nN10 #2=#2+1\nEND1\nM30\n"), "PS0126");
  EXPECT_EQ(alarmOf("O1\n#1=10\nWHILE[#3LT1]DO1\n#3=1\nGOTO#1\nEND1\nWHILE[#2LT2]DO2\n"
                    "N10 #2=#2+1\nEND2\nM30\n"),
            "PS0126");  // from inside one loop into another
  EXPECT_DOUBLE_EQ(var("O1\nWHILE[#2LT3]DO1\n#2=#2+1\n#1=20\nGOTO#1\n#3=99\nN20 #3=#3+1\nEND1\n"
                       "M30\n",
                       3),
                   3);
  EXPECT_DOUBLE_EQ(var("O1\nWHILE[#2LT3]DO1\n#2=#2+1\n#1=30\nGOTO#1\nEND1\nN30 #4=7\nM30\n", 4),
                   7);  // out of the loop
}
