#pragma once
// The executor's straight path for plain G01 blocks (straight_move.cpp) gives exactly what the
// general path gives. Tests switch it off to run the same program both ways and compare the
// trace and state byte for byte (and read the count to see that it ran); nothing else touches
// these.
#include <cstdint>

namespace ncvm {
extern bool straightPathEnabled;
extern uint64_t straightPathMoves;  // blocks the straight path has run in this process
}  // namespace ncvm
