// The macro variable component on its own: no program, no Executor.
#include "exec/macro_variables.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "core/alarm.hpp"

using namespace ncvm;

namespace {
std::string alarmCode(const std::function<void()>& f) {
  try {
    f();
  } catch (const AlarmError& e) {
    return e.code();
  }
  return "";
}

MacroVariables::Locals argsWith(int n, double v) {
  MacroVariables::Locals a{};
  a[static_cast<size_t>(n - 1)] = Value::num(v);
  return a;
}
}  // namespace

TEST(MacroVariables, StartVacantAndZeroIsAlwaysVacant) {
  std::array<Value, 500> c500{};
  MacroVariables vars(c500, false);
  EXPECT_TRUE(vars.read(0, 0).null);
  EXPECT_TRUE(vars.read(1, 0).null);
  EXPECT_TRUE(vars.read(100, 0).null);
  EXPECT_TRUE(vars.read(999, 0).null);
  EXPECT_EQ(alarmCode([&] { vars.write(0, Value::num(1), 0); }), "PS0116");
}

TEST(MacroVariables, LocalsBelongToTheirLevel) {
  std::array<Value, 500> c500{};
  MacroVariables vars(c500, false);
  vars.write(1, Value::num(7), 0);
  vars.enterCall(1, argsWith(1, 3), {});
  EXPECT_EQ(vars.read(1, 1).v, 3);
  vars.write(2, Value::num(5), 1);
  EXPECT_EQ(vars.read(1, 0).v, 7);  // the caller's #1 is untouched
  EXPECT_TRUE(vars.read(2, 0).null);
  EXPECT_EQ(vars.read(2, 1).v, 5);
}

TEST(MacroVariables, CommonVariablesAreSharedByEveryLevel) {
  std::array<Value, 500> c500{};
  MacroVariables vars(c500, false);
  vars.write(100, Value::num(1.5), 2);
  EXPECT_EQ(vars.read(100, 0).v, 1.5);
  EXPECT_EQ(vars.common100()[0].v, 1.5);
  vars.write(500, Value::num(4), 1);
  EXPECT_EQ(vars.read(500, 3).v, 4);
}

// #500-#999 live in the machine's persistent memory: the component writes through to it.
TEST(MacroVariables, Common500IsTheMemorysArray) {
  std::array<Value, 500> c500{};
  c500[499] = Value::num(9);
  MacroVariables vars(c500, false);
  EXPECT_EQ(vars.read(999, 0).v, 9);
  vars.write(501, Value::num(2), 0);
  EXPECT_FALSE(c500[1].null);
  EXPECT_EQ(c500[1].v, 2);
}

TEST(MacroVariables, Common200NeedsItsOption) {
  std::array<Value, 500> c500{};
  MacroVariables without(c500, false);
  EXPECT_EQ(alarmCode([&] { (void)without.read(200, 0); }), "PS0115");
  EXPECT_EQ(alarmCode([&] { without.write(499, Value::num(1), 0); }), "PS0115");
  MacroVariables with(c500, true);
  with.write(499, Value::num(1), 0);
  EXPECT_EQ(with.read(499, 0).v, 1);
}

TEST(MacroVariables, NumbersThatAreNotVariablesAlarm) {
  std::array<Value, 500> c500{};
  MacroVariables vars(c500, true);
  EXPECT_EQ(alarmCode([&] { (void)vars.read(34, 0); }), "PS0115");
  EXPECT_EQ(alarmCode([&] { (void)vars.read(99, 0); }), "PS0115");
  EXPECT_EQ(alarmCode([&] { (void)vars.read(-1, 0); }), "PS0115");
  EXPECT_EQ(alarmCode([&] { vars.write(50, Value::num(1), 0); }), "PS0115");
}

TEST(MacroVariables, ValuesThatAreNotFiniteOverflow) {
  std::array<Value, 500> c500{};
  MacroVariables vars(c500, false);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(alarmCode([&] { vars.write(100, Value::num(inf), 0); }), "PS0111");
  EXPECT_EQ(alarmCode([&] { vars.write(1, Value::num(std::nan("")), 0); }), "PS0111");
  vars.write(100, Value::vacant(), 0);  // vacant is a value
  EXPECT_TRUE(vars.read(100, 0).null);
}

// An L repeat of a macro call starts again from the call's arguments and ADP scales.
TEST(MacroVariables, RepeatRestoresTheCallsArgumentsAndScales) {
  std::array<Value, 500> c500{};
  MacroVariables vars(c500, false);
  MacroVariables::Scales scale{};
  scale[0] = 1000;
  vars.enterCall(1, argsWith(1, 0.002), scale);
  EXPECT_EQ(vars.noPointScale(1, 1), 1000);
  vars.write(1, Value::num(8), 1);
  EXPECT_EQ(vars.noPointScale(1, 1), 0);  // a value the macro set is not scaled
  vars.repeatCall(1);
  EXPECT_EQ(vars.read(1, 1).v, 0.002);
  EXPECT_EQ(vars.noPointScale(1, 1), 1000);
  EXPECT_EQ(vars.noPointScale(1, 40), 0);  // not a local
}

TEST(MacroVariables, UserVariablesListLevelZeroAndCommonsInOrder) {
  std::array<Value, 500> c500{};
  MacroVariables vars(c500, true);
  vars.write(501, Value::num(5), 0);
  vars.write(3, Value::num(1), 0);
  vars.write(250, Value::num(4), 0);
  vars.write(100, Value::num(2), 0);
  vars.enterCall(1, argsWith(2, 9), {});  // a macro's locals are not the program's state
  const std::vector<std::pair<int, double>> expected{{3, 1}, {100, 2}, {250, 4}, {501, 5}};
  EXPECT_EQ(vars.userVariables(), expected);
}
