#pragma once
// What the control keeps through power-off (fanuc-reference B.10): work offsets, tool
// offsets, common variables #500-#999 and the part counters. Lengths are integer nm like
// positions (lathe X as a radius), so offsets add to positions without rounding.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "canon/events.hpp"
#include "core/value.hpp"

namespace ncvm {

// Work offset table index: 0 = EXT (external work zero offset), 1..6 = G54..G59,
// 7.. = G54.1 P1..P300.
constexpr int kWorkExt = 0;
constexpr int kWorkG54 = 1;
constexpr int kWorkP1 = 7;
constexpr int kWorkTables = kWorkP1 + 300;
std::string workOffsetName(int index);         // "EXT", "G54", "G54.1 P7"
int workOffsetIndex(const std::string& name);  // -1 if not a work offset name

// One tool offset number. Mill (memory C): field 0 = H (length), 2 = D (radius).
// Lathe: 0 = X, 1 = Z, 2 = R (nose radius), 3 = Y; `tip` = imaginary tip direction.
enum ToolField : int { kFieldXorH = 0, kFieldZ = 1, kFieldRorD = 2, kFieldY = 3 };
struct ToolOffsetRow {
  std::array<int64_t, 4> geometry{};
  std::array<int64_t, 4> wear{};
  int tip = 0;
  bool empty() const;
};
constexpr int kToolRows = 1000;  // numbers 0..999 (0 = no offset)

struct MachineMemory {
  std::vector<std::array<int64_t, kMaxAxes>> work =
      std::vector<std::array<int64_t, kMaxAxes>>(kWorkTables);
  std::vector<ToolOffsetRow> tools = std::vector<ToolOffsetRow>(kToolRows);
  std::array<Value, 500> common500{};
  double parts3901 = 0, parts3902 = 0;
};

}  // namespace ncvm
