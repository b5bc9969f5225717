// Reference positions and machine coordinates: G28/G30 (through the intermediate point),
// G27 reference position check, G29 return from the reference position, G53 positioning.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "exec/executor.hpp"
#include "exec/words.hpp"

namespace ncvm {

void Executor::referenceReturn(const Words& w, int which) {
  if (modal_.g[9] != 800) throw AlarmError(AlarmId::G27to30InCycle);
  if (which < 1 || which > 4)
    throw AlarmError(AlarmId::IllegalReferenceReturn, fmt::format("P{}", which));
  std::array<int64_t, kMaxAxes> mid{};
  uint32_t mask = 0;
  axisTargets(w, mid, mask);
  if (!mask) return;
  g28Mid_ = mid;
  g28MidSet_ = true;
  std::array<int64_t, kMaxAxes> toM = machine_;
  for (size_t k = 0; k < kMaxAxes; ++k)
    if (mask & (1u << k)) toM[k] = mid[k] + offset_[k];
  if (toM != machine_) rapidMachine(toM, mask);  // no leg when already at the intermediate point
  for (size_t k = 0; k < kMaxAxes; ++k) {
    if (!(mask & (1u << k))) continue;
    toM[k] = referenceNm(k, which);
  }
  if (toM != machine_) rapidMachine(toM, mask);
  for (size_t k = 0; k < kMaxAxes; ++k) programmed_[k] = machine_[k] - offset_[k];
}

// Reference point `which` (1-4) of axis k as a machine position in nm (radius on a diameter
// axis). Reference positions are fixed machine points, in mm whatever G20/G21 says.
int64_t Executor::referenceNm(size_t k, int which) const {
  const AxisConfig& a = setup_.axes[k];
  const double ref = a.reference[static_cast<size_t>(which - 1)];
  const int64_t nm =
      roundToIncrements(ref, incrementsPerUnit(setup_.increment, InputUnit::Mm)) * nmPerIncMm_[k];
  return a.diameter ? nm / 2 : nm;
}

// G27: rapid to the commanded point (with the active offsets), then every commanded axis
// must be at its first reference position; an axis that is not gives PS0092. Programs
// cancel the offsets first, as the manuals advise, or the check fails by the offset. In
// G41/G42 the compensation lookahead has ended before this block (nc_block.cpp) and the
// tool keeps the vector it has at the end of the block before: it arrives shifted by it
// (docs/fanuc-decisions.md), so with a cutter radius the check fails by the radius.
void Executor::referencePositionCheck(const Words& w) {
  if (modal_.g[9] != 800) throw AlarmError(AlarmId::G27to30InCycle);
  std::array<int64_t, kMaxAxes> target{};
  uint32_t mask = 0;
  if (!axisTargets(w, target, mask)) return;
  std::array<int64_t, kMaxAxes> here{};
  for (size_t k = 0; k < kMaxAxes; ++k) here[k] = machine_[k] - offset_[k];
  const std::array<int64_t, kMaxAxes> commanded = target;
  if (!lathe_ && modal_.g[7] != 400) {
    const size_t u = modal_.plane == 18 ? 2 : modal_.plane == 19 ? 1 : 0;
    const size_t v = modal_.plane == 18 ? 0 : modal_.plane == 19 ? 2 : 1;
    for (size_t k : {u, v})
      if (mask & (1u << k)) target[k] += here[k] - programmed_[k];
  }
  if (target != here) moveTo(target, MoveMode::Rapid, mask);  // no zero-length leg, as G28
  for (size_t k = 0; k < kMaxAxes; ++k)
    if (mask & (1u << k)) programmed_[k] = commanded[k];
  for (size_t k = 0; k < kMaxAxes; ++k) {
    if (!(mask & (1u << k))) continue;
    const AxisConfig& a = setup_.axes[k];
    const int64_t nm = referenceNm(k, 1);
    // The machine positions to its detection unit (the metric increment): an inch command
    // 3.937 in = 99.9998 mm reaches a 100.000 mm reference.
    if (std::llabs(machine_[k] - nm) * 2 >= nmPerIncMm_[k])
      throw AlarmError(
          AlarmId::ReferenceCheckError,
          fmt::format("{} is at {:.4f}, its reference position is {:.4f} (machine, mm)",
                      "XYZABC"[k], static_cast<double>(machine_[k]) / 1e6 * (a.diameter ? 2 : 1),
                      a.reference[0]));
  }
}

void Executor::returnFromReference(const Words& w) {
  if (modal_.g[9] != 800) throw AlarmError(AlarmId::G27to30InCycle);
  std::array<int64_t, kMaxAxes> target{};
  uint32_t mask = 0;
  axisTargets(w, target, mask);
  if (!mask) return;
  if (modal_.incremental && g28MidSet_) {
    // In G91 the end point is an increment from the intermediate point.
    for (size_t k = 0; k < kMaxAxes; ++k)
      if (mask & (1u << k)) target[k] = g28Mid_[k] + (target[k] - (machine_[k] - offset_[k]));
  }
  std::array<int64_t, kMaxAxes> toM = machine_;
  if (g28MidSet_) {
    for (size_t k = 0; k < kMaxAxes; ++k)
      if (mask & (1u << k)) toM[k] = g28Mid_[k] + offset_[k];
    if (toM != machine_) rapidMachine(toM, mask);
  }
  for (size_t k = 0; k < kMaxAxes; ++k)
    if (mask & (1u << k)) toM[k] = target[k] + offset_[k];
  rapidMachine(toM, mask);
  programmed_ = target;
}

void Executor::machinePositioning(const Words& w) {
  // G53: machine coordinates, absolute even in G91, at rapid.
  std::array<int64_t, kMaxAxes> toM = machine_;
  uint32_t mask = 0;
  static constexpr char kAbs[kMaxAxes] = {'X', 'Y', 'Z', 'A', 'B', 'C'};
  for (int k = 0; k < kMaxAxes; ++k) {
    auto s = static_cast<size_t>(k);
    if (!setup_.axes[s].present || !w.has(kAbs[k])) continue;
    int64_t nm = lengthNm(w.value(kAbs[k]), w.hasPoint(kAbs[k]), k);
    toM[s] = setup_.axes[s].diameter ? nm / 2 : nm;
    mask |= 1u << k;
  }
  if (!mask) return;
  rapidMachine(toM, mask);
  for (size_t k = 0; k < kMaxAxes; ++k) programmed_[k] = machine_[k] - offset_[k];
}

}  // namespace ncvm
