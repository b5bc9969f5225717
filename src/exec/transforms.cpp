// G51.1/G50.1 programmable mirror image, G51/G50 scaling and G68/G69 coordinate system
// rotation (mill; fanuc-reference C). The transforms map the programmed work position to
// the one the tool follows (src/motion/transform); here the control reads their blocks,
// keeps the programmed position for incremental words and #5001, and moves the tool.
// Order of application, and the restrictions, are in docs/fanuc-decisions.md.
#include <fmt/format.h>

#include <cmath>

#include "exec/arc_math.hpp"
#include "exec/executor.hpp"
#include "exec/words.hpp"

namespace ncvm {

namespace {
xform::P3 toP3(const std::array<int64_t, kMaxAxes>& p) {
  return {static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])};
}
bool hasCode(const Words& w, int code10) {
  for (int k = 0; k < w.ng; ++k)
    if (w.g[static_cast<size_t>(k)] == code10) return true;
  return false;
}
AlarmError orderAlarm(const char* what) {
  return AlarmError(AlarmId::ImproperGCode, what);
}
}  // namespace

std::array<int64_t, kMaxAxes> Executor::transformed(const std::array<int64_t, kMaxAxes>& p) const {
  if (!xf_.active()) return p;
  xform::P3 t = xf_.apply(toP3(p));
  std::array<int64_t, kMaxAxes> out = p;
  for (size_t k = 0; k < 3; ++k) {
    // A scaled point far outside any machine must not overflow the nm counts.
    if (!(std::fabs(t[k]) < 1e18))
      throw AlarmError(AlarmId::FloatOverflow, "transformed position out of range");
    out[k] = static_cast<int64_t>(std::llround(t[k]));
  }
  return out;
}

std::array<int64_t, kMaxAxes> Executor::programmedHere() const {
  if (xf_.active() || cornerHold_) return programmed_;
  std::array<int64_t, kMaxAxes> p{};
  for (size_t k = 0; k < kMaxAxes; ++k) p[k] = machine_[k] - offset_[k];
  return p;
}

const std::array<int64_t, kMaxAxes>* Executor::moveBase() const {
  return (xf_.active() || cornerHold_) ? &programmed_ : nullptr;
}

void Executor::untransformProgrammed() {
  for (size_t k = 0; k < kMaxAxes; ++k) programmed_[k] = machine_[k] - offset_[k];
  if (!xf_.active()) return;
  xform::P3 p = xf_.invert(toP3(programmed_));
  for (size_t k = 0; k < 3; ++k)
    if (std::fabs(p[k]) < 1e18) programmed_[k] = static_cast<int64_t>(std::llround(p[k]));
}

// Blocks a real control refuses (or leaves undefined: "do not specify") while a transform
// is in effect. ncvm stops with an alarm rather than guess the motion.
void Executor::transformRestrictions(int oneShot, bool workChanged) const {
  if (!xf_.active()) return;
  const char* what = nullptr;
  if (oneShot == 270 || oneShot == 280 || oneShot == 290 || oneShot == 300)
    what = "G27-G30 in G51/G51.1/G68 mode: cancel the transform first";
  else if (oneShot == 520 || oneShot == 920 || oneShot == 921 || workChanged)
    what =
        "changing the coordinate system (G52, G54-G59, G92) in G51/G51.1/G68 mode: cancel the "
        "transform first";
  if (what) throw AlarmError(AlarmId::ImproperGCode, what);
}

// The transform codes of a block, cancels first, then mirror, scaling and rotation (the
// order they must be programmed in). Returns true when the block's axis words were the
// transform's data (centres, mirror axes), so the block does not move.
bool Executor::transformBlock(const Words& w, int oneShot) {
  (void)oneShot;
  const bool g69 = hasCode(w, 690), g50 = hasCode(w, 500), g501 = hasCode(w, 501);
  const bool g511 = hasCode(w, 511), g51 = hasCode(w, 510), g68 = hasCode(w, 680);
  if (!(g69 || g50 || g501 || g511 || g51 || g68)) return false;
  if (crc_ && crc_->active())
    throw orderAlarm(
        "G50/G51/G50.1/G51.1/G68/G69 in cutter compensation mode: program them with G40");
  const std::array<int64_t, kMaxAxes> here = programmedHere();
  static constexpr char kAxis[3] = {'X', 'Y', 'Z'};
  auto absNm = [&](char c, size_t k) {
    return static_cast<double>(lengthNm(w.value(c), w.hasPoint(c), static_cast<int>(k)));
  };
  if (g69) {
    xf_.rotation = false;
    xfAngleDeg_ = 0;
  }
  if (g50) {
    if (xf_.rotation) throw orderAlarm("G50 in G68 mode: cancel the rotation (G69) first");
    xf_.scaling = false;
    xf_.scale = {1, 1, 1};
  }
  if (g501) {
    if (xf_.rotation || xf_.scaling)
      throw orderAlarm("G50.1 in G51/G68 mode: cancel rotation and scaling first");
    bool any = w.any("XYZ");
    for (size_t k = 0; k < 3; ++k)
      if (!any || w.has(kAxis[k])) xf_.mirror[k] = false;
  }
  if (g511) {
    if (xf_.rotation || xf_.scaling)
      throw orderAlarm("G51.1 in G51/G68 mode: program the mirror before scaling and rotation");
    for (size_t k = 0; k < 3; ++k) {
      if (!w.has(kAxis[k])) continue;
      xf_.mirror[k] = true;
      xf_.mirrorAt[k] = absNm(kAxis[k], k);
    }
  }
  if (g51) {
    if (xf_.rotation) throw orderAlarm("G51 in G68 mode: program scaling before the rotation");
    // P / I J K without a decimal point count 0.001 (5400#7 SCR = 0) or 0.00001 (SCR = 1).
    const bool fine = setup_.bit("5400#7");
    const double unit = fine ? 1e-5 : 1e-3, maxFactor = fine ? 9.99999 : 999.999;
    auto factor = [&](char c, double fallback, bool signedOk) {
      double f = fallback;
      if (w.has(c)) f = w.hasPoint(c) ? w.value(c) : w.value(c) * unit;
      if (std::fabs(f) < unit - 1e-12 || std::fabs(f) > maxFactor + 1e-12 || (!signedOk && f < 0))
        throw AlarmError(AlarmId::IllegalScaleRate, fmt::format("{} = {}", c, f));
      return f;
    };
    auto param = [&](const std::string& key, double fallback) {
      auto it = setup_.parameters.find(key);
      return it == setup_.parameters.end() ? fallback : it->second * unit;
    };
    xform::P3 scale{1, 1, 1};
    if (w.any("IJK")) {
      // 5421 is an axis parameter (5421.X); a plain 5421 applies to every axis.
      const double all = param("5421", 1.0);
      for (size_t k = 0; k < 3; ++k)
        scale[k] = factor("IJK"[k], param(fmt::format("5421.{}", kAxis[k]), all), true);
    } else {
      double p = factor('P', param("5411", 1.0), false);
      scale = {p, p, p};
    }
    // 5401#0 SCLx = 0 for an axis: that axis is not scaled (unset: scaled).
    for (size_t k = 0; k < 3; ++k)
      if (setup_.param(fmt::format("5401#0.{}", kAxis[k]), 1) == 0) scale[k] = 1;
    for (size_t k = 0; k < 3; ++k)
      xf_.scaleAt[k] = w.has(kAxis[k]) ? absNm(kAxis[k], k) : static_cast<double>(here[k]);
    xf_.scale = scale;
    xf_.scaling = true;
  }
  if (g68) {
    const xform::PlaneAxes a = xform::planeAxes(modal_.plane);
    const char cu = kAxis[a.u], cv = kAxis[a.v];
    double u = w.has(cu) ? absNm(cu, a.u) : static_cast<double>(here[a.u]);
    double v = w.has(cv) ? absNm(cv, a.v) : static_cast<double>(here[a.v]);
    double deg = setup_.param("5410", 0) * 1e-3;
    if (w.has('R'))
      deg = (w.hasPoint('R') || dpi_)
                ? w.value('R')
                : w.value('R') * leastIncrement(setup_.increment, InputUnit::Mm);
    // 5400#0 RIN = 1: R follows G90/G91, so G91 adds to the current angle.
    if (w.has('R') && modal_.incremental && setup_.bit("5400#0") && xf_.rotation)
      deg += xfAngleDeg_;
    xf_.rotation = false;
    xf_.setRotation(modal_.plane, u, v, deg);
    xfAngleDeg_ = deg;
  }
  // The next incremental word counts from the programmed point, which the tool reached
  // through the old transform; once every transform is off, from where the tool is.
  programmed_ = here;
  if (!xf_.active()) untransformProgrammed();
  return g501 || g511 || g51 || g68;
}

// A move through the transforms: the end point (and an arc's centre) go through the map;
// a reflection swaps G02/G03.
void Executor::runPlanned(const PlannedMove& m) {
  bool arc = m.mode == 20 || m.mode == 30;
  bool cw = m.mode == 20;
  if (!xf_.active()) {
    if (arc)
      arcWithCenter(m.end, m.cu, m.cv, cw);
    else
      moveTo(m.end, m.mode == 0 ? MoveMode::Rapid : MoveMode::Linear, m.mask);
    programmed_ = m.end;
    return;
  }
  std::array<int64_t, kMaxAxes> to = transformed(m.end);
  uint32_t mask = m.mask;
  for (size_t k = 0; k < kMaxAxes; ++k)
    if (to[k] != machine_[k] - offset_[k]) mask |= 1u << k;
  if (!arc) {
    moveTo(to, m.mode == 0 ? MoveMode::Rapid : MoveMode::Linear, mask);
    programmed_ = m.end;
    return;
  }
  if (xf_.rotation && xf_.rotPlane != modal_.plane)
    throw AlarmError(AlarmId::IllegalPlaneForRotation,
                     fmt::format("arc in G{} under G68 in G{}", modal_.plane, xf_.rotPlane));
  const xform::PlaneAxes a = xform::planeAxes(modal_.plane);
  xform::P3 c = toP3(programmed_);
  c[a.u] = m.cu;
  c[a.v] = m.cv;
  c = xf_.apply(c);
  if (xf_.flips(modal_.plane)) cw = !cw;
  // Unequal scaling of the two plane axes would make an ellipse, which the control cannot
  // cut: the end radius no longer matches (PS0020).
  double su = static_cast<double>(machine_[a.u] - offset_[a.u]),
         sv = static_cast<double>(machine_[a.v] - offset_[a.v]);
  double rs = planeDistance(su - c[a.u], sv - c[a.v]);
  double re =
      planeDistance(static_cast<double>(to[a.u]) - c[a.u], static_cast<double>(to[a.v]) - c[a.v]);
  if (std::fabs(re - rs) > arcTolerance_ * 1e6)
    throw AlarmError(
        AlarmId::OverToleranceOfRadius,
        fmt::format("scaled arc: end radius differs by {:.4f} mm", std::fabs(re - rs) / 1e6));
  arcWithCenter(to, c[a.u], c[a.v], cw);
  programmed_ = m.end;
}

}  // namespace ncvm
