// The straight path for the bulk of a CAM program: a plain block (compiler flag kPlainBlock:
// literal G00-G03 X Y Z F I J K R words) that is a G00 or G01 move, or a G02/G03 arc in G17
// with R or I/J, on a mill in the plainest modal state. It does exactly what plainMotion ->
// moveTo (-> rapidMachine) / plannedBlock -> arcCenter -> arcWithCenter -> emitMove do for
// such a block, with the same doubles in the same order and the same alarms, but reads the
// compiled words directly, converts only the three axes that can move, checks the stroke
// against limits precomputed in nanometres, and reuses one MoveEvent instead of building a
// 680-byte one per move. Anything else (K, G18/G19 arcs, a zero-length R arc, a mode it does
// not cover) returns false before it changes anything, and the general path runs the block.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "exec/arc_math.hpp"
#include "exec/executor.hpp"
#include "exec/straight_path.hpp"
#include "lang/address_letters.hpp"
#include "motion/cutter_comp.hpp"

namespace ncvm {

namespace {

// The position checkStroke compares with an axis's limits (mm or degrees), in the same
// arithmetic: program units of the machine position, times 25.4 for a linear axis in inch.
double strokePosition(const AxisConfig& a, int64_t nm, bool inch) {
  const double per =
      a.rotary ? 1e6 : (inch ? static_cast<double>(kNmPerInch) : static_cast<double>(kNmPerMm));
  double pos = static_cast<double>(nm) / per;
  if (a.diameter) pos *= 2.0;
  const double unit = (inch && !a.rotary) ? 25.4 : 1.0;
  return pos * unit;
}
bool overMax(const AxisConfig& a, int64_t nm, bool inch) {
  return strokePosition(a, nm, inch) > a.max + 1e-9;
}
bool underMin(const AxisConfig& a, int64_t nm, bool inch) {
  return strokePosition(a, nm, inch) < a.min - 1e-9;
}

// The test is monotonic in nm (a division and a multiplication by positive constants, each
// correctly rounded), so it holds exactly beyond one threshold: found from an estimate by
// stepping until the test flips (a few steps: as many as nanometres share one double there).
// Limits beyond 4e12 mm (or NaN) are treated as never reached: positions that far overflow the
// nanometre arithmetic anyway.
constexpr int64_t kFar = int64_t{4'000'000'000'000'000'000};
int64_t highestAllowed(const AxisConfig& a, bool inch) {
  if (!(std::fabs(a.max) < 4e12)) return a.max > 0 ? kFar : -kFar;  // NaN: the test never trips
  const double nmPerUnit = 1e6;                                     // limits are in mm / deg
  int64_t t = static_cast<int64_t>(std::floor(a.max * nmPerUnit / (a.diameter ? 2.0 : 1.0)));
  while (overMax(a, t, inch)) --t;
  while (!overMax(a, t + 1, inch)) ++t;
  return t;
}
int64_t lowestAllowed(const AxisConfig& a, bool inch) {
  if (!(std::fabs(a.min) < 4e12)) return a.min < 0 ? -kFar : kFar;
  const double nmPerUnit = 1e6;
  int64_t t = static_cast<int64_t>(std::ceil(a.min * nmPerUnit / (a.diameter ? 2.0 : 1.0)));
  while (underMin(a, t, inch)) ++t;
  while (!underMin(a, t - 1, inch)) --t;
  return t;
}
}  // namespace

// Where a straight block keeps the value of its letter X Y Z F I J R (nullptr for another).
Executor::StraightWords::Number* Executor::numberFor(StraightWords& w, char letter) {
  switch (letter) {
    case 'X':
      return &w.axis[0];
    case 'Y':
      return &w.axis[1];
    case 'Z':
      return &w.axis[2];
    case 'F':
      return &w.feed;
    case 'I':
      return &w.i;
    case 'J':
      return &w.j;
    case 'R':
      return &w.r;
    default:
      return nullptr;
  }
}

const Executor::StraightAxes& Executor::fillStraightAxes(bool inch) {
  StraightAxes& t = straightAxes_[inch ? 1 : 0];
  const InputUnit unit = inch ? InputUnit::Inch : InputUnit::Mm;
  for (size_t k = 0; k < kMaxAxes; ++k) {
    const AxisConfig& a = setup_.axes[k];
    StraightAxes::Axis& x = t.axis[k];
    x.present = a.present;
    x.diameter = a.diameter;
    // lengthNm: a rotary axis counts in degrees whatever the unit.
    x.perIncrement = incrementsPerUnit(setup_.increment, a.rotary ? InputUnit::Mm : unit);
    x.nmPerIncrement = (a.rotary || !inch) ? nmPerIncMm_[k] : nmPerIncInch_[k];
    // toProgramUnits / emitMove: the divisor and the diameter factor.
    x.per =
        a.rotary ? 1e6 : (inch ? static_cast<double>(kNmPerInch) : static_cast<double>(kNmPerMm));
    x.dia = a.diameter ? 2.0 : 1.0;
    if (!a.present) {
      x.lo = -kFar * 2, x.hi = kFar * 2;  // checkStroke skips the axis
    } else {
      x.hi = highestAllowed(a, inch);
      x.lo = lowestAllowed(a, inch);
    }
  }
  t.valid = true;
  return t;
}

bool straightPathEnabled = true;
thread_local uint64_t straightPathMoves = 0;

bool Executor::straightRun() {
  Frame& f = frames_.back();  // a straight block pushes no frame: the reference stays valid
  const Program& prog = *f.prog;
  const size_t n = prog.blocks.size();
  while (f.pc < n) {
    const Block& b = prog.blocks[f.pc];
    // A block skip level (step() decides it) or any other block: step() runs it.
    if (b.kind != BlockKind::Nc || !(b.flags & kPlainBlock) || b.skipLevel) return true;
    // step()'s bookkeeping, in its order.
    block_ = &b;
    if (stats_.blocks >= setup_.limits.maxBlocks) blockLimitAlarm();
    ++stats_.blocks;
    if (b.n >= 0) lastN_ = b.n;
    origin_.file = b.loc.file;
    origin_.line = b.loc.line;
    origin_.n = b.n;
    origin_.programName = &prog.label;
    // The block before was a straight move: no compensation, nothing held (crcBusy() is false)
    // and the modal state still passes straightMove's test.
    deferring_ = false;
    if (straightMove(b, true)) {
      if (simTime_ > setup_.limits.maxTimeSeconds) timeLimitAlarm();
      continue;
    }
    execNcGeneral(b);  // the state may change in any way now: the run ends with this block
    if (simTime_ > setup_.limits.maxTimeSeconds) timeLimitAlarm();
    return !ended_;
  }
  return true;  // the end of the program: step() decides what follows
}

bool Executor::straightMove(const Block& b, bool modalChecked) {
  if (!straightPathEnabled) return false;
  // The modal state plainMotion requires, and none of what emitMove would add to the event.
  if (!modalChecked &&
      (lathe_ || modal_.g[7] != 400 || modal_.g[9] != 800 || modal_.g[17] != 150 ||
       !modalCalls_.empty() || xf_.active() || cornerHold_ || crcCorner_ || !pending_.empty() ||
       (crc_ && crc_->active()) || modal_.css || programmedEnd_ || noseEnd_ || threadMove_))
    return false;
  const Word* words = frames_.back().prog->words.data() + b.firstWord;
  StraightWords w;
  if (!(b.flags & kPlainBlock)) {
    if (!straightVariableWords(b, words, w)) return false;
  } else {
    for (uint32_t k = 0; k < b.nWords; ++k) {
      const Word& wd = words[k];
      if (wd.letter == 'G') {
        w.code = static_cast<int>(wd.value * 10.0);
        continue;
      }
      StraightWords::Number* slot = numberFor(w, wd.letter);
      if (!slot) return false;  // K: the general path decides what it means
      *slot = StraightWords::Number{wd.value, true, (wd.flags & kHasPoint) != 0};
    }
  }
  const int code = w.code;
  const GCodeInfo*& info = w.info;
  if (code >= 0) {
    if ((code != 0 && code != 10 && code != 20 && code != 30) ||
        gCall_[static_cast<size_t>(code / 10)] > 0)
      return false;
    info = gInfo(code);
    if (!info || info->status == GStatus::NotYet || info->group != 1) return false;
  }
  const int motion = w.motion = code >= 0 ? code : modal_.motion;
  const bool arc = motion == 20 || motion == 30;
  const bool ij = w.i.given || w.j.given;
  if (arc) {
    // G18/G19 arcs, and an arc without R, I or J (its alarm): the general path.
    if (modal_.plane != 17 || !(w.r.given || ij)) return false;
  } else if ((motion != 10 && motion != 0) || ij || w.r.given) {
    return false;  // another mode, or I J R in a G00/G01 block: the general path
  }
  const bool anyAxis = (w.axis[0].given && setup_.axes[0].present) ||
                       (w.axis[1].given && setup_.axes[1].present) ||
                       (w.axis[2].given && setup_.axes[2].present);
  // F alone, an absent axis, an arc with nothing but R: rare, the general path.
  if (!anyAxis && !(arc && ij)) return false;
  if (arc) return straightBlock<true, false>(w);
  return motion == 0 ? straightBlock<false, true>(w) : straightBlock<false, false>(w);
}

// gatherWords for the words a straight block may have: first the letters and kinds alone
// (nothing read, so a block that is no straight move costs only this look), then the values
// in block order, with gatherWords' range alarm. Reading a variable or an expression changes
// nothing, so when the general path runs the block after all it reads the same.
bool Executor::straightVariableWords(const Block& b, const Word* words, StraightWords& w) {
  constexpr uint32_t kLetters = letters::mask("GXYZFIJR");
  uint32_t seen = 0;
  for (uint32_t k = 0; k < b.nWords; ++k) {
    const Word& wd = words[k];
    if (wd.letter < 'A' || wd.letter > 'Z') return false;  // a name, ,C or ,R
    const uint32_t bit = 1u << (wd.letter - 'A');
    if (!(bit & kLetters) || (seen & bit)) return false;  // a repeated letter: the general path
    seen |= bit;
    // A literal as in a plain block (G00-G03, no digit-count check); no G#1.
    if (wd.kind == WordKind::Literal ? !letters::plainWord(wd) : wd.letter == 'G') return false;
  }
  for (uint32_t k = 0; k < b.nWords; ++k) {
    const Word& wd = words[k];
    double v = wd.value;
    bool point = (wd.flags & kHasPoint) != 0;
    if (wd.kind != WordKind::Literal) {
      const Value x = wd.kind == WordKind::Expr ? evalAddress(wd.a, wd.letter) : readVar(wd.a);
      if (x.null) continue;  // a vacant variable drops the whole word
      v = wd.kind == WordKind::NegVar ? -x.v : x.v;
      point = true;
    }
    if (!std::isfinite(v) || std::fabs(v) > 1e12) {
      AlarmError e(AlarmId::FloatOverflow, fmt::format("{} value out of range", wd.letter));
      e.col = wd.col;
      throw e;
    }
    // Beyond a million metres (or inches) lengthNm's range check decides: the general path.
    if (std::fabs(v) > 1e9) return false;
    if (wd.letter == 'G') {
      w.code = static_cast<int>(v * 10.0);
      continue;
    }
    *numberFor(w, wd.letter) = StraightWords::Number{v, true, point};  // a letter checked above
  }
  return true;
}

// rapidMachine's time, feed and length for a rapid of X, Y and Z alone: the other axes add
// nothing to its sums (their distances and times are 0, the dog-leg skips a stop of 0), so
// three axes give the same doubles. The dog-leg's corner points carry the other axes where
// they are.
void Executor::straightRapid(MoveEvent& e, const int64_t* fromM, const int64_t* toM,
                             const double* dist, double sq, bool inch) {
  constexpr size_t kXyz = 3;
  double t[kXyz];
  double time = 0;
  for (size_t s = 0; s < kXyz; ++s) {
    // Rapid rates are machine values in mm/min (deg/min): time from the distance in mm.
    const double mm = static_cast<double>(toM[s] - fromM[s]) / 1e6;
    const double rate = setup_.axes[s].rapidRate;
    t[s] = rate > 0 ? std::fabs(mm) / rate * 60.0 : 0.0;
    time = std::max(time, t[s]);
  }
  e.time = time;
  e.feed = time > 0 ? std::sqrt(sq) / time * 60.0 : 0.0;
  if (lrp_) {
    e.length = std::sqrt(sq);
    return;
  }
  // Dog-leg: every axis at its own rapid rate, so the path bends where an axis arrives.
  double stops[kXyz] = {t[0], t[1], t[2]};
  std::sort(stops, stops + kXyz);
  double length = 0;
  double prev[kXyz] = {0, 0, 0};
  const StraightAxes& ax = straightAxes(inch);
  for (double stop : stops) {
    if (stop <= 0 || stop >= time) continue;
    double at[kXyz];
    double seg = 0;
    for (size_t s = 0; s < kXyz; ++s) {
      const double frac = t[s] > 0 ? std::min(stop, t[s]) / t[s] : 1.0;
      at[s] = dist[s] * frac;
      seg += (at[s] - prev[s]) * (at[s] - prev[s]);
    }
    if (e.pathPoints > 0 && seg == 0) continue;
    length += std::sqrt(seg);
    AxisArray& point = e.path[static_cast<size_t>(e.pathPoints++)];
    for (size_t s = 0; s < kXyz; ++s) {
      const double scale = setup_.axes[s].rotary ? 1e6 : (inch ? 25.4e6 : 1e6);
      const int64_t nm = fromM[s] + static_cast<int64_t>(std::llround(at[s] * scale));
      point[s] = static_cast<double>(nm - offset_[s]) / ax.axis[s].per * ax.axis[s].dia;
    }
    for (size_t s = kXyz; s < kMaxAxes; ++s)
      point[s] = static_cast<double>(machine_[s] - offset_[s]) / ax.axis[s].per * ax.axis[s].dia;
    for (size_t s = 0; s < kXyz; ++s) prev[s] = at[s];
  }
  double seg = 0;
  for (size_t s = 0; s < kXyz; ++s) seg += (dist[s] - prev[s]) * (dist[s] - prev[s]);
  e.length = length + std::sqrt(seg);
}

// The block itself, from its targets to the event: one instance each for G01, G00 and arcs, so
// that the G01 blocks, nearly all of a program, are compiled without the others' code around.
template <bool Arc, bool Rapid>
bool Executor::straightBlock(const StraightWords& w) {
  const StraightWords::Number* axis = w.axis;
  const StraightWords::Number &feed = w.feed, &wi = w.i, &wj = w.j, &wr = w.r;
  const int code = w.code, motion = w.motion;
  const GCodeInfo* info = w.info;
  constexpr bool arc = Arc;
  // The targets (plainTargets) come first: the block's G code (group 1) cannot change the unit
  // or G90/G91, and computing them changes nothing, so an arc the general path must take can
  // still be refused here.
  const bool inch = modal_.unit == InputUnit::Inch;
  const StraightAxes& ax = straightAxes(inch);
  constexpr size_t kXyz = 3;
  // lengthNm with the axis's constants looked up once per unit: axis words, and R I J.
  auto lengthNmOf = [&](const StraightWords::Number& wd, size_t slot) {
    const StraightAxes::Axis& a = ax.axis[slot];
    const int64_t inc =
        (!wd.point && !dpi_) ? roundHalfAway(wd.v) : roundToIncrements(wd.v, a.perIncrement);
    // No overflow: a plain literal is below 1000 and straightVariableWords refuses values
    // past 1e9, far inside lengthNm's bound (checkedNm).
    return inc * a.nmPerIncrement;
  };
  int64_t start[kXyz], target[kXyz], toM[kXyz];
  for (size_t k = 0; k < kXyz; ++k) {
    const StraightAxes::Axis& a = ax.axis[k];
    int64_t t = start[k] = machine_[k] - offset_[k];
    if (axis[k].given && a.present) {
      int64_t nm = lengthNmOf(axis[k], k);
      if (a.diameter) nm /= 2;
      t = modal_.incremental ? t + nm : nm;
    }
    target[k] = t;
  }
  // plannedBlock's zero-length R arc (no movement in the plane) becomes a G01 there.
  if constexpr (Arc)
    if (wr.given && target[0] == start[0] && target[1] == start[1]) return false;

  // From here on this is the block's execution, in the general path's order.
  // modal_'s derived fields follow its G codes after every block: only a G word changes them.
  if (info) {
    applyModalG(code, *info);
    deriveModal();
  }
  exactStop_ = modal_.g[15] == 610;
  if (feed.given) {
    double fv = feed.v;
    if (fv < 0) throw AlarmError(AlarmId::IllegalMinus, "F");
    if (!feed.point && !dpi_ && modal_.feedPerRev)
      fv *= leastIncrement(setup_.increment, modal_.unit);
    modal_.feed = fv;
  }
  MoveEvent& e = straight_;
  if constexpr (Arc) {
    double cu0 = 0, cv0 = 0;
    double radius = -1;  // the start radius, once computed (the general path's double)
    // arcCenter in G17 (u = X, v = Y): R and I with X's increments, J with Y's.
    const bool cw = motion == 20;
    const double su = static_cast<double>(start[0]), sv = static_cast<double>(start[1]);
    const double eu = static_cast<double>(target[0]), ev = static_cast<double>(target[1]);
    const double tolNm = arcTolerance_ * 1e6;
    cu0 = su;
    cv0 = sv;
    if (wr.given) {
      const double r = static_cast<double>(lengthNmOf(wr, 0));
      const double du = eu - su, dv = ev - sv;
      const double d = planeDistance(du, dv);
      if (d != 0) {
        double h2 = r * r - d * d / 4.0;
        if (h2 < 0) {
          if (d / 2.0 - std::fabs(r) > tolNm)
            throw AlarmError(AlarmId::OverToleranceOfRadius, "R smaller than half the chord");
          h2 = 0;
        }
        const double h = std::sqrt(h2);
        const double pu = -dv / d, pv = du / d;  // left of the chord
        const double side = (cw ? -1.0 : 1.0) * (r < 0 ? -1.0 : 1.0);
        cu0 = (su + eu) / 2.0 + side * h * pu;
        cv0 = (sv + ev) / 2.0 + side * h * pv;
      }
    } else {
      cu0 = su + (wi.given ? static_cast<double>(lengthNmOf(wi, 0)) : 0.0);
      cv0 = sv + (wj.given ? static_cast<double>(lengthNmOf(wj, 1)) : 0.0);
      const double rs = radius = planeDistance(su - cu0, sv - cv0);
      const double re = planeDistance(eu - cu0, ev - cv0);
      if (rs == 0) throw AlarmError(AlarmId::OverToleranceOfRadius, "centre on the start point");
      if (std::fabs(re - rs) > tolNm)
        throw AlarmError(AlarmId::OverToleranceOfRadius,
                         fmt::format("end radius differs by {:.4f} mm", std::fabs(re - rs) / 1e6));
    }
    // arcWithCenter: the feed first, then the sweep and the length.
    e.feed = effectiveFeed();
    const double r = radius >= 0 ? radius : planeDistance(su - cu0, sv - cv0);
    const double sweep = arcSweep(su, sv, eu, ev, cu0, cv0, cw);
    const double unitNm = inch ? 25.4e6 : 1e6;
    const double arcLen = r * sweep / unitNm;
    const double dz = static_cast<double>(target[2] - start[2]) / ax.axis[2].per;
    const double lin = 0 + dz * dz;  // the axes after Z add 0
    e.mode = cw ? MoveMode::Cw : MoveMode::Ccw;
    e.arc = true;
    e.plane = 17;
    e.length = std::sqrt(arcLen * arcLen + lin);
    e.time = e.feed > 0 ? e.length / e.feed * 60.0 : 0.0;
    // roundHalfAway is llround (halves away from zero) without the libm call.
    const int64_t center[kXyz] = {roundHalfAway(cu0), roundHalfAway(cv0), start[2]};
    for (size_t k = 0; k < kXyz; ++k)
      e.center[k] = static_cast<double>(center[k]) / ax.axis[k].per * ax.axis[k].dia;
  }
  for (size_t k = 0; k < kXyz; ++k) toM[k] = target[k] + offset_[k];
  // moveTo sets the programmed position before its stroke check, arcWithCenter after it.
  auto setProgrammed = [&] {
    for (size_t k = 0; k < kXyz; ++k) programmed_[k] = target[k];
    for (size_t k = kXyz; k < kMaxAxes; ++k) programmed_[k] = machine_[k] - offset_[k];
  };
  if (!arc) setProgrammed();

  // The other axes' part of the event (and of lastEmit_) depends only on where they are, their
  // offsets and the unit: filled and stroke-checked again only when one of those changed.
  const bool tailSame =
      straightTail_.valid && straightTail_.inch == inch &&
      straightTail_.machine[0] == machine_[3] && straightTail_.machine[1] == machine_[4] &&
      straightTail_.machine[2] == machine_[5] && straightTail_.offset[0] == offset_[3] &&
      straightTail_.offset[1] == offset_[4] && straightTail_.offset[2] == offset_[5];
  bool over = false;
  for (size_t k = 0; k < kXyz; ++k) over |= toM[k] > ax.axis[k].hi || toM[k] < ax.axis[k].lo;
  for (size_t k = kXyz; !tailSame && k < kMaxAxes; ++k)
    over |= machine_[k] > ax.axis[k].hi || machine_[k] < ax.axis[k].lo;
  if (over) {
    std::array<int64_t, kMaxAxes> all = machine_;
    for (size_t k = 0; k < kXyz; ++k) all[k] = toM[k];
    checkStroke(all);  // throws the alarm
  }
  if (arc) setProgrammed();
  constexpr bool rapid = Rapid;
  if constexpr (!Arc) {
    e.mode = rapid ? MoveMode::Rapid : MoveMode::Linear;
    e.arc = false;
    e.plane = 17;
    e.center = {};
    if (!rapid) e.feed = effectiveFeed();  // moveTo: after the stroke check; a rapid has none
  }
  // A dog-leg rapid before left its corner points: every other move has none (the general
  // path's fresh event has them zero; no sink reads past pathPoints, so this is for tidiness).
  for (int k = 0; k < e.pathPoints; ++k) e.path[static_cast<size_t>(k)] = {};
  e.pathPoints = 0;
  if (!tailSame || !lastEmitTail_) {
    for (size_t s = kXyz; s < kMaxAxes; ++s) {
      const double p = ax.axis[s].per, d = ax.axis[s].dia;
      e.mstart[s] = e.mend[s] = lastEmit_.mend[s] = static_cast<double>(machine_[s]) / p * d;
      e.start[s] = e.end[s] = lastEmit_.end[s] =
          static_cast<double>(machine_[s] - offset_[s]) / p * d;
      lastEmit_.toMachine[s] = machine_[s];
      lastEmit_.offset[s] = offset_[s];
      straightTail_.machine[s - kXyz] = machine_[s];
      straightTail_.offset[s - kXyz] = offset_[s];
    }
    straightTail_.valid = true;
    straightTail_.inch = inch;
    lastEmitTail_ = true;
  }
  // emitMove's test whether the last end is this start (the other axes agree by the above).
  const bool same = lastEmit_.valid && lastEmit_.inch == inch &&
                    lastEmit_.toMachine[0] == machine_[0] &&
                    lastEmit_.toMachine[1] == machine_[1] &&
                    lastEmit_.toMachine[2] == machine_[2] && lastEmit_.offset[0] == offset_[0] &&
                    lastEmit_.offset[1] == offset_[1] && lastEmit_.offset[2] == offset_[2];
  // One pass per axis: the line's length (toProgramUnits of the difference, summed in axis
  // order; the other axes add 0), the event's coordinates as emitMove converts them, the
  // bookkeeping.
  double sq = 0;
  int64_t fromM[kXyz];  // the rapid's per-axis times and dog-leg need the start
  double dist[kXyz];    // program units, without the diameter factor
  for (size_t s = 0; s < kXyz; ++s) {
    const double p = ax.axis[s].per, d = ax.axis[s].dia;
    const double diff = static_cast<double>(toM[s] - machine_[s]) / p;
    fromM[s] = machine_[s];
    dist[s] = diff;
    sq += diff * diff;
    if (same) {
      e.mstart[s] = lastEmit_.mend[s];
      e.start[s] = lastEmit_.end[s];
    } else {
      e.mstart[s] = static_cast<double>(machine_[s]) / p * d;
      e.start[s] = static_cast<double>(machine_[s] - offset_[s]) / p * d;
    }
    e.mend[s] = lastEmit_.mend[s] = static_cast<double>(toM[s]) / p * d;
    e.end[s] = lastEmit_.end[s] = static_cast<double>(toM[s] - offset_[s]) / p * d;
    lastEmit_.toMachine[s] = toM[s];
    lastEmit_.offset[s] = offset_[s];
    machine_[s] = toM[s];
  }
  if constexpr (!Arc) {
    if constexpr (Rapid) {
      straightRapid(e, fromM, toM, dist, sq, inch);
    } else {
      e.length = std::sqrt(sq);
      e.time = e.feed > 0 ? e.length / e.feed * 60.0 : 0.0;
    }
  }
  e.at = origin_;
  e.exactStop = exactStop_;
  e.inch = inch;
  e.perRev = modal_.feedPerRev && !rapid ? modal_.feed : 0;
  lastEmit_.valid = true;
  lastEmit_.inch = inch;
  ++stats_.moves;
  if (rapid)
    stats_.rapidLength += e.length;
  else
    stats_.feedLength += e.length;
  simTime_ += e.time;  // advanceTime
  stats_.time += e.time;
  realSink_.onMove(e);  // sink(): nothing is deferred without compensation
  ++frames_.back().pc;
  ++straightPathMoves;
  return true;
}

template bool Executor::straightBlock<true, false>(const StraightWords&);
template bool Executor::straightBlock<false, false>(const StraightWords&);
template bool Executor::straightBlock<false, true>(const StraightWords&);

}  // namespace ncvm
