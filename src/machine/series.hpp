#pragma once
// Which kind of control the setup describes, as the code tables split them: M, the machining
// centre; TA, TB, TC, the lathe with G-code system A, B or C. The setup chooses it
// (Setup::series); the G-code table (exec/gcode_table.hpp) and the control read it.
#include <cstdint>

namespace ncvm {

enum class Series : uint8_t { M, TA, TB, TC };

constexpr uint8_t seriesBit(Series s) {
  return static_cast<uint8_t>(1u << static_cast<unsigned>(s));
}

}  // namespace ncvm
