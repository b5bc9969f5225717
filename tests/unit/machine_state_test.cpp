// The machine-state loader refuses what the control would not hold (G10's limits, the tip
// directions, finite numbers) with the key and the value, instead of wrapping it.
#include "app/machine_state.hpp"

#include <gtest/gtest.h>

using namespace ncvm;

namespace {
nlohmann::json stateWith(const char* section, nlohmann::json body) {
  nlohmann::json j = {{"format", "ncvm-machine-state/1"}, {"units", "mm"}};
  j[section] = std::move(body);
  return j;
}

std::string refusal(const nlohmann::json& j, const Setup& setup) {
  MachineMemory mem;
  try {
    memoryFromJson(j, setup, mem);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "accepted";
}

Setup lathe() {
  Setup s = defaultSetup();
  applySetting(s, "machine.kind=lathe");
  return s;
}
}  // namespace

TEST(MachineState, OutOfRangeWorkOffsetIsRefusedWithItsKeyAndValue) {
  const std::string why =
      refusal(stateWith("work_offsets", {{"G54", {{"X", 1e13}}}}), defaultSetup());
  EXPECT_NE(why.find("work_offsets.G54.X"), std::string::npos) << why;
  EXPECT_NE(why.find("10000000000000"), std::string::npos) << why;
  EXPECT_NE(why.find("99999.999"), std::string::npos) << why;
  // The limit itself loads, and comes back as it was.
  MachineMemory mem;
  memoryFromJson(stateWith("work_offsets", {{"G54", {{"X", -99999.999}}}}), defaultSetup(), mem);
  EXPECT_EQ(memoryToJson(mem, defaultSetup())["work_offsets"]["G54"]["X"].get<double>(),
            -99999.999);
}

TEST(MachineState, ToolOffsetsAndTipsKeepTheControlsLimits) {
  EXPECT_NE(refusal(stateWith("tool_offsets", {{"1", {{"h_geometry", 1000.5}}}}), defaultSetup())
                .find("tool_offsets.1.h_geometry = 1000.5"),
            std::string::npos);
  for (double tip : {1e300, -7.0, 99.0, 2.5}) {
    const std::string why = refusal(stateWith("tool_offsets", {{"3", {{"tip", tip}}}}), lathe());
    EXPECT_NE(why.find("tool_offsets.3.tip"), std::string::npos) << tip << ": " << why;
  }
  MachineMemory mem;
  memoryFromJson(stateWith("tool_offsets", {{"3", {{"tip", 9}, {"x_geometry", 1999.998}}}}),
                 lathe(), mem);
  EXPECT_EQ(mem.tools[3].tip, 9);
  EXPECT_EQ(mem.tools[3].geometry[kFieldXorH], 999'999'000);  // a diameter: the radius is stored
}

TEST(MachineState, VariablesAndCountersAreFiniteNumbersInRange) {
  EXPECT_NE(refusal(stateWith("vars", {{"#1000", 1}}), defaultSetup()).find("vars.#1000"),
            std::string::npos);
  EXPECT_NE(refusal(stateWith("vars", {{"#500x", 1}}), defaultSetup()).find("vars.#500x"),
            std::string::npos);
  EXPECT_NE(refusal(stateWith("vars", {{"#500", "1"}}), defaultSetup()).find("not a number"),
            std::string::npos);
  EXPECT_NE(refusal(stateWith("parts", {{"#3901", "x"}}), defaultSetup()).find("parts.#3901"),
            std::string::npos);
  EXPECT_NE(refusal(stateWith("bogus", 1), defaultSetup()).find("bogus"), std::string::npos);
  EXPECT_NE(refusal(stateWith("tool_offsets", {{"1", {{"x_geometry", 1}}}}), defaultSetup())
                .find("tool_offsets.1.x_geometry"),
            std::string::npos);  // a lathe field in a mill's file
}
