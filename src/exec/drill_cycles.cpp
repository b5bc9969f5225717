// Machining-centre drilling cycles G73, G74, G76, G81-G89 (fanuc-reference D.1): each hole
// is positioned at rapid, then the drilling axis goes to the R level, runs the cycle body,
// and returns to the initial level (G98) or the R level (G99). Z, R, Q, P and F stay modal
// until G80 or a group-01 code cancels the cycle.
#include <fmt/format.h>

#include <cmath>

#include "exec/executor.hpp"
#include "exec/words.hpp"

namespace ncvm {

namespace {
// The drilling axis is the normal of the plane: Z in G17, Y in G18, X in G19.
int drillingAxis(int plane) {
  return plane == 18 ? 1 : plane == 19 ? 0 : 2;
}
}  // namespace

void Executor::cancelCycle() {
  modal_.g[9] = 800;
  cycle_ = DrillCycle{};
  rigidTap_ = false;  // G80 and group 01 also end rigid tapping mode (M29)
}

// Called for every block in cycle mode. Returns true if the block drilled (it moved).
bool Executor::drillCycle(const Words& w, bool cycleCommanded) {
  const int axis = drillingAxis(modal_.plane);
  const auto A = static_cast<size_t>(axis);
  const char axisLetter = "XYZ"[axis];
  const char reLetter = 'R';
  int code = modal_.g[9];
  // Hole positions and levels are program coordinates; under G51.1/G51/G68 each hole and
  // level goes through the transforms (drillOneHole runs in the tool's coordinates).
  if (xf_.active() && xf_.rotation && xf_.rotPlane != modal_.plane)
    throw AlarmError(
        AlarmId::IllegalPlaneForRotation,
        fmt::format("canned cycle in G{} under G68 in G{}", modal_.plane, xf_.rotPlane));
  const std::array<int64_t, kMaxAxes> here = programmedHere();

  if (cycleCommanded && (!cycle_.active || cycle_.axis != axis)) {
    // Entering cycle mode: the initial level is where the drilling axis is now.
    cycle_ = DrillCycle{};
    cycle_.active = true;
    cycle_.axis = axis;
    cycle_.initial = here[A];
    cycle_.r = here[A];
  }
  // Cycle data: modal until G80. In G91, R is measured from the initial level and Z from R.
  if (w.has(reLetter)) {
    int64_t r = lengthNm(w.value(reLetter), w.hasPoint(reLetter), axis);
    cycle_.r = modal_.incremental ? cycle_.initial + r : r;
    cycle_.haveR = true;
  }
  if (w.has(axisLetter)) {
    int64_t z = lengthNm(w.value(axisLetter), w.hasPoint(axisLetter), axis);
    cycle_.bottom = modal_.incremental ? cycle_.r + z : z;
    cycle_.haveZ = true;
  }
  if (w.has('Q') && !w.pqBelongToCall())
    cycle_.q = std::llabs(lengthNm(w.value('Q'), w.hasPoint('Q'), axis));
  if (w.has('P') && !w.pqBelongToCall())
    cycle_.dwellMs = static_cast<double>(std::llround(w.value('P')));
  int repeats = w.has('K') ? static_cast<int>(std::llround(w.value('K'))) : 1;
  if (repeats < 0 || repeats > 9999) throw AlarmError(AlarmId::IntegerOverflow, "K");

  // Drilling happens when the block has position data (plane axes, the drilling axis or R).
  bool position = false;
  for (int k = 0; k < kMaxAxes; ++k)
    if (setup_.axes[static_cast<size_t>(k)].present && w.has("XYZABC"[k])) position = true;
  if (!position && !w.has(reLetter)) return false;
  if (repeats == 0) return false;  // K0 stores the data without drilling
  if (!cycle_.haveZ)
    throw AlarmError(AlarmId::NoDataAfterAddress, fmt::format("{} of the hole bottom", axisLetter));
  if ((code == 730 || code == 830) && cycle_.q <= 0) throw AlarmError(AlarmId::QNotFound);
  if (code == 870 && modal_.g[10] == 990)
    throw AlarmError(AlarmId::ImproperGCode,
                     "G87 back boring returns to the initial level only (G98)");

  // Hole positions: the plane axes of the block; with G91 and K they repeat at that pitch.
  std::array<int64_t, kMaxAxes> planeTarget = here;
  uint32_t mask = 0;
  Words planeWords = w;
  planeWords.present &= ~(Words::bit(axisLetter));
  if (lathe_) planeWords.present &= ~Words::bit("UVW"[axis]);
  axisTargets(planeWords, planeTarget, mask, moveBase());
  std::array<int64_t, kMaxAxes> step{};
  for (size_t k = 0; k < kMaxAxes; ++k) step[k] = planeTarget[k] - here[k];

  const std::array<int64_t, kMaxAxes> first = here;
  // G16 with G91: each repeat turns by the angle again (a bolt circle), not a straight pitch.
  const bool polarRepeat = !lathe_ && modal_.g[17] == 160 && modal_.incremental;
  std::array<int64_t, kMaxAxes> previous = here;
  for (int n = 0; n < repeats; ++n) {
    std::array<int64_t, kMaxAxes> hole = first;
    if (polarRepeat) {
      uint32_t m = 0;
      std::array<int64_t, kMaxAxes> t{};
      axisTargets(planeWords, t, m, &previous);
      for (size_t k = 0; k < kMaxAxes; ++k)
        if (k != A) hole[k] = t[k];
      previous = hole;
    } else {
      for (size_t k = 0; k < kMaxAxes; ++k)
        if (k != A) hole[k] = modal_.incremental ? first[k] + step[k] * (n + 1) : planeTarget[k];
    }
    if (!xf_.active()) {
      drillOneHole(hole, code, axis, cycle_.initial, cycle_.r, cycle_.bottom);
      continue;
    }
    // Under a transform: the hole and the three levels as the tool sees them. Q, d and the
    // G76/G87 shift stay as programmed (not scaled; docs/fanuc-decisions.md).
    auto level = [&](int64_t z) {
      std::array<int64_t, kMaxAxes> p = hole;
      p[A] = z;
      return transformed(p)[A];
    };
    drillOneHole(transformed(hole), code, axis, level(cycle_.initial), level(cycle_.r),
                 level(cycle_.bottom));
    programmed_ = hole;
    programmed_[A] = modal_.g[10] != 990 || code == 870 ? cycle_.initial : cycle_.r;
  }
  return true;
}

void Executor::drillOneHole(const std::array<int64_t, kMaxAxes>& hole, int code, int axis,
                            int64_t initial, int64_t rLevel, int64_t bottom) {
  const auto A = static_cast<size_t>(axis);
  const bool toInitial = modal_.g[10] != 990;
  auto at = [&](int64_t level) {
    std::array<int64_t, kMaxAxes> p = hole;
    p[A] = level;
    return p;
  };
  // Moves of zero length (R level equal to the current level, ...) are not made.
  auto rapid = [&](int64_t level) {
    if (machine_[A] - offset_[A] != level) moveTo(at(level), MoveMode::Rapid, 1u << axis);
  };
  auto feed = [&](int64_t level) {
    if (machine_[A] - offset_[A] != level) moveTo(at(level), MoveMode::Linear, 1u << axis);
  };
  auto dwellMs = [&]() {
    if (cycle_.dwellMs <= 0) return;
    DwellEvent e;
    e.at = origin_;
    e.time = cycle_.dwellMs / 1000.0;
    advanceTime(e.time);
    sink().onDwell(e);
  };
  auto spindle = [&](SpindleDir d) {
    spindleDir_ = d == SpindleDir::Stop || d == SpindleDir::Orient ? spindleDir_ : d;
    spindleOn_ = d == SpindleDir::Cw || d == SpindleDir::Ccw;
    sink().onSpindle(SpindleEvent{origin_, d, spindleOn_ ? rpm_ : 0.0});
  };
  // The direction bottom -> R: pecks advance against it.
  const int64_t dir = bottom < rLevel ? -1 : 1;
  // Fine boring and back boring shift away from the wall by Q (parameter 5101 RD1/RD2:
  // 0 = +X, 1 = -X, 2 = +Y, 3 = -Y in G17).
  auto shifted = [&](int64_t level, int sign) {
    std::array<int64_t, kMaxAxes> p = at(level);
    int rd = static_cast<int>(setup_.param("5101#4", 0)) +
             2 * static_cast<int>(setup_.param("5101#5", 0));
    size_t shiftAxis = rd >= 2 ? (A == 1 ? 2 : 1) : (A == 0 ? 1 : 0);
    int64_t s = (rd % 2 == 0 ? 1 : -1) * sign * cycle_.q;
    p[shiftAxis] += s;
    return p;
  };

  // 1. Position in the plane at rapid, at the current level of the drilling axis.
  std::array<int64_t, kMaxAxes> pos = hole;
  pos[A] = machine_[A] - offset_[A];
  bool samePlace = true;
  for (size_t k = 0; k < kMaxAxes; ++k) samePlace &= pos[k] == machine_[k] - offset_[k];
  if (!samePlace) moveTo(pos, MoveMode::Rapid, ~(1u << axis));
  // 2. Rapid to the R level (G87 goes to the bottom instead, shifted, after orienting).
  if (code != 870) rapid(rLevel);

  switch (code) {
    case 810:  // drilling
      feed(bottom);
      break;
    case 820:  // counter boring: dwell at the bottom
      feed(bottom);
      dwellMs();
      break;
    case 831:    // lathe G83/G87 with RTR = 1: peck, dwell P at the bottom
    case 830: {  // deep peck: back to R after each peck, rapid to d above the last depth
      int64_t d = std::llround(setup_.param("5115", 0.5) * 1e6);  // mm, machine units
      int64_t depth = rLevel;
      while (true) {
        int64_t next = depth + dir * cycle_.q;
        if ((next - bottom) * dir >= 0) next = bottom;
        if (depth != rLevel) rapid(depth - dir * d);
        feed(next);
        depth = next;
        if (depth == bottom) break;
        rapid(rLevel);
      }
      if (code == 831) dwellMs();
      break;
    }
    case 731:    // lathe G83/G87 with RTR = 0: high-speed peck, dwell P at the bottom
    case 730: {  // high-speed peck: back off d after each peck
      int64_t d = std::llround(setup_.param("5114", 0.5) * 1e6);  // mm, machine units
      int64_t depth = rLevel;
      while (true) {
        int64_t next = depth + dir * cycle_.q;
        if ((next - bottom) * dir >= 0) next = bottom;
        feed(next);
        depth = next;
        if (depth == bottom) break;
        rapid(depth - dir * d);
      }
      if (code == 731) dwellMs();
      break;
    }
    case 840:  // tapping: reverse at the bottom, feed out, spindle forward again
    case 740:
    case 841:  // lathe G84/G88: reverses whatever the live tool's direction is
    {
      // Forward and reverse: G84 cw/ccw, G74 ccw/cw, lathe: the direction now and its opposite.
      SpindleDir fwd = code == 840 ? SpindleDir::Cw : code == 740 ? SpindleDir::Ccw : spindleDir_;
      SpindleDir rev = fwd == SpindleDir::Cw ? SpindleDir::Ccw : SpindleDir::Cw;
      // Rigid tapping (M29, or 5200#0): the spindle follows the axis, so no M05 and the
      // moves are synchronised like threading. Otherwise 5101#6 M5T = 0 sends M05 before
      // each reversal.
      const bool rigid = rigidTap_ || setup_.bit("5200#0");
      if (rigid && rpm_ <= 0)
        throw AlarmError(AlarmId::IllegalSInRigidTap, "rigid tapping without S");
      const bool stopFirst = !rigid && !setup_.bit("5101#6");
      threadMove_ = rigid;
      feed(bottom);
      threadMove_ = false;
      dwellMs();
      if (stopFirst) spindle(SpindleDir::Stop);
      spindle(rev);
      threadMove_ = rigid;
      feed(rLevel);
      threadMove_ = false;
      if (stopFirst) spindle(SpindleDir::Stop);
      spindle(fwd);
      break;
    }
    case 850:  // boring: feed in, feed out
      feed(bottom);
      feed(rLevel);
      break;
    case 860:  // boring: spindle stop at the bottom, rapid out, spindle on
      feed(bottom);
      spindle(SpindleDir::Stop);
      rapid(toInitial ? initial : rLevel);
      spindle(spindleDir_);
      return;
    case 890:  // boring with dwell, feed out
      feed(bottom);
      dwellMs();
      feed(rLevel);
      break;
    case 880: {  // boring: dwell, spindle stop, manual retract, then cycle start returns
      feed(bottom);
      dwellMs();
      spindle(SpindleDir::Stop);
      sink().onMessage(MessageEvent{origin_, "G88: retract by hand, then cycle start", "G88"});
      rapid(rLevel);
      spindle(spindleDir_);
      break;
    }
    case 760: {  // fine boring: orient, shift off the wall, rapid out, shift back
      feed(bottom);
      dwellMs();
      spindle(SpindleDir::Orient);
      moveTo(shifted(bottom, 1), MoveMode::Rapid, 0);
      moveTo(shifted(toInitial ? initial : rLevel, 1), MoveMode::Rapid, 0);
      moveTo(at(toInitial ? initial : rLevel), MoveMode::Rapid, 0);
      spindle(spindleDir_);
      return;
    }
    case 870: {  // back boring: orient, shift, rapid to the bottom, cut upwards to Z
      spindle(SpindleDir::Orient);
      moveTo(shifted(machine_[A] - offset_[A], 1), MoveMode::Rapid, 0);
      moveTo(shifted(rLevel, 1), MoveMode::Rapid, 0);
      moveTo(at(rLevel), MoveMode::Rapid, 0);
      spindle(SpindleDir::Cw);
      feed(bottom);
      spindle(SpindleDir::Orient);
      moveTo(shifted(bottom, 1), MoveMode::Rapid, 0);
      moveTo(shifted(initial, 1), MoveMode::Rapid, 0);
      moveTo(at(initial), MoveMode::Rapid, 0);
      spindle(SpindleDir::Cw);
      return;
    }
    default:
      throw AlarmError(AlarmId::ImproperGCode, fmt::format("G{}", code / 10));
  }
  // Return: G98 to the initial level, G99 to R (the tapping and boring cycles that feed out
  // are already at R).
  if (toInitial)
    rapid(initial);
  else if (machine_[A] - offset_[A] != rLevel)
    rapid(rLevel);
}

}  // namespace ncvm
