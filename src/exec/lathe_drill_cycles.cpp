// Lathe drilling cycles (0i-T/16i-T "canned cycle for drilling", live tools): G83 face
// drilling, G84 face tapping and G85 face boring drill along Z at X(U) C(H) positions; G87,
// G88 and G89 do the same along X (side holes) at Z(W) C(H) positions. G80 or a group-01
// code cancels them. The moves are those of the machining-centre cycles (drill_cycles.cpp,
// drillOneHole); this file reads the lathe's words and parameters:
//  - R: the R level. G-code system A: incremental from the initial level (parameter 5102#6
//    RAB = 1 makes it absolute); systems B/C: G90 absolute, G91 from the initial level. For
//    the side cycles R is a radius (5102#7 RDI = 1: a diameter).
//  - Z/X: the hole bottom (absolute; X a diameter); W/U (or G91 in B/C): from the R level.
//  - Q: depth of each peck of G83/G87 (radius, no sign). Without Q they drill in one feed.
//    5101#2 RTR = 0: high-speed peck (back off d = 5114); 1: peck (back to R, then rapid to
//    d = 5115 above the last depth).
//  - P: dwell at the bottom (ms); F: feed; K: repeats (with U/W/H or G91, at that pitch).
//  - Return: systems B/C by G98 (initial level) / G99 (R level); system A has no G98/G99
//    for this (they are feed per minute / revolution): the tool returns to the initial level.
#include <fmt/format.h>

#include <cmath>

#include "exec/executor.hpp"
#include "exec/words.hpp"

namespace ncvm {

bool Executor::latheDrillCycle(const Words& w, bool cycleCommanded) {
  const int code = modal_.g[9];
  const bool side = code == 870 || code == 880 || code == 890;
  const int axis = side ? 0 : 2;
  const auto A = static_cast<size_t>(axis);
  const char absL = side ? 'X' : 'Z', incL = side ? 'U' : 'W';
  const bool diameter = setup_.axes[A].diameter;
  std::array<int64_t, kMaxAxes> here{};
  for (size_t k = 0; k < kMaxAxes; ++k) here[k] = machine_[k] - offset_[k];

  if (cycleCommanded && (!cycle_.active || cycle_.axis != axis)) {
    cycle_ = DrillCycle{};
    cycle_.active = true;
    cycle_.axis = axis;
    cycle_.initial = here[A];
    cycle_.r = here[A];
  }
  if (w.has('R')) {
    int64_t r = lengthNm(w.value('R'), w.hasPoint('R'), axis);
    if (diameter && setup_.bit("5102#7")) r /= 2;  // RDI: R of a diameter axis as a diameter
    bool incremental = series_ == Series::TA ? !setup_.bit("5102#6") : modal_.incremental;
    // An absolute R on the diameter axis is a position like X: a radius unless RDI says so.
    cycle_.r = incremental ? cycle_.initial + r : r;
    cycle_.haveR = true;
  }
  if (w.has(absL) || w.has(incL)) {
    bool inc = w.has(incL) || modal_.incremental;
    char L = w.has(incL) ? incL : absL;
    int64_t z = lengthNm(w.value(L), w.hasPoint(L), axis);
    if (diameter) z /= 2;
    cycle_.bottom = inc ? cycle_.r + z : z;
    cycle_.haveZ = true;
  }
  if (w.has('Q') && !w.pqBelongToCall())
    cycle_.q = std::llabs(lengthNm(w.value('Q'), w.hasPoint('Q'), axis));
  if (w.has('P') && !w.pqBelongToCall())
    cycle_.dwellMs = static_cast<double>(std::llround(w.value('P')));
  int repeats = w.has('K') ? static_cast<int>(std::llround(w.value('K'))) : 1;
  if (repeats < 0 || repeats > 9999) throw AlarmError(AlarmId::IntegerOverflow, "K");

  bool position = w.has('R');
  for (char c : {'X', 'Y', 'Z', 'C', 'U', 'V', 'W', 'H'}) position |= w.has(c);
  if (!position || repeats == 0) return false;
  if (!cycle_.haveZ)
    throw AlarmError(AlarmId::NoDataAfterAddress, fmt::format("{} of the hole bottom", absL));

  // Which body the hole gets (the codes of drillOneHole).
  int body = 0;
  switch (code) {
    case 830:
    case 870:
      if (cycle_.q <= 0)
        body = 820;  // one feed to the bottom, dwell P, rapid out
      else
        body = setup_.bit("5101#2") ? 831 : 731;
      break;
    case 840:
    case 880:
      body = 841;
      break;
    default:  // G85, G89: feed in, dwell P, feed out
      body = 890;
      break;
  }

  // Hole positions: the other axes of the block; incremental words repeat at their pitch.
  Words planeWords = w;
  planeWords.present &= ~(Words::bit(absL) | Words::bit(incL));
  std::array<int64_t, kMaxAxes> planeTarget = here;
  uint32_t mask = 0;
  axisTargets(planeWords, planeTarget, mask);
  static constexpr char kInc[kMaxAxes] = {'U', 'V', 'W', 0, 0, 'H'};
  const std::array<int64_t, kMaxAxes> first = here;
  for (int n = 0; n < repeats; ++n) {
    std::array<int64_t, kMaxAxes> hole = first;
    for (size_t k = 0; k < kMaxAxes; ++k) {
      if (k == A) continue;
      bool inc = modal_.incremental || (kInc[k] && planeWords.has(kInc[k]));
      hole[k] = inc ? first[k] + (planeTarget[k] - first[k]) * (n + 1) : planeTarget[k];
    }
    drillOneHole(hole, body, axis, cycle_.initial, cycle_.r, cycle_.bottom);
  }
  return true;
}

}  // namespace ncvm
