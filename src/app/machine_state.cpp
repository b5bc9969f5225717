#include "app/machine_state.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "machine/offset_limits.hpp"

namespace ncvm {

namespace {
constexpr const char* kFormat = "ncvm-machine-state/1";

double toMm(int64_t nm, bool diameter) {
  return static_cast<double>(nm) / 1e6 * (diameter ? 2.0 : 1.0);
}
bool latheX(const Setup& s, int field) {
  return s.kind == MachineKind::Lathe && field == kFieldXorH;
}
}  // namespace

nlohmann::json workOffsetsJson(const MachineMemory& mem, const Setup& setup, bool all) {
  nlohmann::json out = nlohmann::json::object();
  for (int i = 0; i < kWorkTables; ++i) {
    const auto& row = mem.work[static_cast<size_t>(i)];
    bool zero = true;
    for (auto v : row) zero &= v == 0;
    if (zero && !all && i >= kWorkP1) continue;
    if (zero && i >= kWorkP1) continue;
    nlohmann::json axes = nlohmann::json::object();
    for (int k = 0; k < kMaxAxes; ++k) {
      const AxisConfig& a = setup.axes[static_cast<size_t>(k)];
      if (a.present) axes[std::string(1, a.name)] = toMm(row[static_cast<size_t>(k)], a.diameter);
    }
    out[workOffsetName(i)] = axes;
  }
  return out;
}

nlohmann::json toolOffsetsJson(const MachineMemory& mem, const Setup& setup) {
  nlohmann::json out = nlohmann::json::object();
  bool lathe = setup.kind == MachineKind::Lathe;
  static const char* millNames[] = {"h", "", "d", ""};
  static const char* latheNames[] = {"x", "z", "r", "y"};
  for (int r = 1; r < kToolRows; ++r) {
    const ToolOffsetRow& row = mem.tools[static_cast<size_t>(r)];
    if (row.empty()) continue;
    nlohmann::json j = nlohmann::json::object();
    for (int f = 0; f < 4; ++f) {
      const char* name = lathe ? latheNames[f] : millNames[f];
      if (!*name) continue;
      j[std::string(name) + "_geometry"] =
          toMm(row.geometry[static_cast<size_t>(f)], latheX(setup, f));
      j[std::string(name) + "_wear"] = toMm(row.wear[static_cast<size_t>(f)], latheX(setup, f));
    }
    if (lathe) j["tip"] = row.tip;
    out[std::to_string(r)] = j;
  }
  return out;
}

nlohmann::json memoryToJson(const MachineMemory& mem, const Setup& setup) {
  nlohmann::json vars = nlohmann::json::object();
  for (int k = 0; k < 500; ++k)
    if (!mem.common500[static_cast<size_t>(k)].null)
      vars["#" + std::to_string(500 + k)] = mem.common500[static_cast<size_t>(k)].v;
  return nlohmann::json{{"format", kFormat},
                        {"units", "mm"},
                        {"vars", vars},
                        {"work_offsets", workOffsetsJson(mem, setup, false)},
                        {"tool_offsets", toolOffsetsJson(mem, setup)},
                        {"parts", {{"#3901", mem.parts3901}, {"#3902", mem.parts3902}}}};
}

namespace {
// A bad value is refused with its key and value: the file is left as it is for the user.
[[noreturn]] void refuse(const std::string& key, const nlohmann::json& value,
                         const std::string& why) {
  throw std::runtime_error(
      fmt::format("{} = {}: {}", key,
                  value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), why));
}

double finiteNumber(const nlohmann::json& v, const std::string& key) {
  if (!v.is_number()) refuse(key, v, "not a number");
  double d = v.get<double>();
  if (!std::isfinite(d)) refuse(key, v, "not a finite number");
  return d;
}

// A length in mm within the control's limit (limitNm as stored: a lathe X as a radius).
int64_t offsetLength(const nlohmann::json& v, const std::string& key, bool diameter,
                     int64_t limitNm) {
  const double scale = diameter ? 2.0 : 1.0;
  const double nm = finiteNumber(v, key) * 1e6 / scale;
  if (std::fabs(nm) > static_cast<double>(limitNm))
    refuse(key, v,
           fmt::format("beyond the control's limit of ±{:.3f} mm (G10, PS0032)",
                       static_cast<double>(limitNm) * scale / 1e6));
  return static_cast<int64_t>(std::llround(nm));
}

const nlohmann::json& objectAt(const nlohmann::json& j, const std::string& key) {
  if (!j.is_object()) refuse(key, j, "not an object");
  return j;
}
}  // namespace

void memoryFromJson(const nlohmann::json& j, const Setup& setup, MachineMemory& mem) {
  if (!j.is_object() || !j.contains("format") || j["format"] != kFormat)
    throw std::runtime_error(std::string("not an ncvm machine-state file (format ") + kFormat +
                             ")");
  for (const auto& [key, value] : j.items())
    if (key != "format" && key != "units" && key != "vars" && key != "work_offsets" &&
        key != "tool_offsets" && key != "parts")
      refuse(key, value, "unknown key (format, units, vars, work_offsets, tool_offsets, parts)");
  if (j.contains("units") && j["units"] != "mm")
    refuse("units", j["units"], "the file's units are mm");
  if (j.contains("vars")) {
    for (const auto& [key, value] : objectAt(j["vars"], "vars").items()) {
      int n = -1;
      if (key.size() > 1 && key[0] == '#') {
        auto parsed = std::from_chars(key.data() + 1, key.data() + key.size(), n);
        if (parsed.ptr != key.data() + key.size()) n = -1;
      }
      const std::string where = "vars." + key;
      if (n < 500 || n > 999) refuse(where, value, "the file keeps #500-#999");
      mem.common500[static_cast<size_t>(n - 500)] = Value::num(finiteNumber(value, where));
    }
  }
  if (j.contains("work_offsets")) {
    for (const auto& [name, axes] : objectAt(j["work_offsets"], "work_offsets").items()) {
      int idx = workOffsetIndex(name);
      const std::string where = "work_offsets." + name;
      if (idx < 0) refuse(where, axes, "not a work offset (EXT, G54-G59, G54.1 P1-P300)");
      for (const auto& [letter, value] : objectAt(axes, where).items()) {
        int slot = letter.size() == 1 ? setup.axisSlot(letter[0]) : -1;
        if (slot < 0) refuse(where + "." + letter, value, "not an axis of this machine");
        mem.work[static_cast<size_t>(idx)][static_cast<size_t>(slot)] =
            offsetLength(value, where + "." + letter,
                         setup.axes[static_cast<size_t>(slot)].diameter, kMaxWorkOffsetNm);
      }
    }
  }
  if (j.contains("tool_offsets")) {
    bool lathe = setup.kind == MachineKind::Lathe;
    static const char* millNames[] = {"h", "", "d", ""};
    static const char* latheNames[] = {"x", "z", "r", "y"};
    for (const auto& [num, row] : objectAt(j["tool_offsets"], "tool_offsets").items()) {
      int r = 0;
      auto parsed = std::from_chars(num.data(), num.data() + num.size(), r);
      const std::string where = "tool_offsets." + num;
      if (parsed.ec != std::errc() || parsed.ptr != num.data() + num.size() || r < 1 ||
          r >= kToolRows)
        refuse(where, row, "offset numbers are 1-999");
      ToolOffsetRow& t = mem.tools[static_cast<size_t>(r)];
      for (const auto& [field, value] : objectAt(row, where).items()) {
        const std::string key = where + "." + field;
        if (lathe && field == "tip") {
          double tip = finiteNumber(value, key);
          if (tip != std::floor(tip) || tip < 0 || tip > kMaxTipDirection)
            refuse(key, value, "the imaginary tip direction is 0-9");
          t.tip = static_cast<int>(tip);
          continue;
        }
        bool known = false;
        for (int f = 0; f < 4 && !known; ++f) {
          const std::string name = lathe ? latheNames[f] : millNames[f];
          if (name.empty()) continue;
          for (bool wear : {false, true}) {
            if (field != name + (wear ? "_wear" : "_geometry")) continue;
            (wear ? t.wear : t.geometry)[static_cast<size_t>(f)] =
                offsetLength(value, key, latheX(setup, f), kMaxToolOffsetNm);
            known = true;
          }
        }
        if (!known)
          refuse(key, value,
                 lathe ? "a lathe offset has x, z, r, y (_geometry, _wear) and tip"
                       : "a mill offset has h_geometry, h_wear, d_geometry, d_wear");
      }
    }
  }
  if (j.contains("parts")) {
    for (const auto& [key, value] : objectAt(j["parts"], "parts").items()) {
      if (key == "#3901")
        mem.parts3901 = finiteNumber(value, "parts.#3901");
      else if (key == "#3902")
        mem.parts3902 = finiteNumber(value, "parts.#3902");
      else
        refuse("parts." + key, value, "the part counters are #3901 and #3902");
    }
  }
}

}  // namespace ncvm
