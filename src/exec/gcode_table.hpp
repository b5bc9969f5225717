#pragma once
// Every G code ncvm knows, per series (M: machining centre; T: lathe with G-code system
// A, B or C), with its modal group and whether ncvm executes it yet. docs/support-matrix.md
// is generated from this table by `ncvm codes`.
#include <cstdint>
#include <vector>

#include "machine/series.hpp"

namespace ncvm {

enum class GStatus : uint8_t {
  Supported,  // executed as the control does
  Accepted,   // accepted; no effect on motion in ncvm (look-ahead modes and the like)
  NotYet,     // a real code ncvm does not execute yet: alarm PS0010 naming it
};

struct GCodeInfo {
  int16_t code10;      // G code x10 (G54.1 = 541)
  uint8_t seriesMask;  // bit per Series
  uint8_t group;       // modal group number as in #4000+group; 0 = one-shot
  GStatus status;
  const char* meaning;
};

const std::vector<GCodeInfo>& gcodeTable();
// nullptr when the series has no such code.
const GCodeInfo* findGCode(Series s, int code10);

}  // namespace ncvm
