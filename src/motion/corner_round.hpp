#pragma once
// Chamfer (,C) and corner rounding (,R) between two programmed blocks (30i comma form;
// fanuc-reference C): block A is shortened before the corner, a line or an arc is
// inserted, and block B starts after it. Plane geometry in program units; lines and arcs
// in any combination. Nothing here knows about programs.
#include <stdexcept>
#include <string>

#include "core/alarm.hpp"
#include "motion/cutter_comp.hpp"

namespace ncvm::cornerw {

using crc::Kind;
using crc::P2;

struct Seg {
  Kind kind = Kind::Line;
  P2 a, b, c;  // start, end, centre (arcs)
};

struct Corner {
  bool none = false;  // the blocks meet tangentially: nothing to insert
  P2 endA, startB;    // where A now ends and B now starts
  bool arc = false;   // ,R: an arc around `center` in direction `kind`; ,C: a line
  Kind kind = Kind::Line;
  P2 center;
};

struct CornerError : std::runtime_error {
  CornerError(AlarmId alarm, const std::string& detail) : std::runtime_error(detail), id(alarm) {}
  AlarmId id;
};

// ,C: the chamfer starts and ends `amount` from the virtual corner (straight-line distance,
// also on arcs). ,R: an arc of radius `amount` tangent to both blocks. A corner that does
// not fit on either block raises PS0055.
Corner place(const Seg& a, const Seg& b, bool chamfer, double amount, double eps = 1e-9);

}  // namespace ncvm::cornerw
