// The interface signal component on its own: a SignalSpec, no program, no Executor.
#include "exec/interface_signals.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/alarm.hpp"

using namespace ncvm;

TEST(InterfaceSignals, EachReadTakesTheNextValueAndTheLastRepeats) {
  SignalSpec spec;
  spec.inputs[1001] = {0, 1};
  InterfaceSignals s(spec);
  std::string warning;
  EXPECT_EQ(s.readInput(1001, warning), 0);
  EXPECT_EQ(s.readInput(1001, warning), 1);
  EXPECT_EQ(s.readInput(1001, warning), 1);
  EXPECT_TRUE(warning.empty());
}

TEST(InterfaceSignals, BitsAndTheWordStandForEachOther) {
  SignalSpec word;
  word.inputs[1032] = {5};  // UI000 and UI002 on
  InterfaceSignals fromWord(word);
  std::string warning;
  EXPECT_EQ(fromWord.readInput(1000, warning), 1);
  EXPECT_EQ(fromWord.readInput(1001, warning), 0);
  EXPECT_EQ(fromWord.readInput(1002, warning), 1);
  SignalSpec bits;
  bits.inputs[1000] = {1};
  bits.inputs[1003] = {1};
  InterfaceSignals fromBits(bits);
  EXPECT_EQ(fromBits.readInput(1032, warning), 9);
  EXPECT_TRUE(warning.empty());
}

TEST(InterfaceSignals, AMissingInputReadsZeroWarnsOnceOrAlarms) {
  SignalSpec spec;
  InterfaceSignals s(spec);
  std::string warning;
  EXPECT_EQ(s.readInput(1005, warning), 0);
  EXPECT_NE(warning.find("UI005"), std::string::npos);
  warning.clear();
  EXPECT_EQ(s.readInput(1005, warning), 0);
  EXPECT_TRUE(warning.empty());  // said once
  spec.missingAlarm = true;
  InterfaceSignals strict(spec);
  EXPECT_THROW(strict.readInput(1005, warning), AlarmError);
}

TEST(InterfaceSignals, OutputsAsBitsAndWords) {
  SignalSpec spec;
  InterfaceSignals s(spec);
  EXPECT_EQ(s.writeOutput(1101, Value::num(7)), 1);  // any value but 0 is on
  EXPECT_EQ(s.outputs(0), 2u);
  EXPECT_EQ(s.readOutput(1101), 1);
  EXPECT_EQ(s.readOutput(1132), 2);
  EXPECT_EQ(s.writeOutput(1101, Value::vacant()), 0);  // vacant is off
  EXPECT_EQ(s.outputs(0), 0u);
  EXPECT_EQ(s.writeOutput(1133, Value::num(-1)), 4294967295.0);  // two's complement
  EXPECT_EQ(s.outputs(1), 0xffffffffu);
  EXPECT_THROW(s.writeOutput(1132, Value::num(4294967296.0)), AlarmError);
  EXPECT_EQ(s.outputs(0), 0u);  // a refused write changes nothing
}
