// Coordinate systems and offsets (fanuc-reference C and B.10): work offsets (EXT, G54-G59,
// G54.1 P1-P300), G52 local systems, G92/G50 coordinate setting, tool length offsets
// (G43/G44/G49, H) and lathe tool offsets (T code), G10 and the offset system variables.
// Every write goes through writeWorkOffset/writeToolOffset, which record an offset event.
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "exec/executor.hpp"
#include "exec/words.hpp"
#include "machine/offset_limits.hpp"

namespace ncvm {

namespace {
constexpr char kAxisLetters[kMaxAxes] = {'X', 'Y', 'Z', 'A', 'B', 'C'};
}  // namespace

int64_t Executor::offsetNm(double v, bool point, int slot) const {
  int64_t nm = lengthNm(v, point, slot);
  return setup_.axes[static_cast<size_t>(slot)].diameter ? nm / 2 : nm;
}

void Executor::initMemoryFromSetup() {
  for (const auto& [index, values] : setup_.workOffsets)
    for (int k = 0; k < kMaxAxes; ++k)
      mem_.work[static_cast<size_t>(index)][static_cast<size_t>(k)] =
          offsetNm(values[static_cast<size_t>(k)], true, k);
  for (const auto& [row, spec] : setup_.toolOffsets) {
    ToolOffsetRow& r = mem_.tools[static_cast<size_t>(row)];
    for (int f = 0; f < 4; ++f) {
      // Mill H/D and lathe Z/R/Y are plain lengths; lathe X is entered as a diameter.
      int slot = (lathe_ && f == kFieldXorH) ? 0 : 2;
      r.geometry[static_cast<size_t>(f)] =
          offsetNm(spec.geometry[static_cast<size_t>(f)], true, slot);
      r.wear[static_cast<size_t>(f)] = offsetNm(spec.wear[static_cast<size_t>(f)], true, slot);
    }
    r.tip = spec.tip;
  }
  for (const auto& [n, v] : setup_.initialVars)
    if (n >= 500) mem_.common500[static_cast<size_t>(n - 500)] = Value::num(v);
}

AxisArray Executor::workOffsetValues(int index) const {
  AxisArray out{};
  for (int k = 0; k < kMaxAxes; ++k)
    out[static_cast<size_t>(k)] =
        toProgramUnits(mem_.work[static_cast<size_t>(index)][static_cast<size_t>(k)], k, true);
  return out;
}

void Executor::recomputeOffset() {
  for (size_t k = 0; k < kMaxAxes; ++k)
    offset_[k] = mem_.work[kWorkExt][k] + mem_.work[static_cast<size_t>(workIndex_)][k] + g52_[k] +
                 g92_[k] + toolShift_[k];
  // The stock model places the moves on the machine with the work origin (a tool offset
  // moves the tip, not work zero): tell it when that changes.
  std::array<int64_t, 3> origin{};
  for (size_t k = 0; k < 3; ++k) origin[k] = offset_[k] - toolShift_[k];
  if (originKnown_ && origin == originSent_) return;
  originKnown_ = true;
  originSent_ = origin;
  sink().onWorkOrigin(WorkOriginEvent{origin_, workOriginMm()});
}

void Executor::writeWorkOffset(int index, int slot, int64_t nm, bool add) {
  auto& cell = mem_.work[static_cast<size_t>(index)][static_cast<size_t>(slot)];
  int64_t value = add ? cell + nm : nm;
  if (value > kMaxWorkOffsetNm || value < -kMaxWorkOffsetNm)
    throw AlarmError(AlarmId::IllegalOffsetValueInG10);
  cell = value;
  recomputeOffset();
  eventName_ = workOffsetName(index);
  sink().onOffset(
      OffsetEvent{origin_, "work", eventName_, slot, toProgramUnits(value, slot, true)});
}

void Executor::writeToolOffset(int row, int field, bool wear, int64_t nm, bool add) {
  if (row < 1 || row >= kToolRows)
    throw AlarmError(AlarmId::IllegalOffsetNumber, fmt::format("{}", row));
  ToolOffsetRow& r = mem_.tools[static_cast<size_t>(row)];
  int64_t& cell = (wear ? r.wear : r.geometry)[static_cast<size_t>(field)];
  int64_t value = add ? cell + nm : nm;
  if (value > kMaxToolOffsetNm || value < -kMaxToolOffsetNm)
    throw AlarmError(AlarmId::IllegalOffsetValueInG10);
  cell = value;
  static const char* millNames[] = {"H", "", "D", ""};
  static const char* latheNames[] = {"X", "Z", "R", "Y"};
  eventName_ = fmt::format("{}{} {}", lathe_ ? latheNames[field] : millNames[field], row,
                           wear ? "wear" : "geometry");
  int slot = (lathe_ && field == kFieldXorH) ? 0 : 2;
  sink().onOffset(OffsetEvent{origin_, "tool", eventName_, -1, toProgramUnits(value, slot, true)});
  applyToolShift();
}

void Executor::setTip(int row, int tip) {
  if (row < 1 || row >= kToolRows)
    throw AlarmError(AlarmId::IllegalOffsetNumber, fmt::format("{}", row));
  if (tip < 0 || tip > kMaxTipDirection)
    throw AlarmError(AlarmId::IllegalOffsetValueInG10, "imaginary tip 0-9");
  mem_.tools[static_cast<size_t>(row)].tip = tip;
  eventName_ = fmt::format("T{} tip", row);
  sink().onOffset(OffsetEvent{origin_, "tool", eventName_, -1, static_cast<double>(tip)});
}

// The tool shift follows the modal state: G43/G44 with H on a mill (type A: always Z), the
// T code's geometry and wear numbers on a lathe.
void Executor::applyToolShift() {
  toolShift_.fill(0);
  if (!lathe_) {
    int h = modal_.hOffset;
    int mode = modal_.g[8];
    if ((mode == 430 || mode == 440) && h > 0 && h < kToolRows) {
      const ToolOffsetRow& r = mem_.tools[static_cast<size_t>(h)];
      int64_t len = r.geometry[kFieldXorH] + r.wear[kFieldXorH];
      toolShift_[2] = mode == 430 ? len : -len;
    }
  } else {
    int tool = latheGeometryNumber(modal_.tool);
    int wear = latheWearNumber(modal_.tool);
    if (wear != 0 && wear < kToolRows) {
      const ToolOffsetRow& w = mem_.tools[static_cast<size_t>(wear)];
      const ToolOffsetRow& g = mem_.tools[static_cast<size_t>(tool < kToolRows ? tool : 0)];
      toolShift_[0] = g.geometry[kFieldXorH] + w.wear[kFieldXorH];
      toolShift_[2] = g.geometry[kFieldZ] + w.wear[kFieldZ];
      if (setup_.axes[1].present) toolShift_[1] = g.geometry[kFieldY] + w.wear[kFieldY];
    }
  }
  recomputeOffset();
}

// G10 (programmable data input): L2 work offsets, L20 G54.1 P, L10-L13 mill tool offsets
// (memory C), and the lathe form without L. G90 replaces, G91 (or U/W/V/C) adds.
// The block is all or nothing, as on the control: every value is read and checked first,
// so a value out of range (PS0032) leaves the offsets the block names unchanged.
void Executor::programmableDataInput(const Words& w) {
  struct Write {
    enum Kind { Work, Tool, Tip } kind;
    int index, field;  // work index and axis slot; tool row and field; tip row
    bool wear;
    int64_t nm;  // value (tip: the direction)
    bool add;
  };
  std::vector<Write> writes;
  int L = w.has('L') ? static_cast<int>(std::llround(w.value('L'))) : -1;
  int P = w.has('P') ? static_cast<int>(std::llround(w.value('P'))) : -1;
  bool add = modal_.incremental;
  if (L == 2 || L == 20) {
    int index = L == 2 ? P : (P >= 1 && P <= 300 ? kWorkP1 + P - 1 : -1);
    if ((L == 2 && (P < 0 || P > 6)) || index < 0)
      throw AlarmError(AlarmId::IllegalPInG10, fmt::format("L{} P{}", L, P));
    static constexpr char kInc[kMaxAxes] = {'U', 'V', 'W', 0, 0, 'H'};
    for (int k = 0; k < kMaxAxes; ++k) {
      if (!setup_.axes[static_cast<size_t>(k)].present) continue;
      char a = kAxisLetters[k];
      if (w.has(a))
        writes.push_back(
            {Write::Work, index, k, false, offsetNm(w.value(a), w.hasPoint(a), k), add});
      if (lathe_ && kInc[k] && w.has(kInc[k]))
        writes.push_back({Write::Work, index, k, false,
                          offsetNm(w.value(kInc[k]), w.hasPoint(kInc[k]), k), true});
    }
  } else if (!lathe_) {
    if (L < 10 || L > 13)
      throw AlarmError(AlarmId::IllegalPInG10,
                       L < 0 ? std::string("G10 needs L") : fmt::format("L{}", L));
    if (P < 1 || P >= kToolRows) throw AlarmError(AlarmId::IllegalPInG10, fmt::format("P{}", P));
    if (!w.has('R')) return;
    int field = L <= 11 ? kFieldXorH : kFieldRorD;
    writes.push_back({Write::Tool, P, field, L == 11 || L == 13,
                      lengthNm(w.value('R'), w.hasPoint('R'), 2), add});
  } else {
    // Lathe: G10 P n (wear) or P 10000+n (geometry), X/U Z/W R/C Y/V Q.
    if (L != -1 && L != 1 && L != 10 && L != 11)
      throw AlarmError(AlarmId::IllegalPInG10, fmt::format("L{}", L));
    bool geometry = P > 10000;
    int row = geometry ? P - 10000 : P;
    if (row < 1 || row >= kToolRows)
      throw AlarmError(AlarmId::IllegalPInG10, fmt::format("P{}", P));
    struct F {
      char abs, inc;
      int field, slot;
    };
    static constexpr F fields[] = {{'X', 'U', kFieldXorH, 0},
                                   {'Z', 'W', kFieldZ, 2},
                                   {'R', 'C', kFieldRorD, 2},
                                   {'Y', 'V', kFieldY, 1}};
    for (const F& f : fields) {
      if (w.has(f.abs))
        writes.push_back({Write::Tool, row, f.field, !geometry,
                          offsetNm(w.value(f.abs), w.hasPoint(f.abs), f.slot), false});
      if (w.has(f.inc))
        writes.push_back({Write::Tool, row, f.field, !geometry,
                          offsetNm(w.value(f.inc), w.hasPoint(f.inc), f.slot), true});
    }
    if (w.has('Q'))
      writes.push_back({Write::Tip, row, 0, false, std::llround(w.value('Q')), false});
  }
  // Check: each value as it would be after the writes before it in the block.
  std::vector<std::pair<const int64_t*, int64_t>> after;
  for (const Write& x : writes) {
    if (x.kind == Write::Tip) {
      if (x.nm < 0 || x.nm > 9)
        throw AlarmError(AlarmId::IllegalOffsetValueInG10, "imaginary tip 0-9");
      continue;
    }
    const int64_t* cell =
        x.kind == Write::Work
            ? &mem_.work[static_cast<size_t>(x.index)][static_cast<size_t>(x.field)]
            : &(x.wear ? mem_.tools[static_cast<size_t>(x.index)].wear
                       : mem_.tools[static_cast<size_t>(x.index)]
                             .geometry)[static_cast<size_t>(x.field)];
    int64_t old = *cell;
    for (const auto& [c, v] : after)
      if (c == cell) old = v;
    int64_t value = x.add ? old + x.nm : x.nm;
    int64_t limit = x.kind == Write::Work ? kMaxWorkOffsetNm : kMaxToolOffsetNm;
    if (value > limit || value < -limit) throw AlarmError(AlarmId::IllegalOffsetValueInG10);
    after.emplace_back(cell, value);
  }
  for (const Write& x : writes) {
    if (x.kind == Write::Work)
      writeWorkOffset(x.index, x.field, x.nm, x.add);
    else if (x.kind == Write::Tool)
      writeToolOffset(x.index, x.field, x.wear, x.nm, x.add);
    else
      setTip(x.index, static_cast<int>(x.nm));
  }
}

// G52: local coordinate system inside every work system; G52 with zero cancels it.
void Executor::localCoordinates(const Words& w) {
  for (int k = 0; k < kMaxAxes; ++k) {
    if (!setup_.axes[static_cast<size_t>(k)].present || !w.has(kAxisLetters[k])) continue;
    char a = kAxisLetters[k];
    g52_[static_cast<size_t>(k)] = offsetNm(w.value(a), w.hasPoint(a), k);
    eventName_ = "G52";
    sink().onOffset(OffsetEvent{origin_, "local", eventName_, k,
                                toProgramUnits(g52_[static_cast<size_t>(k)], k, true)});
  }
  recomputeOffset();
  for (size_t k = 0; k < kMaxAxes; ++k) programmed_[k] = machine_[k] - offset_[k];
}

// G92 (mill, lathe systems B/C) and G50 (lathe system A): the tool's current position
// becomes the commanded coordinates, by shifting every work system.
void Executor::coordinateSetting(const Words& w) {
  static constexpr char kInc[kMaxAxes] = {'U', 'V', 'W', 0, 0, 'H'};
  for (int k = 0; k < kMaxAxes; ++k) {
    auto s = static_cast<size_t>(k);
    if (!setup_.axes[s].present) continue;
    char a = kAxisLetters[k];
    bool incremental = lathe_ && kInc[k] && w.has(kInc[k]);
    if (!w.has(a) && !incremental) continue;
    // The wanted coordinate; U/W count from the position shown before the command.
    int64_t shown = machine_[s] - offset_[s];
    int64_t wanted = w.has(a) ? offsetNm(w.value(a), w.hasPoint(a), k)
                              : shown + offsetNm(w.value(kInc[k]), w.hasPoint(kInc[k]), k);
    // G92 cancels the local coordinate system (G52) on the axes it names.
    if (g52_[s] != 0) {
      g52_[s] = 0;
      eventName_ = "G52";
      sink().onOffset(OffsetEvent{origin_, "local", eventName_, k, 0.0});
    }
    recomputeOffset();
    g92_[s] += (machine_[s] - offset_[s]) - wanted;
    recomputeOffset();
    eventName_ = "G92";
    sink().onOffset(OffsetEvent{origin_, "shift", eventName_, k, toProgramUnits(g92_[s], k, true)});
  }
  for (size_t k = 0; k < kMaxAxes; ++k) programmed_[k] = machine_[k] - offset_[k];
}

// G92.1 IP0: the work coordinate system preset. The G92 shift and the G52 local system go
// away on the axes named, so the work system is again the one the offsets define.
void Executor::coordinatePreset(const Words& w) {
  for (int k = 0; k < kMaxAxes; ++k) {
    auto s = static_cast<size_t>(k);
    if (!setup_.axes[s].present || !w.has(kAxisLetters[k])) continue;
    if (w.value(kAxisLetters[k]) != 0)
      throw AlarmError(AlarmId::ImproperGCode, "G92.1 takes IP0 only");
    g92_[s] = 0;
    g52_[s] = 0;
    eventName_ = "G92";
    sink().onOffset(OffsetEvent{origin_, "shift", eventName_, k, 0.0});
  }
  recomputeOffset();
  for (size_t k = 0; k < kMaxAxes; ++k) programmed_[k] = machine_[k] - offset_[k];
}

double Executor::cssRpmAt(int64_t xMachine) const {
  double dia = std::fabs(toProgramUnits(xMachine - offset_[0], 0, true));
  double perMin = modal_.unit == InputUnit::Inch ? 12.0 : 1000.0;
  double rpm = dia > 0 ? modal_.speed * perMin / (std::numbers::pi * dia) : spindleClamp_;
  if (spindleClamp_ > 0) rpm = std::min(rpm, spindleClamp_);
  return std::round(rpm);
}

void Executor::checkStroke(const std::array<int64_t, kMaxAxes>& toMachine) {
  for (int k = 0; k < kMaxAxes; ++k) {
    const AxisConfig& a = setup_.axes[static_cast<size_t>(k)];
    if (!a.present) continue;
    double pos = toProgramUnits(toMachine[static_cast<size_t>(k)], k, true);
    double unit = (modal_.unit == InputUnit::Inch && !a.rotary) ? 25.4 : 1.0;  // limits in mm / deg
    if (pos * unit > a.max + 1e-9)
      throw AlarmError(AlarmId::OvertravelPlus,
                       fmt::format("{} {:.3f} > {:.3f}", a.name, pos * unit, a.max));
    if (pos * unit < a.min - 1e-9)
      throw AlarmError(AlarmId::OvertravelMinus,
                       fmt::format("{} {:.3f} < {:.3f}", a.name, pos * unit, a.min));
  }
}

// Offset system variables. Returns false when n is not one of them.
bool Executor::offsetVariable(int64_t n, Value* read, const Value* write) {
  auto axisOf = [&](int64_t k) {
    int slot = axisByNumber(static_cast<int>(k) + 1);
    if (slot < 0)
      throw AlarmError(AlarmId::VariableOutOfRange, fmt::format("#{}: no such axis", n));
    return slot;
  };
  auto workVar = [&](int index, int slot) {
    if (read) {
      *read = Value::num(toProgramUnits(
          mem_.work[static_cast<size_t>(index)][static_cast<size_t>(slot)], slot, true));
    } else {
      writeWorkOffset(index, slot, offsetNm(write->asNumber(), true, slot), false);
    }
    return true;
  };
  if (n >= 5201 && n <= 5340 && (n - 5201) % 20 < 20) {
    int table = static_cast<int>((n - 5201) / 20);
    if (table <= 6) return workVar(table, axisOf((n - 5201) % 20));
  }
  if (!lathe_ && n >= 7001 && n <= 7960)
    return workVar(kWorkP1 + static_cast<int>((n - 7001) / 20), axisOf((n - 7001) % 20));
  if (!lathe_ && n >= 14001 && n <= 19980)
    return workVar(kWorkP1 + static_cast<int>((n - 14001) / 20), axisOf((n - 14001) % 20));

  auto toolVar = [&](int row, int field, bool wear, int slot) {
    if (row < 1 || row >= kToolRows)
      throw AlarmError(AlarmId::VariableOutOfRange, fmt::format("#{}", n));
    if (read) {
      const ToolOffsetRow& r = mem_.tools[static_cast<size_t>(row)];
      *read = Value::num(
          toProgramUnits((wear ? r.wear : r.geometry)[static_cast<size_t>(field)], slot, true));
    } else {
      writeToolOffset(row, field, wear, offsetNm(write->asNumber(), true, slot), false);
    }
    return true;
  };
  if (!lathe_) {
    // Memory C: #10001 H wear, #11001 H geometry, #12001 D wear, #13001 D geometry; the
    // #2001-#2800 banks alias the first 200 of each.
    if (n >= 10001 && n <= 13999 && n % 1000 != 0) {
      int bank = static_cast<int>(n / 1000) - 10;
      return toolVar(static_cast<int>(n % 1000), bank < 2 ? kFieldXorH : kFieldRorD, bank % 2 == 0,
                     2);
    }
    if (n >= 2001 && n <= 2800) {
      int bank = static_cast<int>((n - 2001) / 200);
      int row = static_cast<int>((n - 2001) % 200) + 1;
      return toolVar(row, bank < 2 ? kFieldXorH : kFieldRorD, bank % 2 == 0, 2);
    }
  } else if (n >= 2001 && n <= 2964) {
    // Lathe (64 sets): #2001 X wear, #2101 Z wear, #2201 R wear, #2301 tip, #2401 Y wear,
    // #2701 X geometry, #2801 Z geometry, #2901 R geometry.
    int bank = static_cast<int>((n - 2001) / 100);
    int row = static_cast<int>((n - 2001) % 100) + 1;
    if (row > 64) return false;
    switch (bank) {
      case 0:
        return toolVar(row, kFieldXorH, true, 0);
      case 1:
        return toolVar(row, kFieldZ, true, 2);
      case 2:
        return toolVar(row, kFieldRorD, true, 2);
      case 3:
        if (read)
          *read = Value::num(mem_.tools[static_cast<size_t>(row)].tip);
        else
          setTip(row, static_cast<int>(std::llround(write->asNumber())));
        return true;
      case 4:
        return toolVar(row, kFieldY, true, 1);
      case 7:
        return toolVar(row, kFieldXorH, false, 0);
      case 8:
        return toolVar(row, kFieldZ, false, 2);
      case 9:
        return toolVar(row, kFieldRorD, false, 2);
      default:
        return false;
    }
  }
  return false;
}

}  // namespace ncvm
