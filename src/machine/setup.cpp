#include "machine/setup.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <variant>

#include "machine/setup_keys.hpp"
#include "machine/timing_keys.hpp"

namespace ncvm {
namespace {

// Friendly names of bit parameters, as Fanuc manuals spell them.
const std::map<std::string, std::string>& parameterAliases() {
  static const std::map<std::string, std::string> aliases = {
      {"DPI", "3401#0"}, {"NAT", "6004#0"}, {"LRP", "1401#1"}, {"PRT", "6001#1"}, {"TCS", "6001#5"},
      {"CCV", "6001#6"}, {"CLV", "6001#7"}, {"SBM", "6000#5"}, {"M3B", "3404#7"}, {"TVC", "0000#0"},
      {"CIR", "3403#5"}, {"LGN", "5002#1"}, {"F16", "6008#0"},
  };
  return aliases;
}

bool isParameterNumber(const std::string& key) {
  size_t i = 0;
  while (i < key.size() && std::isdigit(static_cast<unsigned char>(key[i]))) ++i;
  if (i < 4 || i > 5) return false;
  if (i == key.size()) return true;
  return key.size() == i + 2 && key[i] == '#' && key[i + 1] >= '0' && key[i + 1] <= '7';
}

// An axis-type parameter for one axis: "5421.X", "5401#0.Z".
bool isAxisParameter(const std::string& key) {
  auto dot = key.rfind('.');
  return dot != std::string::npos && dot + 2 == key.size() &&
         std::string("XYZABC").find(key[dot + 1]) != std::string::npos &&
         isParameterNumber(key.substr(0, dot));
}

using SettingValue = std::variant<bool, double, std::string, std::vector<double>>;

struct Where {
  std::string key;
  int line = 0;
  int col = 0;
};

[[noreturn]] void bad(const Where& w, const std::string& why) {
  std::string text = fmt::format("{}: {}", w.key, why);
  // A key the setup does not know: the nearest one it does ("did you mean machine.kind?").
  if ((why.rfind("unknown", 0) == 0 && why.find("key") != std::string::npos) ||
      why.find(" keys") != std::string::npos || why.find("fields:") != std::string::npos ||
      why.find("a parameter is a number") != std::string::npos)
    if (auto near = nearestSetupKey(w.key)) text += fmt::format(" (did you mean {}?)", *near);
  SetupError e(text, w.key, w.line);
  e.col = w.col;
  throw e;
}

// A setup error located in its file: "FILE:LINE:COL: KEY: WHY".
[[noreturn]] void inFile(const SetupError& e, const std::string& file, std::string why = {}) {
  if (why.empty()) why = e.what();
  SetupError located(fmt::format("{}:{}:{}: {}", file, e.line, e.col, why), e.key, e.line);
  located.col = e.col;
  located.file = file;
  throw located;
}

double asNumber(const SettingValue& v, const Where& w) {
  if (auto* d = std::get_if<double>(&v)) return *d;
  if (auto* b = std::get_if<bool>(&v)) return *b ? 1.0 : 0.0;
  bad(w, "expected a number");
}
bool asBool(const SettingValue& v, const Where& w) {
  if (auto* b = std::get_if<bool>(&v)) return *b;
  if (auto* d = std::get_if<double>(&v)) return *d != 0;
  bad(w, "expected true or false");
}
const std::string& asString(const SettingValue& v, const Where& w) {
  if (auto* s = std::get_if<std::string>(&v)) return *s;
  bad(w, "expected a string");
}
int64_t asInteger(const SettingValue& v, const Where& w) {
  double d = asNumber(v, w);
  if (d != static_cast<double>(static_cast<int64_t>(d))) bad(w, "expected a whole number");
  return static_cast<int64_t>(d);
}

void applyControlDefaults(Setup& s) {
  if (s.control == "16i" || s.control == "18i" || s.control == "21i" || s.control == "0i-C") {
    s.limits.macroNesting = 4;
    s.limits.subprogramNesting = 4;
    s.limits.totalNesting = 8;
  } else {
    s.limits.macroNesting = 5;
    s.limits.subprogramNesting = 10;
    s.limits.totalNesting = 15;
  }
}

// The one place where a setting is interpreted; TOML files and --set both come here.
void applyKey(Setup& s, const std::string& key, const SettingValue& v, int line, int col = 0) {
  Where w{key, line, col};
  auto dot = key.find('.');
  std::string head = key.substr(0, dot);
  std::string rest = dot == std::string::npos ? "" : key.substr(dot + 1);

  if (head == "machine") {
    if (rest == "kind") {
      const auto& k = asString(v, w);
      if (k != "mill" && k != "lathe") bad(w, "expected \"mill\" or \"lathe\"");
      Setup fresh = defaultSetup(k == "lathe" ? MachineKind::Lathe : MachineKind::Mill);
      // Kind decides the axes; keep what was already set otherwise (also the axes when the
      // kind does not change, so a job file may repeat the kind of the preset before it).
      if (fresh.kind != s.kind) s.axes = fresh.axes;
      s.kind = fresh.kind;
    } else if (rest == "control") {
      s.control = asString(v, w);
      static const char* known[] = {"0i-F", "0i-D", "30i", "31i", "16i", "18i", "21i", "0i-C"};
      bool ok = false;
      for (auto* k : known) ok |= s.control == k;
      if (!ok) bad(w, "unknown control (0i-F, 0i-D, 30i, 31i, 16i, 18i, 21i, 0i-C)");
      applyControlDefaults(s);
    } else if (rest == "gcode_system") {
      const auto& g = asString(v, w);
      if (g != "A" && g != "B" && g != "C") bad(w, "expected \"A\", \"B\" or \"C\"");
      s.gcodeSystem = g[0];
    } else if (rest == "program_number_digits") {
      int64_t d = asInteger(v, w);
      if (d != 4 && d != 8) bad(w, "expected 4 or 8");
      s.programNumberDigits = static_cast<int>(d);
    } else if (rest == "increment") {
      const auto& g = asString(v, w);
      if (g == "IS-A")
        s.increment = IncrementSystem::IsA;
      else if (g == "IS-B")
        s.increment = IncrementSystem::IsB;
      else if (g == "IS-C")
        s.increment = IncrementSystem::IsC;
      else
        bad(w, "expected \"IS-A\", \"IS-B\" or \"IS-C\"");
    } else if (rest == "units") {
      const auto& g = asString(v, w);
      if (g != "mm" && g != "inch") bad(w, "expected \"mm\" or \"inch\"");
      s.initialUnit = g == "inch" ? InputUnit::Inch : InputUnit::Mm;
    } else {
      bad(w, "unknown key");
    }
    return;
  }
  if (head == "parameters" || isAxisParameter(key) ||
      (dot == std::string::npos && (isParameterNumber(key) || parameterAliases().count(key)))) {
    std::string p = head == "parameters" ? rest : key;
    if (auto it = parameterAliases().find(p); it != parameterAliases().end()) p = it->second;
    if (!isParameterNumber(p) && !isAxisParameter(p))
      bad(w,
          "a parameter is a number like 3401#0 or 3410 (5421.X for one axis), or an alias (DPI, "
          "NAT, LRP, ...)");
    const double value = asNumber(v, w);
    // A bit parameter (3401#0, DPI) holds 0 or 1, as on the control's parameter screen.
    if (p.find('#') != std::string::npos && value != 0 && value != 1)
      bad(w, fmt::format("{} is a bit parameter: 0 or 1 (true or false), not {}", p, value));
    s.parameters[p] = value;
    return;
  }
  if (head == "block_skip") {
    int n = rest.size() == 1 ? rest[0] - '0' : -1;
    if (n < 1 || n > 9) bad(w, "block_skip.N with N from 1 to 9");
    s.blockSkip[static_cast<size_t>(n)] = asBool(v, w);
    return;
  }
  if (head == "switches") {
    if (rest == "optional_stop")
      s.optionalStop = asBool(v, w);
    else
      bad(w, "unknown key");
    return;
  }
  if (head == "limits") {
    auto positive = [&](double d) {
      if (!(d > 0)) bad(w, "must be positive");
      return d;
    };
    if (rest == "max_blocks")
      s.limits.maxBlocks = static_cast<uint64_t>(positive(static_cast<double>(asInteger(v, w))));
    else if (rest == "max_time_s")
      s.limits.maxTimeSeconds = positive(asNumber(v, w));
    else if (rest == "max_line_length")
      s.limits.maxLineLength =
          static_cast<uint32_t>(positive(static_cast<double>(asInteger(v, w))));
    else if (rest == "max_file_bytes")
      s.limits.maxFileBytes = static_cast<uint64_t>(positive(static_cast<double>(asInteger(v, w))));
    else if (rest == "max_trace_bytes")
      s.limits.maxTraceBytes =
          static_cast<uint64_t>(positive(static_cast<double>(asInteger(v, w))));
    else if (rest == "macro_nesting") {
      int64_t n = asInteger(v, w);
      // Locals #1-#33 exist for levels 0..15 (the main program and 15 macro levels).
      if (n < 1 || n > 15) bad(w, "macro_nesting is 1 to 15");
      s.limits.macroNesting = static_cast<int>(n);
    } else if (rest == "subprogram_nesting")
      s.limits.subprogramNesting = static_cast<int>(positive(static_cast<double>(asInteger(v, w))));
    else if (rest == "total_nesting")
      s.limits.totalNesting = static_cast<int>(positive(static_cast<double>(asInteger(v, w))));
    else
      bad(w, "unknown key");
    return;
  }
  if (head == "clock") {
    if (rest == "date")
      s.date = asInteger(v, w);
    else if (rest == "time")
      s.time = asInteger(v, w);
    else
      bad(w, "unknown key");
    return;
  }
  if (head == "output") {
    if (rest == "dprnt")
      s.dprntPath = asString(v, w);
    else
      bad(w, "unknown key");
    return;
  }
  if (head == "vars") {
    std::string num = !rest.empty() && rest[0] == '#' ? rest.substr(1) : rest;
    int n = 0;
    auto r = std::from_chars(num.data(), num.data() + num.size(), n);
    if (r.ec != std::errc() || r.ptr != num.data() + num.size() || !((n >= 100 && n <= 999)))
      bad(w, "vars take #100-#199, #200-#499 (with options.common_vars_200 = true) and #500-#999");
    s.initialVars[n] = asNumber(v, w);
    return;
  }
  if (head == "options") {
    if (rest == "common_vars_200")
      s.commonVars200 = asBool(v, w);
    else
      bad(w, "options keys: common_vars_200");
    return;
  }
  if (head == "signals") {
    if (rest == "missing") {
      const auto& m = asString(v, w);
      if (m != "warn" && m != "alarm") bad(w, "expected \"warn\" or \"alarm\"");
      s.signals.missingAlarm = m == "alarm";
      return;
    }
    std::string num = !rest.empty() && rest[0] == '#' ? rest.substr(1) : rest;
    int n = 0;
    auto r = std::from_chars(num.data(), num.data() + num.size(), n);
    if (r.ec != std::errc() || r.ptr != num.data() + num.size() || !((n >= 1000 && n <= 1032)))
      bad(w,
          "signals take the inputs #1000-#1031 (one signal each) and #1032 (UI000-UI031 as one "
          "word), and missing");
    std::vector<double> values;
    if (const auto* arr = std::get_if<std::vector<double>>(&v))
      values = *arr;
    else
      values.push_back(asNumber(v, w));
    if (values.empty()) bad(w, "expected a value or a non-empty list of values");
    for (double x : values) {
      if (n < 1032 && x != 0 && x != 1) bad(w, "an input signal is 0 or 1");
      if (n == 1032 && !(x >= 0 && x <= 4294967295.0 && x == std::floor(x)))
        bad(w, "#1032 is a whole number from 0 to 4294967295 (bit k = #[1000+k])");
    }
    s.signals.inputs[n] = std::move(values);
    return;
  }
  if (head == "axes") {
    auto d2 = rest.find('.');
    std::string axis = rest.substr(0, d2);
    std::string field = d2 == std::string::npos ? "" : rest.substr(d2 + 1);
    static const std::string names = "XYZABC";
    if (axis.size() != 1 || names.find(axis[0]) == std::string::npos)
      bad(w, "axes are X Y Z A B C");
    AxisConfig& a = s.axes[names.find(axis[0])];
    a.present = true;
    if (field == "present")
      a.present = asBool(v, w);
    else if (field == "rapid")
      a.rapidRate = asNumber(v, w);
    else if (field == "initial")
      a.initial = asNumber(v, w);
    else if (field == "rotary")
      a.rotary = asBool(v, w);
    else if (field == "diameter")
      a.diameter = asBool(v, w);
    else if (field == "min")
      a.min = asNumber(v, w);
    else if (field == "max")
      a.max = asNumber(v, w);
    else if (field == "reference") {
      const auto* arr = std::get_if<std::vector<double>>(&v);
      if (!arr || arr->empty() || arr->size() > 4)
        bad(w, "expected an array of 1 to 4 numbers (G28, G30 P2..P4)");
      for (size_t k = 0; k < arr->size(); ++k) a.reference[k] = (*arr)[k];
    } else {
      bad(w, "unknown axis key (present, rapid, initial, rotary, diameter, reference, min, max)");
    }
    return;
  }
  if (head == "work_offsets") {
    // work_offsets.G54 = [x, y, z] (axes in X Y Z A B C order of the axes the machine has)
    // or work_offsets.G54.X = value.
    static const std::string names = "XYZABC";
    int idx = workOffsetIndex(rest);
    std::string axis;
    if (idx < 0) {
      auto d = rest.rfind('.');
      if (d != std::string::npos)
        idx = workOffsetIndex(rest.substr(0, d)), axis = rest.substr(d + 1);
    }
    if (idx < 0) bad(w, "work offsets are EXT, G54-G59 or \"G54.1 P1\"-\"G54.1 P300\"");
    auto& row = s.workOffsets[idx];
    if (axis.empty()) {
      const auto* arr = std::get_if<std::vector<double>>(&v);
      if (!arr) bad(w, "expected [x, y, z] or a table {X = .., Y = ..}");
      size_t k = 0;
      for (int slot = 0; slot < kMaxAxes && k < arr->size(); ++slot)
        if (s.axes[static_cast<size_t>(slot)].present) row[static_cast<size_t>(slot)] = (*arr)[k++];
      if (k < arr->size()) bad(w, "more values than the machine has axes");
    } else {
      if (axis.size() != 1 || names.find(axis[0]) == std::string::npos)
        bad(w, "axis letters are X Y Z A B C");
      row[names.find(axis[0])] = asNumber(v, w);
    }
    return;
  }
  if (head == "tool_offsets") {
    auto d = rest.find('.');
    int n = 0;
    std::string num = rest.substr(0, d), field = d == std::string::npos ? "" : rest.substr(d + 1);
    auto r = std::from_chars(num.data(), num.data() + num.size(), n);
    if (r.ec != std::errc() || n < 1 || n >= kToolRows) bad(w, "tool offset numbers are 1-999");
    ToolOffsetSpec& t = s.toolOffsets[n];
    static const std::map<std::string, std::pair<int, bool>> fields = {
        {"h_geometry", {kFieldXorH, false}},
        {"h_wear", {kFieldXorH, true}},
        {"d_geometry", {kFieldRorD, false}},
        {"d_wear", {kFieldRorD, true}},
        {"x", {kFieldXorH, false}},
        {"x_wear", {kFieldXorH, true}},
        {"z", {kFieldZ, false}},
        {"z_wear", {kFieldZ, true}},
        {"r", {kFieldRorD, false}},
        {"r_wear", {kFieldRorD, true}},
        {"y", {kFieldY, false}},
        {"y_wear", {kFieldY, true}}};
    if (field == "t" || field == "tip") {
      int64_t tip = asInteger(v, w);
      if (tip < 0 || tip > 9) bad(w, "imaginary tip direction is 0-9");
      t.tip = static_cast<int>(tip);
    } else if (auto it = fields.find(field); it != fields.end()) {
      (it->second.second ? t.wear : t.geometry)[static_cast<size_t>(it->second.first)] =
          asNumber(v, w);
    } else {
      bad(w,
          "tool offset fields: h_geometry h_wear d_geometry d_wear (mill); x z r t y and x_wear "
          "z_wear r_wear y_wear (lathe)");
    }
    return;
  }
  if (head == "tools") {
    auto d = rest.find('.');
    int n = 0;
    std::string num = rest.substr(0, d), field = d == std::string::npos ? "" : rest.substr(d + 1);
    auto r = std::from_chars(num.data(), num.data() + num.size(), n);
    if (r.ec != std::errc() || n < 0 || n > 99999999) bad(w, "tools are keyed by T number");
    ToolSpec& t = s.tools[n];
    if (field == "type") {
      t.type = asString(v, w);
      static const char* kinds[] = {"flat", "ball", "bull", "face", "drill", "probe", "insert"};
      bool ok = false;
      for (auto* k : kinds) ok |= t.type == k;
      if (!ok) bad(w, "tool types: flat ball bull face drill probe insert");
    } else if (field == "diameter")
      t.diameter = asNumber(v, w);
    else if (field == "corner_radius")
      t.cornerRadius = asNumber(v, w);
    else if (field == "length")
      t.length = asNumber(v, w);
    else if (field == "point_angle")
      t.pointAngle = asNumber(v, w);
    else if (field == "flute_length")
      t.fluteLength = asNumber(v, w);
    else if (field == "nose_radius")
      t.noseRadius = asNumber(v, w);
    else if (field == "tip")
      t.tip = static_cast<int>(asInteger(v, w));
    else if (field == "insert_angle") {
      t.insertAngle = asNumber(v, w);
      if (!(t.insertAngle > 0 && t.insertAngle < 180))
        bad(w, "insert_angle is between 0 and 180 degrees");
    } else if (field == "edge_length") {
      t.edgeLength = asNumber(v, w);
      if (t.edgeLength < 0) bad(w, "must not be negative");
    } else if (field == "holder_diameter")
      t.holderDiameter = asNumber(v, w);
    else if (field == "holder_length")
      t.holderLength = asNumber(v, w);
    else
      bad(w,
          "tool fields: type diameter corner_radius length point_angle flute_length nose_radius "
          "tip insert_angle edge_length holder_diameter holder_length");
    return;
  }
  if (head == "timing") {
    try {
      applyTimingKey(s.timing, rest, v);
    } catch (const std::invalid_argument& e) {
      bad(w, e.what());
    }
    return;
  }
  if (head == "probe") {
    if (rest == "tool")
      s.probe.tool = static_cast<int>(asInteger(v, w));
    else if (rest == "ball_diameter")
      s.probe.ballDiameter = asNumber(v, w);
    else if (rest == "miss_alarm")
      s.probe.missAlarm = asBool(v, w);
    else if (rest == "use_stock")
      s.probe.useStock = asBool(v, w);
    else if (rest == "length_to") {
      const auto& m = asString(v, w);
      if (m != "ball_bottom" && m != "ball_centre")
        bad(w, "expected \"ball_bottom\" or \"ball_centre\"");
      s.probe.lengthToBallBottom = m == "ball_bottom";
    } else
      bad(w, "probe keys: tool ball_diameter miss_alarm use_stock length_to");
    return;
  }
  if (head == "solids") {
    auto d = rest.find('.');
    int n = 0;
    std::string num = rest.substr(0, d), field = d == std::string::npos ? "" : rest.substr(d + 1);
    auto r = std::from_chars(num.data(), num.data() + num.size(), n);
    if (r.ec != std::errc() || n < 0 || n > 10000) bad(w, "solids is a list: [[solids]]");
    if (static_cast<size_t>(n) >= s.solids.size()) s.solids.resize(static_cast<size_t>(n) + 1);
    SolidSpec& so = s.solids[static_cast<size_t>(n)];
    if (!so.line) so.line = line;
    auto vec = [&](size_t minSize) {
      const auto* arr = std::get_if<std::vector<double>>(&v);
      if (!arr || arr->size() < minSize || arr->size() > 3)
        bad(w, "expected an array of 2 or 3 numbers");
      return *arr;
    };
    if (field == "kind") {
      so.kind = asString(v, w);
      if (so.kind == "boss") so.kind = "cylinder";
      if (so.kind != "box" && so.kind != "cylinder" && so.kind != "bore" && so.kind != "plane")
        bad(w, "solid kinds: box cylinder boss bore plane");
    } else if (field == "frame") {
      so.frame = asString(v, w);
      if (so.frame != "machine" && workOffsetIndex(so.frame) < 0)
        bad(w, "frame is machine or a work offset (G54, ...)");
    } else if (field == "center")
      so.center = vec(2);
    else if (field == "min")
      so.min = vec(3);
    else if (field == "max")
      so.max = vec(3);
    else if (field == "point")
      so.point = vec(3);
    else if (field == "normal")
      so.normal = vec(3);
    else if (field == "diameter")
      so.diameter = asNumber(v, w);
    else if (field == "outer_diameter")
      so.outerDiameter = asNumber(v, w);
    else if (field == "top")
      so.top = asNumber(v, w);
    else if (field == "bottom")
      so.bottom = asNumber(v, w);
    else
      bad(w,
          "solid fields: kind frame center diameter outer_diameter top bottom min max point "
          "normal");
    return;
  }
  if (head == "stock") {
    StockSpec& st = s.stock;
    st.present = true;
    if (!st.line) st.line = line;
    auto nonNegative = [&](double d) {
      if (d < 0) bad(w, "must not be negative");
      return d;
    };
    auto box = [&]() {
      const auto* arr = std::get_if<std::vector<double>>(&v);
      if (!arr || arr->size() != 3) bad(w, "expected [x, y, z]");
      return *arr;
    };
    if (rest == "frame") {
      st.frame = asString(v, w);
      if (st.frame != "work" && st.frame != "machine" && st.frame != "program")
        bad(w, "frame is work, machine or program (sim/stock_frame.hpp)");
    } else if (rest == "diameter")
      st.diameter = nonNegative(asNumber(v, w));
    else if (rest == "bore_diameter")
      st.boreDiameter = nonNegative(asNumber(v, w));
    else if (rest == "length")
      st.length = nonNegative(asNumber(v, w));
    else if (rest == "front_z")
      st.frontZ = asNumber(v, w);
    else if (rest == "min")
      st.min = box();
    else if (rest == "max")
      st.max = box();
    else if (rest == "cell")
      st.cell = nonNegative(asNumber(v, w));
    else
      bad(w,
          "stock keys: frame diameter bore_diameter length front_z (lathe); min max cell (mill)");
    return;
  }
  if (head == "target") {
    TargetSpec& tg = s.target;
    tg.present = true;
    if (!tg.line) tg.line = line;
    if (rest == "blocks") {
      // "N60..N100" (or "60..100", or one block "N200")
      std::string text =
          std::holds_alternative<double>(v) ? std::to_string(asInteger(v, w)) : asString(v, w);
      auto number = [&](std::string part) {
        if (!part.empty() && (part[0] == 'N' || part[0] == 'n')) part = part.substr(1);
        int n = -1;
        auto r = std::from_chars(part.data(), part.data() + part.size(), n);
        if (part.empty() || r.ec != std::errc() || r.ptr != part.data() + part.size() || n < 0)
          bad(w, "expected \"N60..N100\" or \"N200\"");
        return n;
      };
      auto dots = text.find("..");
      tg.fromN = number(text.substr(0, dots));
      tg.toN = dots == std::string::npos ? tg.fromN : number(text.substr(dots + 2));
      if (tg.toN < tg.fromN) bad(w, "the first N must not be above the last");
    } else if (rest == "polyline")
      tg.polyline = asString(v, w);
    else if (rest == "shift") {
      const auto* arr = std::get_if<std::vector<double>>(&v);
      if (!arr || arr->size() != 2) bad(w, "expected [U, W] (U as a diameter)");
      tg.shift = {(*arr)[0], (*arr)[1]};
    } else if (rest == "reachable") {
      tg.reachable = asString(v, w);
      if (tg.reachable != "sharp" && tg.reachable != "nose")
        bad(w, "expected \"sharp\" or \"nose\"");
    } else if (rest == "face_z")
      tg.faceZ = asNumber(v, w);
    else if (rest == "height_map")
      tg.heightMap = asString(v, w);
    else if (rest == "tolerance") {
      tg.tolerance = asNumber(v, w);
      if (!(tg.tolerance > 0)) bad(w, "must be positive");
    } else
      bad(w,
          "target keys: blocks polyline shift reachable (lathe); face_z height_map (mill); "
          "tolerance");
    return;
  }
  bad(w, "unknown key");
}

void walk(Setup& s, const toml::table& t, const std::string& prefix) {
  // machine.* first: the kind resets the axes, which later keys may adjust.
  if (prefix.empty()) {
    if (auto* m = t.get("machine"); m && m->is_table()) walk(s, *m->as_table(), "machine");
  }
  for (const auto& [k, node] : t) {
    std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (prefix.empty() && k.str() == "machine") continue;
    // Errors point at the key (where the value is wrong too, the key names it).
    const auto& at = k.source().begin.line ? k.source().begin : node.source().begin;
    int line = static_cast<int>(at.line);
    int col = static_cast<int>(at.column);
    if (auto* sub = node.as_table()) {
      walk(s, *sub, key);
    } else if (auto* tables = node.as_array();
               tables && !tables->empty() && tables->front().is_table()) {
      // [[solids]]: an array of tables, walked as solids.0, solids.1, ...
      for (size_t i = 0; i < tables->size(); ++i) {
        auto* entry = (*tables)[i].as_table();
        if (!entry) throw SetupError(key + ": mixed array", key, line);
        walk(s, *entry, key + "." + std::to_string(i));
      }
    } else if (auto* arr = node.as_array()) {
      std::vector<double> nums;
      for (const auto& e : *arr) {
        if (auto d = e.value<double>())
          nums.push_back(*d);
        else
          throw SetupError(key + ": expected an array of numbers", key, line);
      }
      applyKey(s, key, nums, line, col);
    } else if (auto b = node.value<bool>(); node.is_boolean()) {
      applyKey(s, key, *b, line, col);
    } else if (node.is_number()) {
      applyKey(s, key, *node.value<double>(), line, col);
    } else if (auto str = node.value<std::string>()) {
      applyKey(s, key, *str, line, col);
    } else {
      throw SetupError(key + ": unsupported value type", key, line);
    }
  }
}

// toml++ reads a folder as an empty table: a setup path must be a readable regular file.
void checkSetupFile(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  auto refuse = [&](const std::string& why) {
    SetupError e(fmt::format("{}: {}", path, why), "", 0);
    e.file = path;
    throw e;
  };
  if (st.type() == fs::file_type::not_found) refuse("no such file");
  if (ec && ec == std::errc::permission_denied) refuse("permission denied");
  if (ec) refuse(ec.message());
  if (st.type() == fs::file_type::directory)
    refuse("is a folder, not a setup file (give FILE.toml)");
  if (st.type() != fs::file_type::regular) refuse("not a regular file (a setup is a TOML file)");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) refuse(errno == EACCES ? "permission denied" : std::strerror(errno));
  std::fclose(f);
}

}  // namespace

Series Setup::series() const {
  if (kind == MachineKind::Mill) return Series::M;
  return gcodeSystem == 'B' ? Series::TB : gcodeSystem == 'C' ? Series::TC : Series::TA;
}

double Setup::param(const std::string& key, double fallback) const {
  auto it = parameters.find(key);
  return it == parameters.end() ? fallback : it->second;
}

double Setup::arcTolerance() const {
  // Parameter 3410 is in least increments (IS-B: 0.001 mm); 0 means the control's default.
  double p = param("3410", 0);
  double unit = leastIncrement(increment, InputUnit::Mm);
  return p > 0 ? p * unit : 0.010;
}

int Setup::gCodeCall(int g) const {
  for (int k = 0; k < 10; ++k)
    if (param(std::to_string(6050 + k), 0) == g && g != 0) return 9010 + k;
  return -1;
}
int Setup::mCodeMacroCall(int m) const {
  for (int k = 0; k < 10; ++k)
    if (param(std::to_string(6080 + k), 0) == m && m != 0) return 9020 + k;
  return -1;
}
int Setup::mCodeSubCall(int m) const {
  for (int k = 0; k < 9; ++k)
    if (param(std::to_string(6071 + k), 0) == m && m != 0) return 9001 + k;
  return -1;
}

int Setup::axisSlot(char name) const {
  static const std::string names = "XYZABC";
  auto p = names.find(name);
  if (p == std::string::npos || !axes[p].present) return -1;
  return static_cast<int>(p);
}

Setup defaultSetup(MachineKind kind) {
  Setup s;
  s.kind = kind;
  static const char names[] = "XYZABC";
  for (int k = 0; k < kMaxAxes; ++k) {
    s.axes[static_cast<size_t>(k)].name = names[k];
    s.axes[static_cast<size_t>(k)].rotary = k >= 3;
  }
  if (kind == MachineKind::Mill) {
    for (int k = 0; k < 3; ++k) s.axes[static_cast<size_t>(k)].present = true;
    s.axes[0].rapidRate = s.axes[1].rapidRate = 36000;
    s.axes[2].rapidRate = 30000;
  } else {
    s.axes[0].present = true;
    s.axes[0].diameter = true;
    s.axes[0].rapidRate = 20000;
    s.axes[2].present = true;
    s.axes[2].rapidRate = 24000;
  }
  applyControlDefaults(s);
  return s;
}

Setup parseSetup(std::string_view text, const std::string& name) {
  Setup s = defaultSetup();
  toml::table t;
  try {
    t = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    SetupError located("", "", static_cast<int>(e.source().begin.line));
    located.col = static_cast<int>(e.source().begin.column);
    inFile(located, name, std::string(e.description()));
  }
  try {
    walk(s, t, "");
  } catch (const SetupError& e) {
    inFile(e, name);
  }
  return s;
}

Setup loadSetup(const std::string& path) {
  Setup s = defaultSetup();
  loadSetupInto(s, path);
  return s;
}

void loadSetupInto(Setup& s, const std::string& path) {
  checkSetupFile(path);
  toml::table t;
  try {
    t = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    SetupError located("", "", static_cast<int>(e.source().begin.line));
    located.col = static_cast<int>(e.source().begin.column);
    inFile(located, path, std::string(e.description()));
  }
  try {
    walk(s, t, "");
  } catch (const SetupError& e) {
    inFile(e, path);
  }
  // Files named by the setup are found beside it.
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  for (std::string* f : {&s.target.polyline, &s.target.heightMap})
    if (!f->empty() && std::filesystem::path(*f).is_relative()) *f = (dir / *f).string();
}

void applySetting(Setup& setup, const std::string& assignment) {
  auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) throw SetupError("--set needs KEY=VALUE: " + assignment);
  std::string key = assignment.substr(0, eq);
  std::string text = assignment.substr(eq + 1);
  SettingValue v;
  double d = 0;
  auto r = std::from_chars(text.data(), text.data() + text.size(), d);
  if (text.size() >= 2 && text.front() == '[' && text.back() == ']') {
    std::vector<double> nums;
    std::string inner = text.substr(1, text.size() - 2);
    size_t pos = 0;
    while (pos <= inner.size() && !inner.empty()) {
      size_t comma = inner.find(',', pos);
      std::string item =
          inner.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
      double x = 0;
      size_t b = item.find_first_not_of(' '), e = item.find_last_not_of(' ');
      item = b == std::string::npos ? "" : item.substr(b, e - b + 1);
      auto ir = std::from_chars(item.data(), item.data() + item.size(), x);
      if (ir.ec != std::errc() || ir.ptr != item.data() + item.size())
        throw SetupError("--set " + key + ": bad number in array: " + item, key, 0);
      nums.push_back(x);
      if (comma == std::string::npos) break;
      pos = comma + 1;
    }
    v = nums;
  } else if (text == "true" || text == "false")
    v = text == "true";
  else if (r.ec == std::errc() && r.ptr == text.data() + text.size())
    v = d;
  else
    v = text;
  try {
    applyKey(setup, key, v, 0);
  } catch (const SetupError& e) {
    throw SetupError("--set " + assignment + ": " + e.what(), e.key);
  }
}

std::string setupErrorText(const SetupError& e) {
  if (!e.file.empty() || e.line == 0) return e.what();
  return fmt::format("{} (line {})", e.what(), e.line);
}

const ToolSpec* physicalTool(const Setup& setup, int number) {
  if (auto it = setup.tools.find(number); it != setup.tools.end()) return &it->second;
  for (const auto& [t, spec] : setup.tools)
    if (t >= 100 && t / 100 == number) return &spec;
  return nullptr;
}

// The significant decimal digits of custom macro values: the 16i class keeps about 8
// ("the precision of variable values is about 8 decimal digits"); the 30i class computes in
// double precision unless 6008#0 (F16) asks for the 16i's precision.
int Setup::macroDigits() const {
  const bool class16i =
      control == "16i" || control == "18i" || control == "21i" || control == "0i-C";
  return class16i || bit("6008#0") ? 8 : 0;
}

}  // namespace ncvm
