#include "exec/gcode_table.hpp"

namespace ncvm {
namespace {
constexpr uint8_t M = seriesBit(Series::M);
constexpr uint8_t TA = seriesBit(Series::TA);
constexpr uint8_t TB = seriesBit(Series::TB);
constexpr uint8_t TC = seriesBit(Series::TC);
constexpr uint8_t T = TA | TB | TC;
constexpr uint8_t ALL = M | T;
constexpr GStatus S = GStatus::Supported;
constexpr GStatus A = GStatus::Accepted;
constexpr GStatus N = GStatus::NotYet;
}  // namespace

// Group numbers follow #4001-#4030 of each series. Lathe groups differ from the mill:
// G96/G97 is group 2, G17-G19 group 16, G98/G99 (system A feed) group 5.
const std::vector<GCodeInfo>& gcodeTable() {
  static const std::vector<GCodeInfo> table = {
      {0, ALL, 1, S, "positioning (rapid)"},
      {10, ALL, 1, S, "linear interpolation"},
      {20, ALL, 1, S, "circular interpolation CW (helical with a third axis)"},
      {30, ALL, 1, S, "circular interpolation CCW"},
      {40, ALL, 0, S, "dwell (X/U seconds, P milliseconds)"},
      {51, ALL, 0, A, "AI contour control / high-precision mode (no effect on the path)"},
      {71, ALL, 0, N, "cylindrical interpolation"},
      {80, ALL, 0, A, "look-ahead control (no effect on the path)"},
      {90, ALL, 0, S, "exact stop (one block)"},
      {100, ALL, 0, S, "programmable data input: L2/L20 work offsets, L10-L13 tool offsets, lathe P form"},
      {110, ALL, 0, A, "programmable data input cancel"},
      {121, ALL, 21, N, "polar coordinate interpolation"},
      {131, ALL, 21, S, "polar coordinate interpolation cancel"},
      {150, M, 17, S, "polar coordinate command cancel"},
      {160, M, 17, N, "polar coordinate command"},
      {170, M, 2, S, "XY plane"},
      {180, M, 2, S, "ZX plane"},
      {190, M, 2, S, "YZ plane"},
      {170, T, 16, S, "XY plane"},
      {180, T, 16, S, "ZX plane"},
      {190, T, 16, S, "YZ plane"},
      {200, M | TA | TB, 6, S, "inch input"},
      {210, M | TA | TB, 6, S, "metric input"},
      {200, TC, 1, N, "OD/ID cutting cycle (system C)"},
      {210, TC, 1, N, "thread cutting cycle (system C)"},
      {220, ALL, 4, A, "stored stroke check on"},
      {230, ALL, 4, S, "stored stroke check off"},
      {240, TC, 1, N, "end-face cutting cycle (system C)"},
      {270, ALL, 0, N, "reference position return check"},
      {280, ALL, 0, S, "return to reference position via the intermediate point"},
      {290, ALL, 0, S, "return from reference position"},
      {300, ALL, 0, S, "return to 2nd/3rd/4th reference position"},
      {310, ALL, 0, S, "skip function (probing against the setup's solids)"},
      {320, T, 1, N, "thread cutting"},
      {330, M, 1, N, "thread cutting"},
      {330, TB | TC, 1, N, "thread cutting (systems B and C)"},
      {340, T, 1, N, "variable-lead thread cutting"},
      {390, M, 0, N, "corner offset circular interpolation"},
      {400, ALL, 7, S, "cutter / tool-nose radius compensation cancel"},
      {410, ALL, 7, N, "cutter / tool-nose radius compensation left"},
      {420, ALL, 7, N, "cutter / tool-nose radius compensation right"},
      {430, M, 8, S, "tool length compensation + (type A: Z)"},
      {440, M, 8, S, "tool length compensation - (type A: Z)"},
      {490, M, 8, S, "tool length compensation cancel"},
      {450, M, 0, N, "tool offset increase"},
      {460, M, 0, N, "tool offset decrease"},
      {470, M, 0, N, "tool offset double increase"},
      {480, M, 0, N, "tool offset double decrease"},
      {500, M, 11, S, "scaling cancel"},
      {510, M, 11, N, "scaling"},
      {500, TA, 0, S, "coordinate system setting / maximum spindle speed"},
      {501, ALL, 22, S, "programmable mirror image cancel"},
      {511, ALL, 22, N, "programmable mirror image"},
      {520, ALL, 0, S, "local coordinate system"},
      {530, ALL, 0, S, "machine coordinate positioning"},
      {540, ALL, 14, S, "work coordinate system 1"},
      {541, ALL, 14, S, "additional work coordinate systems (P1-P48/P300)"},
      {550, ALL, 14, S, "work coordinate system 2"},
      {560, ALL, 14, S, "work coordinate system 3"},
      {570, ALL, 14, S, "work coordinate system 4"},
      {580, ALL, 14, S, "work coordinate system 5"},
      {590, ALL, 14, S, "work coordinate system 6"},
      {600, M, 0, N, "single direction positioning"},
      {610, M, 15, S, "exact stop mode"},
      {620, M, 15, S, "automatic corner override"},
      {630, M, 15, S, "tapping mode"},
      {640, M, 15, S, "cutting mode"},
      {650, ALL, 0, S, "macro call"},
      {660, ALL, 12, S, "macro modal call"},
      {670, ALL, 12, S, "macro modal call cancel"},
      {680, M, 16, N, "coordinate rotation"},
      {690, M, 16, S, "coordinate rotation cancel"},
      {700, TA | TB, 0, N, "finishing cycle"},
      {700, TC, 6, S, "inch input (system C)"},
      {710, TA | TB, 0, N, "stock removal in turning"},
      {710, TC, 6, S, "metric input (system C)"},
      {720, TA | TB, 0, N, "stock removal in facing"},
      {720, TC, 0, N, "finishing cycle (system C)"},
      {730, M, 9, N, "high-speed peck drilling cycle"},
      {730, TA | TB, 0, N, "pattern repeating"},
      {730, TC, 0, N, "stock removal in turning (system C)"},
      {740, M, 9, N, "left-hand tapping cycle"},
      {740, TA | TB, 0, N, "end-face peck drilling"},
      {740, TC, 0, N, "stock removal in facing (system C)"},
      {750, TA | TB, 0, N, "OD/ID drilling (grooving)"},
      {750, TC, 0, N, "pattern repeating (system C)"},
      {760, M, 9, N, "fine boring cycle"},
      {760, TA | TB, 0, N, "multiple threading cycle"},
      {760, TC, 0, N, "end-face peck drilling (system C)"},
      {770, TB, 1, N, "OD/ID cutting cycle (system B)"},
      {770, TC, 0, N, "OD/ID drilling (system C)"},
      {780, TB, 1, N, "thread cutting cycle (system B)"},
      {780, TC, 0, N, "multiple threading cycle (system C)"},
      {790, TB, 1, N, "end-face cutting cycle (system B)"},
      {800, ALL, 9, S, "canned cycle cancel"},
      {810, M, 9, N, "drilling cycle"},
      {820, M, 9, N, "counter boring cycle"},
      {830, ALL, 9, N, "peck drilling cycle"},
      {840, ALL, 9, N, "tapping cycle"},
      {850, ALL, 9, N, "boring cycle"},
      {860, M, 9, N, "boring cycle"},
      {870, ALL, 9, N, "back boring / side drilling cycle"},
      {880, ALL, 9, N, "boring cycle"},
      {890, ALL, 9, N, "boring cycle"},
      {900, M | TB | TC, 3, S, "absolute programming"},
      {910, M | TB | TC, 3, S, "incremental programming"},
      {900, TA, 1, N, "OD/ID cutting cycle"},
      {920, M, 0, S, "work coordinate system setting"},
      {920, TB | TC, 0, S, "coordinate system setting / maximum spindle speed"},
      {920, TA, 1, N, "thread cutting cycle"},
      {940, M, 5, S, "feed per minute"},
      {950, M, 5, S, "feed per revolution"},
      {940, TB | TC, 5, S, "feed per minute"},
      {950, TB | TC, 5, S, "feed per revolution"},
      {940, TA, 1, N, "end-face cutting cycle"},
      {960, M, 13, S, "constant surface speed control"},
      {970, M, 13, S, "constant surface speed control cancel"},
      {960, T, 2, S, "constant surface speed control"},
      {970, T, 2, S, "constant surface speed control cancel"},
      {980, M, 10, S, "canned cycle: return to initial level"},
      {990, M, 10, S, "canned cycle: return to R point level"},
      {980, TA, 5, S, "feed per minute"},
      {990, TA, 5, S, "feed per revolution"},
      {980, TB | TC, 10, S, "canned cycle: return to initial level"},
      {990, TB | TC, 10, S, "canned cycle: return to R point level"},
  };
  return table;
}

const GCodeInfo* findGCode(Series s, int code10) {
  uint8_t bit = seriesBit(s);
  for (const auto& g : gcodeTable())
    if (g.code10 == code10 && (g.seriesMask & bit)) return &g;
  return nullptr;
}

}  // namespace ncvm
