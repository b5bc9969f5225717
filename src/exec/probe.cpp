// G31 skip: a linear feed move that stops where the probe first touches the probe world
// (fanuc-reference C, G31). The latched position goes to #5061- (work) and the skip event.
#include <fmt/format.h>

#include <cmath>

#include "exec/executor.hpp"
#include "exec/words.hpp"

namespace ncvm {

void Executor::skipMove(const Words& w) {
  if (modal_.g[7] != 400) throw AlarmError(AlarmId::CannotG31InCompensation);
  std::array<int64_t, kMaxAxes> target{};
  uint32_t mask = 0;
  if (!axisTargets(w, target, mask, moveBase())) return;
  double feed = effectiveFeed();
  // Under G51.1/G51/G68 the probe moves toward the transformed target; the latch below is
  // mapped back to the program's coordinates (docs/fanuc-decisions.md).
  const std::array<int64_t, kMaxAxes> programTarget = target;
  target = transformed(target);

  // The probe is a sphere at the tool tip: the stylus ball of the probe tool, otherwise the
  // tool's own diameter from [tools].
  double r = 0;
  const ProbeSpec& probe = setup_.probe;
  // On a lathe the physical tool is the T code's tool number (T0101 -> tool 1).
  int current = lathe_ ? latheToolNumber(modal_.tool) : modal_.tool;
  // [tools.N] as the stock model finds it (by the turret number or the whole T word).
  const ToolSpec* tool = lathe_ ? physicalTool(setup_, current) : nullptr;
  if (!lathe_)
    if (auto it = setup_.tools.find(current); it != setup_.tools.end()) tool = &it->second;
  if ((probe.tool < 0 || probe.tool == current) && probe.ballDiameter > 0)
    r = probe.ballDiameter / 2;
  else if (tool)
    r = tool->diameter / 2;

  std::array<int64_t, kMaxAxes> fromM = machine_, toM;
  for (size_t k = 0; k < kMaxAxes; ++k) toM[k] = target[k] + offset_[k];
  checkStroke(toM);
  // Ball centres in machine coordinates, mm: the gauge point less the tool shift is the tip;
  // on a mill whose length offsets end at the bottom of the ball (probe.length_to) the
  // centre is a radius above it, along the spindle (+Z).
  const double centreAboveTip = !lathe_ && probe.lengthToBallBottom ? r : 0.0;
  auto tipMm = [&](const std::array<int64_t, kMaxAxes>& m) {
    Vec3 p{};
    for (size_t k = 0; k < 3; ++k) p[k] = static_cast<double>(m[k] - toolShift_[k]) / 1e6;
    p[2] += centreAboveTip;
    return p;
  };
  std::optional<double> t;
  if (probeWorld_) t = probeWorld_->firstContact(tipMm(fromM), tipMm(toM), r);
  if (stockProbe_) {
    // The stock has seen every earlier move: the stock sink sits before any stage that
    // holds moves back (app/session.cpp), and the block drained cutter compensation.
    std::optional<double> s = stockProbe_->firstContact(tipMm(fromM), tipMm(toM), r);
    if (s && (!t || *s < *t)) t = s;
  }
  if (t) {
    for (size_t k = 0; k < kMaxAxes; ++k)
      toM[k] = fromM[k] +
               static_cast<int64_t>(std::llround(*t * static_cast<double>(toM[k] - fromM[k])));
  }

  MoveEvent e;
  e.mode = MoveMode::Linear;
  e.feed = feed;
  double sq = 0;
  for (int k = 0; k < kMaxAxes; ++k) {
    double d =
        toProgramUnits(toM[static_cast<size_t>(k)] - fromM[static_cast<size_t>(k)], k, false);
    sq += d * d;
  }
  e.length = std::sqrt(sq);
  e.time = feed > 0 ? e.length / feed * 60.0 : 0.0;
  e.skip = true;
  emitMove(e, fromM, toM);
  machine_ = toM;

  // The program continues from the contact point in its own coordinates (without a
  // contact: from the programmed end point).
  if (!xf_.active()) {
    for (size_t k = 0; k < kMaxAxes; ++k) programmed_[k] = machine_[k] - offset_[k];
  } else if (t) {
    untransformProgrammed();
  } else {
    programmed_ = programTarget;
  }
  // The control latches the position in its detection unit: round to the least increment.
  for (int k = 0; k < kMaxAxes; ++k) {
    auto s = static_cast<size_t>(k);
    int64_t per = modal_.unit == InputUnit::Inch ? nmPerIncInch_[s] : nmPerIncMm_[s];
    double work = static_cast<double>(programmed_[s]);
    skip_[s] = static_cast<int64_t>(std::llround(work / static_cast<double>(per))) * per;
  }
  SkipEvent ev;
  ev.at = origin_;
  ev.hit = t.has_value();
  for (int k = 0; k < kMaxAxes; ++k) {
    ev.position[static_cast<size_t>(k)] = toProgramUnits(skip_[static_cast<size_t>(k)], k, true);
    ev.mposition[static_cast<size_t>(k)] =
        toProgramUnits(machine_[static_cast<size_t>(k)], k, true);
  }
  sink().onSkip(ev);
  if (!t && probe.missAlarm) throw AlarmError(AlarmId::SkipNotReceived);
}

Vec3 Executor::workOriginMm() const {
  Vec3 o{};
  for (size_t k = 0; k < 3; ++k) o[k] = static_cast<double>(offset_[k] - toolShift_[k]) / 1e6;
  return o;
}

}  // namespace ncvm
