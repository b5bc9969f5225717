// G45-G48 tool position offset (mill): the move of each axis named in the block is made
// longer (G45) or shorter (G46) by the D offset value, or by twice it (G47, G48), along the
// direction of that axis's move. One-shot; the coordinates are not shifted afterwards (the
// tool simply ends where the lengthened or shortened move took it). Sources: Fanuc 0i-MC
// "tool position offset", the Mitsubishi M700V and Yaskawa J50M manuals (Fanuc-compatible),
// docs/fanuc-decisions.md.
#include <fmt/format.h>

#include "exec/executor.hpp"
#include "exec/words.hpp"

namespace ncvm {

bool Executor::toolPositionOffset(const Words& w, int code10) {
  // The control refuses these in cutter compensation (PS0042); arcs (quarter circles with an
  // offset radius), canned cycles and the transforms are not modelled: an alarm, never a
  // silently wrong path.
  if (modal_.g[7] != 400 || crcBusy())
    throw AlarmError(AlarmId::G45G48InCrc, fmt::format("G{}", code10 / 10));
  if (modal_.motion != 0 && modal_.motion != 10)
    throw AlarmError(AlarmId::ImproperGCode, "G45-G48 with G02/G03 (not supported yet)");
  if (modal_.g[9] != 800)
    throw AlarmError(AlarmId::ImproperGCode, "G45-G48 in a canned cycle (not supported yet)");
  if (xf_.active() || cornerHold_ || w.hasCorner())
    throw AlarmError(AlarmId::ImproperGCode,
                     "G45-G48 with G51/G51.1/G68 or ,C/,R (not supported yet)");
  // The offset value of D (geometry + wear, memory C); D0 or no D: 0.
  int d = modal_.dOffset;
  int64_t value = 0;
  if (d > 0 && d < kToolRows) {
    const ToolOffsetRow& r = mem_.tools[static_cast<size_t>(d)];
    value = r.geometry[kFieldRorD] + r.wear[kFieldRorD];
  }
  const int64_t k = code10 == 450 ? 1 : code10 == 460 ? -1 : code10 == 470 ? 2 : -2;
  std::array<int64_t, kMaxAxes> target{};
  uint32_t mask = 0;
  if (!axisTargets(w, target, mask)) return false;
  const std::array<int64_t, kMaxAxes> start = programmedHere();
  for (size_t a = 0; a < kMaxAxes; ++a) {
    if (!(mask & (1u << a))) continue;
    int64_t move = target[a] - start[a];
    if (move != 0) {
      // Along the move: a negative offset value works the other way (G45 then shortens).
      target[a] += (move > 0 ? 1 : -1) * k * value;
    } else if (modal_.incremental) {
      // An incremental zero move: G45/G47 move by +value, G46/G48 by -value (the control
      // reads the sign of "-0", which a number cannot keep: ncvm takes it as +0).
      target[a] += k * value;
    }  // an absolute move of zero ends at once
  }
  moveTo(target, modal_.motion == 0 ? MoveMode::Rapid : MoveMode::Linear, mask);
  programmed_ = target;
  return true;
}

}  // namespace ncvm
