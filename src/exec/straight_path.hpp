#pragma once
// The executor's straight path for plain G01 and G17 arc blocks (straight_move.cpp) gives what the
// general path gives. Tests switch it off to run the same program both ways and compare the
// trace and state byte for byte (and read the count to see that it ran); nothing else touches
// these.
#include <cstdint>

namespace ncvm {
extern bool straightPathEnabled;
// Blocks the straight path has run on this thread (batch runs execute programs on several
// threads at once: one counter each, no shared write).
extern thread_local uint64_t straightPathMoves;
}  // namespace ncvm
