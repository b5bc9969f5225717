#pragma once
// Corner placement for cutter compensation C (internal to src/motion/crc_*.cpp): where the
// tool centre goes between two programmed blocks, following the rules of the Fanuc
// operator's manual for offset mode, start-up and cancel (fanuc-reference E.1).
#include <vector>

#include "motion/cutter_comp.hpp"

namespace ncvm::crc::corner {

// Which table of the manual applies to the corner. Start-up and cancel come in type A and
// type B (parameter 5003#0 SUP); they differ only at outer corners.
enum class Rule { Offset, StartupA, StartupB, CancelA, CancelB };

// The tool path between block a (ending at a.end) and block b (starting at b.start).
// dA is the signed offset of a at its end, dB that of b at its start (both computed with the
// radius of a: a new D takes effect at the end of its block). The result is never empty:
// block a ends at the first point, each further point is reached by an extra linear move
// the control inserts, and block b starts at the last point.
std::vector<P2> place(const InSeg& a, double dA, const InSeg& b, double dB, Rule rule, double eps);

// G40 with I/J/K: block a ends where its offset path meets the offset of a virtual path
// from a.end in direction `dir`; perpendicular to a if they do not meet.
std::vector<P2> placeToward(const InSeg& a, double dA, P2 dir, double eps);

}  // namespace ncvm::crc::corner
