// Positions and moves: rounding to the least increment, rapids (linear or dog-leg per
// 1401#1), linear and circular interpolation with the radius check, dwell (reference
// returns and G53: reference_return.cpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "exec/arc_math.hpp"
#include "exec/executor.hpp"
#include "exec/words.hpp"
#include "motion/transform.hpp"

namespace ncvm {

int64_t Executor::lengthNm(double v, bool point, int slot) const {
  auto s = static_cast<size_t>(slot < 0 ? 0 : slot);
  bool rotary = setup_.axes[s].rotary;
  InputUnit u = rotary ? InputUnit::Mm : modal_.unit;
  int64_t perUnit = incrementsPerUnit(setup_.increment, u);
  int64_t nmPer = u == InputUnit::Inch ? nmPerIncInch_[s] : nmPerIncMm_[s];
  // Without a decimal point (and without calculator-type input) a value counts increments.
  int64_t inc = (!point && !dpi_) ? roundHalfAway(v) : roundToIncrements(v, perUnit);
  return checkedNm(inc, nmPer);
}

// checkedNm: increments to nanometres. A variable's value is limited only to 1e12 (PS0111), which
// in inch or IS-C can be more nanometres than int64 holds: beyond kMaxTravelNm (2,000 km, so that a
// position, an increment and an offset still add up without overflow) the value is an alarm.
void Executor::travelAlarm() {
  throw AlarmError(AlarmId::TooManyDigits, "value beyond the range of any machine (2,000 km)");
}

// A dimension word may have at most 8 digits counted in least increments of the current unit
// and increment system (PS0003, like the control's tape format check): IS-B mm allows
// X99999.999, X12345678.9 is 12345678900 increments. Only literals are checked (a variable's
// value is not limited this way), and not the arguments of G65/G66, which become variables.
void Executor::checkDigits(const Word& wd, bool macroCall) const {
  if (macroCall) return;
  int slot = -1;  // A B C: degrees when the machine has that rotary axis
  if (wd.letter >= 'A' && wd.letter <= 'C') slot = 3 + (wd.letter - 'A');
  const bool rotary = slot >= 0 && setup_.axes[static_cast<size_t>(slot)].present &&
                      setup_.axes[static_cast<size_t>(slot)].rotary;
  const int64_t perUnit = incrementsPerUnit(setup_.increment, rotary ? InputUnit::Mm : modal_.unit);
  const bool point = wd.flags & kHasPoint;
  const int64_t inc =
      (point || dpi_) ? roundToIncrements(wd.value, perUnit) : roundHalfAway(wd.value);
  if (inc > 99999999 || inc < -99999999) {
    AlarmError e(AlarmId::TooManyDigits, fmt::format("{}: {} increments, more than 8 digits",
                                                     wd.letter, inc < 0 ? -inc : inc));
    e.col = wd.col;
    throw e;
  }
}

double Executor::toProgramUnits(int64_t nm, int slot, bool diameter) const {
  const AxisConfig& a = setup_.axes[static_cast<size_t>(slot)];
  double per = a.rotary ? 1e6
                        : (modal_.unit == InputUnit::Inch ? static_cast<double>(kNmPerInch)
                                                          : static_cast<double>(kNmPerMm));
  double v = static_cast<double>(nm) / per;
  return (diameter && a.diameter) ? v * 2.0 : v;
}

AxisArray Executor::workPosition() const {
  AxisArray out{};
  for (int k = 0; k < kMaxAxes; ++k)
    out[static_cast<size_t>(k)] =
        toProgramUnits(machine_[static_cast<size_t>(k)] - offset_[static_cast<size_t>(k)], k, true);
  return out;
}

AxisArray Executor::machinePosition() const {
  AxisArray out{};
  for (int k = 0; k < kMaxAxes; ++k)
    out[static_cast<size_t>(k)] = toProgramUnits(machine_[static_cast<size_t>(k)], k, true);
  return out;
}

// Target work position of the block's axis words. Returns false when no axis is named.
bool Executor::axisTargets(const Words& w, std::array<int64_t, kMaxAxes>& target, uint32_t& mask,
                           const std::array<int64_t, kMaxAxes>* base) {
  for (size_t k = 0; k < kMaxAxes; ++k) target[k] = base ? (*base)[k] : machine_[k] - offset_[k];
  mask = 0;
  static constexpr char kAbs[kMaxAxes] = {'X', 'Y', 'Z', 'A', 'B', 'C'};
  // Lathe system A: U V W H are the incremental forms of X Y Z C.
  static constexpr char kInc[kMaxAxes] = {'U', 'V', 'W', 0, 0, 'H'};
  for (int k = 0; k < kMaxAxes; ++k) {
    auto s = static_cast<size_t>(k);
    const AxisConfig& a = setup_.axes[s];
    char absL = kAbs[k], incL = lathe_ ? kInc[k] : 0;
    if (!a.present) {
      // B without a B axis is the second auxiliary function, not an axis.
      bool named = w.has(absL) && (k >= 3 || lathe_) && absL != 'B';
      if (!lathe_ && k < 3) named = false;
      if (lathe_ && incL && w.has(incL) && k != 5) named = true;
      if (named || (!lathe_ && w.has(absL) && k >= 3 && absL != 'B')) {
        AlarmError e(AlarmId::ImproperAddress,
                     fmt::format("{}: the machine has no such axis", w.has(absL) ? absL : incL));
        e.col = w.col[static_cast<size_t>((w.has(absL) ? absL : incL) - 'A')];
        throw e;
      }
      continue;
    }
    if (w.has(absL)) {
      int64_t nm = lengthNm(w.value(absL), w.hasPoint(absL), k);
      if (a.diameter) nm /= 2;
      target[s] = modal_.incremental ? target[s] + nm : nm;
      mask |= 1u << k;
    }
    if (incL && w.has(incL)) {
      int64_t nm = lengthNm(w.value(incL), w.hasPoint(incL), k);
      if (a.diameter) nm /= 2;
      target[s] += nm;
      mask |= 1u << k;
    }
  }
  if (!lathe_ && modal_.g[17] == 160) polarTargets(w, target, mask, base);
  if (!lathe_) {
    for (char c : {'U', 'V', 'W'}) {
      if (w.has(c)) {
        AlarmError e(AlarmId::ImproperAddress, fmt::format("{}: the machine has no such axis", c));
        e.col = w.col[static_cast<size_t>(c - 'A')];
        throw e;
      }
    }
  }
  return mask != 0;
}

// G16 polar coordinate command (mill): in the selected plane the first axis word is a radius
// and the second an angle in degrees, counter-clockwise from the first axis. The centre is
// the work (or G52 local) zero, or the current position when the radius is incremental (G91);
// an omitted radius is the current distance from the zero, an omitted angle the current
// angle; a G91 angle adds to the current angle. Runs after the Cartesian pass, whose values
// for the two plane axes it replaces.
void Executor::polarTargets(const Words& w, std::array<int64_t, kMaxAxes>& target, uint32_t& mask,
                            const std::array<int64_t, kMaxAxes>* base) {
  static constexpr char kLetter[3] = {'X', 'Y', 'Z'};
  const xform::PlaneAxes pa = xform::planeAxes(modal_.plane);
  const char radiusL = kLetter[pa.u], angleL = kLetter[pa.v];
  const bool hasRadius = w.has(radiusL), hasAngle = w.has(angleL);
  if (!hasRadius && !hasAngle) return;
  const double cu = static_cast<double>(base ? (*base)[pa.u] : machine_[pa.u] - offset_[pa.u]);
  const double cv = static_cast<double>(base ? (*base)[pa.v] : machine_[pa.v] - offset_[pa.v]);
  const double nowAngle = (cu == 0 && cv == 0) ? 0.0 : std::atan2(cv, cu);
  const bool fromHere = hasRadius && modal_.incremental;
  const double radius = hasRadius
                            ? static_cast<double>(lengthNm(w.value(radiusL), w.hasPoint(radiusL),
                                                           static_cast<int>(pa.u)))
                            : std::hypot(cu, cv);
  double angle = nowAngle;
  if (hasAngle) {
    // Degrees, rounded to the metric least increment (0.001 deg for IS-B) whatever G20/G21
    // says, as for a rotary axis: an angle is not a length (docs/fanuc-decisions.md). Without
    // a decimal point (and without calculator-type input, 3401#0) the value counts increments.
    const int64_t perDeg = incrementsPerUnit(setup_.increment, InputUnit::Mm);
    const double v = w.value(angleL);
    const int64_t inc = (!w.hasPoint(angleL) && !dpi_) ? static_cast<int64_t>(std::llround(v))
                                                       : roundToIncrements(v, perDeg);
    double rad = static_cast<double>(inc) / static_cast<double>(perDeg) * std::numbers::pi / 180.0;
    angle = modal_.incremental ? nowAngle + rad : rad;
  }
  const double ou = fromHere ? cu : 0.0, ov = fromHere ? cv : 0.0;
  target[pa.u] = static_cast<int64_t>(std::llround(ou + radius * std::cos(angle)));
  target[pa.v] = static_cast<int64_t>(std::llround(ov + radius * std::sin(angle)));
  mask |= (1u << pa.u) | (1u << pa.v);
}

// axisTargets for a block plainMotion takes (a mill, no words but X Y Z among the axis
// letters): the same targets without the checks for letters that are not there.
bool Executor::plainTargets(const Words& w, std::array<int64_t, kMaxAxes>& target, uint32_t& mask) {
  for (size_t k = 0; k < kMaxAxes; ++k) target[k] = machine_[k] - offset_[k];
  mask = 0;
  for (int k = 0; k < 3; ++k) {
    const char L = "XYZ"[k];
    const AxisConfig& a = setup_.axes[static_cast<size_t>(k)];
    if (!w.has(L) || !a.present) continue;
    int64_t nm = lengthNm(w.value(L), w.hasPoint(L), k);
    if (a.diameter) nm /= 2;
    target[static_cast<size_t>(k)] = modal_.incremental ? target[static_cast<size_t>(k)] + nm : nm;
    mask |= 1u << k;
  }
  return mask != 0;
}

double Executor::effectiveFeed() {
  if (modal_.feed <= 0) throw AlarmError(AlarmId::FeedZero, "no F programmed");
  if (!modal_.feedPerRev) return modal_.feed;
  double rpm = rpm_;
  if (modal_.css) rpm = cssRpmAt(machine_[0]);  // constant surface speed: rpm at the start
  if (rpm <= 0 && !warnedRevFeed_) {
    warnedRevFeed_ = true;
    warn("W004",
         "feed per revolution with no spindle speed: the machine would wait; time counted as 0");
  }
  return modal_.feed * rpm;
}

void Executor::emitMove(MoveEvent& e, const std::array<int64_t, kMaxAxes>& fromMachine,
                        const std::array<int64_t, kMaxAxes>& toMachine) {
  e.at = origin_;
  e.thread = threadMove_;
  e.exactStop = exactStop_;
  e.inch = modal_.unit == InputUnit::Inch;
  if (modal_.feedPerRev && e.mode != MoveMode::Rapid) e.perRev = modal_.feed;
  if (modal_.css) e.surfaceSpeed = modal_.speed, e.rpmLimit = spindleClamp_;
  if (programmedEnd_) {
    e.compensated = true;
    e.programmedEnd = *programmedEnd_;
  }
  if (noseEnd_) {
    e.nose = true;
    e.noseEnd = *noseEnd_;
  }
  // toProgramUnits(nm, k, true) with the divisor looked up once per axis. A move starts
  // where the last one ended unless the offsets or the unit changed in between: then its
  // start is copied from that end, not converted again.
  const bool inch = modal_.unit == InputUnit::Inch;
  const double perLinear = inch ? static_cast<double>(kNmPerInch) : static_cast<double>(kNmPerMm);
  if (lastEmit_.valid && lastEmit_.inch == inch && lastEmit_.toMachine == fromMachine &&
      lastEmit_.offset == offset_) {
    e.mstart = lastEmit_.mend;
    e.start = lastEmit_.end;
  } else {
    for (size_t s = 0; s < kMaxAxes; ++s) {
      const double per = setup_.axes[s].rotary ? 1e6 : perLinear;
      const double dia = setup_.axes[s].diameter ? 2.0 : 1.0;  // v * 1.0 is v
      e.mstart[s] = static_cast<double>(fromMachine[s]) / per * dia;
      e.start[s] = static_cast<double>(fromMachine[s] - offset_[s]) / per * dia;
    }
  }
  for (size_t s = 0; s < kMaxAxes; ++s) {
    const double per = setup_.axes[s].rotary ? 1e6 : perLinear;
    const double dia = setup_.axes[s].diameter ? 2.0 : 1.0;
    e.mend[s] = static_cast<double>(toMachine[s]) / per * dia;
    e.end[s] = static_cast<double>(toMachine[s] - offset_[s]) / per * dia;
  }
  lastEmit_.valid = true;
  lastEmitTail_ = false;  // the straight path refills its slots after Z
  lastEmit_.inch = inch;
  lastEmit_.toMachine = toMachine;
  lastEmit_.offset = offset_;
  lastEmit_.mend = e.mend;
  lastEmit_.end = e.end;
  ++stats_.moves;
  if (e.mode == MoveMode::Rapid)
    stats_.rapidLength += e.length;
  else
    stats_.feedLength += e.length;
  advanceTime(e.time);
  sink().onMove(e);
  if (modal_.css && spindleOn_) {
    // Constant surface speed: the spindle follows X; report the rpm at the move's end.
    double rpm = cssRpmAt(toMachine[0]);
    if (rpm != rpm_) {
      rpm_ = rpm;
      sink().onSpindle(SpindleEvent{origin_, spindleDir_, rpm_, true});
    }
  }
}

void Executor::rapidMachine(const std::array<int64_t, kMaxAxes>& toM, uint32_t mask) {
  (void)mask;
  checkStroke(toM);
  std::array<int64_t, kMaxAxes> fromM = machine_;
  MoveEvent e;
  e.mode = MoveMode::Rapid;
  // Each axis needs |d| / rate; the move takes as long as the slowest axis, linear or not.
  std::array<double, kMaxAxes> t{}, d{};
  double sq = 0, time = 0;
  for (int k = 0; k < kMaxAxes; ++k) {
    auto s = static_cast<size_t>(k);
    d[s] = toProgramUnits(toM[s] - fromM[s], k, false);
    sq += d[s] * d[s];
    // Rapid rates are machine values in mm/min (deg/min): time from the distance in mm.
    double mm = static_cast<double>(toM[s] - fromM[s]) / 1e6;
    double rate = setup_.axes[s].rapidRate;
    t[s] = rate > 0 ? std::fabs(mm) / rate * 60.0 : 0.0;
    time = std::max(time, t[s]);
  }
  e.time = time;
  e.feed = time > 0 ? std::sqrt(sq) / time * 60.0 : 0.0;
  if (!lrp_) {
    // Dog-leg: every axis at its own rapid rate, so the path bends where an axis arrives.
    std::array<double, kMaxAxes> stops = t;
    std::sort(stops.begin(), stops.end());
    double length = 0;
    AxisArray prev{};
    for (int k = 0; k < kMaxAxes; ++k) prev[static_cast<size_t>(k)] = 0;
    for (double stop : stops) {
      if (stop <= 0 || stop >= time) continue;
      AxisArray at{};
      double seg = 0;
      for (int k = 0; k < kMaxAxes; ++k) {
        auto s = static_cast<size_t>(k);
        double frac = t[s] > 0 ? std::min(stop, t[s]) / t[s] : 1.0;
        at[s] = d[s] * frac;
        seg += (at[s] - prev[s]) * (at[s] - prev[s]);
      }
      if (e.pathPoints > 0 && seg == 0) continue;
      length += std::sqrt(seg);
      AxisArray point{};
      for (int k = 0; k < kMaxAxes; ++k) {
        auto s = static_cast<size_t>(k);
        int64_t nm =
            fromM[s] +
            static_cast<int64_t>(std::llround(
                at[s] *
                (setup_.axes[s].rotary ? 1e6 : (modal_.unit == InputUnit::Inch ? 25.4e6 : 1e6))));
        point[s] = toProgramUnits(nm - offset_[s], k, true);
      }
      e.path[static_cast<size_t>(e.pathPoints++)] = point;
      prev = at;
    }
    double seg = 0;
    for (int k = 0; k < kMaxAxes; ++k)
      seg += (d[static_cast<size_t>(k)] - prev[static_cast<size_t>(k)]) *
             (d[static_cast<size_t>(k)] - prev[static_cast<size_t>(k)]);
    e.length = length + std::sqrt(seg);
  } else {
    e.length = std::sqrt(sq);
  }
  emitMove(e, fromM, toM);
  machine_ = toM;
}

void Executor::moveTo(const std::array<int64_t, kMaxAxes>& targetWork, MoveMode mode,
                      uint32_t mask) {
  std::array<int64_t, kMaxAxes> toM;
  for (size_t k = 0; k < kMaxAxes; ++k) toM[k] = targetWork[k] + offset_[k];
  programmed_ = targetWork;
  if (mode == MoveMode::Rapid) {
    rapidMachine(toM, mask);
    return;
  }
  checkStroke(toM);
  MoveEvent e;
  e.mode = mode;
  e.feed = effectiveFeed();
  double sq = 0;
  for (int k = 0; k < kMaxAxes; ++k) {
    double d =
        toProgramUnits(toM[static_cast<size_t>(k)] - machine_[static_cast<size_t>(k)], k, false);
    sq += d * d;
  }
  e.length = std::sqrt(sq);
  e.time = e.feed > 0 ? e.length / e.feed * 60.0 : 0.0;
  std::array<int64_t, kMaxAxes> fromM = machine_;
  emitMove(e, fromM, toM);
  machine_ = toM;
}

namespace {
// Plane axes (u, v) and normal n: (u, v, n) is right-handed, so G02 is clockwise seen from
// +n in every plane (G17: X Y Z, G18: Z X Y, G19: Y Z X).
struct PlaneAxes {
  size_t u, v, n;
  char cu, cv;
};
PlaneAxes planeAxes(int plane) {
  if (plane == 18) return {2, 0, 1, 'K', 'I'};
  if (plane == 19) return {1, 2, 0, 'J', 'K'};
  return {0, 1, 2, 'I', 'J'};
}
}  // namespace

bool Executor::arcBlock(const Words& w) const {
  if (modal_.motion != 20 && modal_.motion != 30) return false;
  const PlaneAxes pa = planeAxes(modal_.plane);
  // Parameter 3403#5 (CIR) = 0: an arc block with neither R nor the plane's centre words
  // moves linearly to its end point; 1: PS0022 (from arcCenter).
  return w.has('R') || w.has(pa.cu) || w.has(pa.cv) || setup_.bit("3403#5");
}

void Executor::arcTo(const std::array<int64_t, kMaxAxes>& targetWork, const Words& w, bool cw) {
  const PlaneAxes pa = planeAxes(modal_.plane);
  std::array<int64_t, kMaxAxes> startW;
  for (size_t k = 0; k < kMaxAxes; ++k) startW[k] = machine_[k] - offset_[k];
  if (w.has('R') && startW[pa.u] == targetWork[pa.u] && startW[pa.v] == targetWork[pa.v]) {
    // An R arc that ends where it starts is a zero-length arc (no movement in the plane).
    if (targetWork != startW) moveTo(targetWork, MoveMode::Linear, 0);
    return;
  }
  double cu0 = 0, cv0 = 0;
  arcCenter(startW, targetWork, w, cw, cu0, cv0);
  arcWithCenter(targetWork, cu0, cv0, cw);
}

// The centre of an arc block (R or I/J/K) in the plane, work coordinates in nm.
void Executor::arcCenter(const std::array<int64_t, kMaxAxes>& startW,
                         const std::array<int64_t, kMaxAxes>& targetWork, const Words& w, bool cw,
                         double& cu0, double& cv0) {
  const PlaneAxes pa = planeAxes(modal_.plane);
  double su = static_cast<double>(startW[pa.u]), sv = static_cast<double>(startW[pa.v]);
  double eu = static_cast<double>(targetWork[pa.u]), ev = static_cast<double>(targetWork[pa.v]);
  double tolNm = arcTolerance_ * 1e6;
  cu0 = su;
  cv0 = sv;
  if (w.has('R')) {
    double r = static_cast<double>(lengthNm(w.value('R'), w.hasPoint('R'), static_cast<int>(pa.u)));
    double du = eu - su, dv = ev - sv;
    double d = planeDistance(du, dv);
    if (d == 0) return;
    double h2 = r * r - d * d / 4.0;
    if (h2 < 0) {
      if (d / 2.0 - std::fabs(r) > tolNm)
        throw AlarmError(AlarmId::OverToleranceOfRadius, "R smaller than half the chord");
      h2 = 0;
    }
    double h = std::sqrt(h2);
    double pu = -dv / d, pv = du / d;  // left of the chord
    double side = (cw ? -1.0 : 1.0) * (r < 0 ? -1.0 : 1.0);
    cu0 = (su + eu) / 2.0 + side * h * pu;
    cv0 = (sv + ev) / 2.0 + side * h * pv;
    return;
  }
  if (!w.has(pa.cu) && !w.has(pa.cv)) throw AlarmError(AlarmId::NoRadiusOrCenter);
  // I, J, K are incremental from the start point and always radius values.
  auto centerNm = [&](char c, size_t axis) {
    return w.has(c)
               ? static_cast<double>(lengthNm(w.value(c), w.hasPoint(c), static_cast<int>(axis)))
               : 0.0;
  };
  cu0 = su + centerNm(pa.cu, pa.u);
  cv0 = sv + centerNm(pa.cv, pa.v);
  double rs = planeDistance(su - cu0, sv - cv0), re = planeDistance(eu - cu0, ev - cv0);
  if (rs == 0) throw AlarmError(AlarmId::OverToleranceOfRadius, "centre on the start point");
  if (std::fabs(re - rs) > tolNm)
    throw AlarmError(AlarmId::OverToleranceOfRadius,
                     fmt::format("end radius differs by {:.4f} mm", std::fabs(re - rs) / 1e6));
}

// An arc from the current position to targetWork around the centre (cu, cv) of the plane
// (work coordinates, nm); the other axes move linearly (helix).
void Executor::arcWithCenter(const std::array<int64_t, kMaxAxes>& targetWork, double cu0,
                             double cv0, bool cw) {
  const PlaneAxes pa = planeAxes(modal_.plane);
  double feed = effectiveFeed();
  std::array<int64_t, kMaxAxes> startW;
  for (size_t k = 0; k < kMaxAxes; ++k) startW[k] = machine_[k] - offset_[k];
  double su = static_cast<double>(startW[pa.u]), sv = static_cast<double>(startW[pa.v]);
  double eu = static_cast<double>(targetWork[pa.u]), ev = static_cast<double>(targetWork[pa.v]);
  double r = planeDistance(su - cu0, sv - cv0);
  double sweep = arcSweep(su, sv, eu, ev, cu0, cv0, cw);
  // Length in program units: the arc and any linear (helical) axes together.
  double unitNm = modal_.unit == InputUnit::Inch ? 25.4e6 : 1e6;
  double arcLen = r * sweep / unitNm;
  double lin = 0;
  for (size_t k = 0; k < kMaxAxes; ++k) {
    if (k == pa.u || k == pa.v) continue;
    double dk = toProgramUnits(targetWork[k] - startW[k], static_cast<int>(k), false);
    lin += dk * dk;
  }
  MoveEvent e;
  e.mode = cw ? MoveMode::Cw : MoveMode::Ccw;
  e.arc = true;
  e.plane = modal_.plane;
  e.feed = feed;
  e.length = std::sqrt(arcLen * arcLen + lin);
  e.time = feed > 0 ? e.length / feed * 60.0 : 0.0;
  std::array<int64_t, kMaxAxes> centerW = startW;
  centerW[pa.u] = static_cast<int64_t>(std::llround(cu0));
  centerW[pa.v] = static_cast<int64_t>(std::llround(cv0));
  centerW[pa.n] = startW[pa.n];
  for (int k = 0; k < 3; ++k)
    e.center[static_cast<size_t>(k)] = toProgramUnits(centerW[static_cast<size_t>(k)], k, true);
  std::array<int64_t, kMaxAxes> toM, fromM = machine_;
  for (size_t k = 0; k < kMaxAxes; ++k) toM[k] = targetWork[k] + offset_[k];
  checkStroke(toM);
  programmed_ = targetWork;
  emitMove(e, fromM, toM);
  machine_ = toM;
}

void Executor::dwell(const Words& w) {
  double seconds = 0;
  double revs = 0;
  if (w.has('P')) {
    seconds = static_cast<double>(std::llround(w.value('P'))) / 1000.0;
  } else {
    char L = w.has('X') ? 'X' : (lathe_ && w.has('U')) ? 'U' : 0;
    if (!L) return;
    double v = w.value(L);
    // X without a decimal point counts least increments: G04 X1 is 0.001 s on IS-B.
    seconds = (!w.hasPoint(L) && !dpi_) ? v * leastIncrement(setup_.increment, InputUnit::Mm) : v;
  }
  if (seconds < 0) throw AlarmError(AlarmId::IllegalMinus, "negative dwell");
  DwellEvent e;
  e.at = origin_;
  if (modal_.feedPerRev && setup_.bit("3405#1")) {
    // Parameter 3405#1: in feed per revolution the dwell is in spindle revolutions.
    revs = seconds;
    seconds = rpm_ > 0 ? revs * 60.0 / rpm_ : 0.0;
    e.revolutions = revs;
  }
  e.time = seconds;
  advanceTime(seconds);
  sink().onDwell(e);
}

}  // namespace ncvm
