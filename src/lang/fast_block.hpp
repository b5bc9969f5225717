#pragma once
// The plain line of a CAM program ("N120 G01 X107.569 Y0.985 Z-2.92", "G02 X1. Y-6.5 I-8. J-5.4")
// compiled in one pass over its characters, straight into the Program's words and blocks.
// Most of a large program is such lines; everything else goes through the general compiler.
#include <cstdint>

#include "lang/ir.hpp"

namespace ncvm {

// Compiles the plain lines from `b` on into `p`, one after another, while each is plain and
// starts before `end`; each of them must end in a '\n' at or before `end` (a last line without
// one goes the general way): the scan stops at it, so it tests no bounds. One call takes a run
// of plain lines, the bulk of a CAM program.
//
// A plain line: spaces, an optional N number, and address words made of an upper-case letter
// and a literal number the general compiler accepts without an alarm (no O/N inside, no sign
// on G, M, S..., no point on M, S, T..., at most 19 digits). A blank line is plain too (it
// compiles to nothing). The result is exactly the general compiler's: the same Block
// (location, N, kind, flags), Words (values bit for bit, flags, columns) and label.
//
// `line` is the number of the line before `b`; it and `compiled` count the lines compiled.
// Returns the start of the first line not compiled (not plain, having written nothing: the
// caller compiles it the general way), or `end`.
const char* compileFastLines(const char* b, const char* end, uint32_t file, uint32_t& line,
                             uint32_t maxLineLength, Program& p, uint32_t& compiled);

}  // namespace ncvm
