#include "app/machine_state.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace ncvm {

namespace {
constexpr const char* kFormat = "ncvm-machine-state/1";

double toMm(int64_t nm, bool diameter) { return static_cast<double>(nm) / 1e6 * (diameter ? 2.0 : 1.0); }
int64_t fromMm(double mm, bool diameter) {
  return static_cast<int64_t>(std::llround(mm * 1e6 / (diameter ? 2.0 : 1.0)));
}
bool latheX(const Setup& s, int field) { return s.kind == MachineKind::Lathe && field == kFieldXorH; }
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
      j[std::string(name) + "_geometry"] = toMm(row.geometry[static_cast<size_t>(f)], latheX(setup, f));
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
    if (!mem.common500[static_cast<size_t>(k)].null) vars["#" + std::to_string(500 + k)] = mem.common500[static_cast<size_t>(k)].v;
  return nlohmann::json{{"format", kFormat},
                        {"units", "mm"},
                        {"vars", vars},
                        {"work_offsets", workOffsetsJson(mem, setup, false)},
                        {"tool_offsets", toolOffsetsJson(mem, setup)},
                        {"parts", {{"#3901", mem.parts3901}, {"#3902", mem.parts3902}}}};
}

void memoryFromJson(const nlohmann::json& j, const Setup& setup, MachineMemory& mem) {
  if (!j.is_object() || j.value("format", "") != kFormat)
    throw std::runtime_error(std::string("not an ncvm machine-state file (format ") + kFormat + ")");
  if (j.contains("vars")) {
    for (const auto& [key, value] : j["vars"].items()) {
      int n = -1;
      if (key.size() > 1 && key[0] == '#') std::from_chars(key.data() + 1, key.data() + key.size(), n);
      if (n < 500 || n > 999 || !value.is_number()) throw std::runtime_error("vars: " + key);
      mem.common500[static_cast<size_t>(n - 500)] = Value::num(value.get<double>());
    }
  }
  if (j.contains("work_offsets")) {
    for (const auto& [name, axes] : j["work_offsets"].items()) {
      int idx = workOffsetIndex(name);
      if (idx < 0 || !axes.is_object()) throw std::runtime_error("work_offsets: " + name);
      for (const auto& [letter, value] : axes.items()) {
        int slot = setup.axisSlot(letter.empty() ? '?' : letter[0]);
        if (slot < 0 || letter.size() != 1 || !value.is_number()) throw std::runtime_error("work_offsets." + name + "." + letter);
        mem.work[static_cast<size_t>(idx)][static_cast<size_t>(slot)] =
            fromMm(value.get<double>(), setup.axes[static_cast<size_t>(slot)].diameter);
      }
    }
  }
  if (j.contains("tool_offsets")) {
    bool lathe = setup.kind == MachineKind::Lathe;
    for (const auto& [num, row] : j["tool_offsets"].items()) {
      int r = 0;
      auto parsed = std::from_chars(num.data(), num.data() + num.size(), r);
      if (parsed.ec != std::errc() || parsed.ptr != num.data() + num.size())
        throw std::runtime_error("tool_offsets: \"" + num + "\" is not an offset number");
      if (r < 1 || r >= kToolRows || !row.is_object()) throw std::runtime_error("tool_offsets: " + num);
      ToolOffsetRow& t = mem.tools[static_cast<size_t>(r)];
      for (int f = 0; f < 4; ++f) {
        static const char* millNames[] = {"h", "", "d", ""};
        static const char* latheNames[] = {"x", "z", "r", "y"};
        const char* name = lathe ? latheNames[f] : millNames[f];
        if (!*name) continue;
        if (row.contains(std::string(name) + "_geometry"))
          t.geometry[static_cast<size_t>(f)] = fromMm(row[std::string(name) + "_geometry"].get<double>(), latheX(setup, f));
        if (row.contains(std::string(name) + "_wear"))
          t.wear[static_cast<size_t>(f)] = fromMm(row[std::string(name) + "_wear"].get<double>(), latheX(setup, f));
      }
      if (row.contains("tip")) t.tip = row["tip"].get<int>();
    }
  }
  if (j.contains("parts")) {
    mem.parts3901 = j["parts"].value("#3901", 0.0);
    mem.parts3902 = j["parts"].value("#3902", 0.0);
  }
}

}  // namespace ncvm
