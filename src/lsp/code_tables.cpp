#include "lsp/code_tables.hpp"

#include <fmt/format.h>

#include "exec/gcode_table.hpp"

namespace ncvm::lsp {

const std::vector<MCodeInfo>& mCodeTable() {
  static const std::vector<MCodeInfo> table = {
      {0, "program stop (cycle start resumes)"},
      {1, "optional stop (only with the optional-stop switch on)"},
      {2, "end of program"},
      {3, "spindle on, clockwise"},
      {4, "spindle on, counter-clockwise"},
      {5, "spindle stop"},
      {6, "tool change (the T word selects the tool)"},
      {7, "mist coolant on"},
      {8, "coolant on"},
      {9, "coolant off"},
      {19, "spindle orientation"},
      {29, "rigid tapping: the next G84/G74 follows the spindle"},
      {30, "end of program and rewind (counts a part, #3901)"},
      {98,
       "subprogram call: P program number, L or leading digits of P repeats, Q sequence number"},
      {99, "end of subprogram: return to the caller (P: to sequence number P)"},
  };
  return table;
}

std::string addressMeaning(char letter, MachineKind kind) {
  const bool lathe = kind == MachineKind::Lathe;
  switch (letter) {
    case 'A':
      return "rotary axis about X (A), or an angle (lathe direct drawing ,A)";
    case 'B':
      return "rotary axis about Y";
    case 'C':
      return lathe ? "C axis (spindle as an axis), or chamfer (,C)" : "rotary axis about Z";
    case 'D':
      return lathe ? "depth of cut (G71-G76), or offset number"
                   : "cutter radius offset number (G41/G42)";
    case 'E':
      return "thread lead, precise (lathe), or feed";
    case 'F':
      return "feedrate (per minute, G94/G98; per revolution, G95/G99), or thread lead";
    case 'G':
      return "preparatory function (G code)";
    case 'H':
      return lathe ? "incremental C (G-code system A)" : "tool length offset number (G43/G44)";
    case 'I':
      return "arc centre, X component (from the start point); cycle parameter";
    case 'J':
      return "arc centre, Y component; cycle parameter";
    case 'K':
      return "arc centre, Z component; repeat count of a canned cycle";
    case 'L':
      return "repeat count (M98, canned cycles), or G10's data type";
    case 'M':
      return "miscellaneous function (M code)";
    case 'N':
      return "sequence number (a label for GOTO, M99 P and the cycles' P/Q)";
    case 'O':
      return "program number";
    case 'P':
      return "program number to call (M98, G65, G66), dwell time (G04), sequence number, or "
             "parameter";
    case 'Q':
      return lathe ? "end sequence number of a cycle's contour (G70-G73), or depth"
                   : "peck depth (G73/G83), shift (G76/G87), or M98's sequence number";
    case 'R':
      return "arc radius, R point of a canned cycle, or an argument";
    case 'S':
      return "spindle speed (rev/min, or m/min with G96)";
    case 'T':
      return "tool function (tool number; a lathe's T: tool and offset)";
    case 'U':
      return lathe ? "incremental X (G-code system A)" : "additional axis U, or an argument";
    case 'V':
      return lathe ? "incremental Y" : "additional axis V";
    case 'W':
      return lathe ? "incremental Z (G-code system A)" : "additional axis W";
    case 'X':
      return lathe ? "X axis (a diameter), or dwell time (G04)" : "X axis, or dwell time (G04)";
    case 'Y':
      return "Y axis";
    case 'Z':
      return "Z axis";
    default:
      return {};
  }
}

std::string keywordMeaning(const std::string& word) {
  struct Entry {
    const char* word;
    const char* meaning;
  };
  static const Entry table[] = {
      {"GOTO", "GOTO n: jump to sequence number n (searched forward, then from the start)"},
      {"IF", "IF [condition] GOTO n, or IF [condition] THEN assignment"},
      {"THEN", "IF [condition] THEN #i = expression: the assignment runs when the condition holds"},
      {"WHILE", "WHILE [condition] DO m: repeat to END m while the condition holds"},
      {"DO", "DO m: start of a loop (m = 1, 2, 3) ended by END m"},
      {"END", "END m: end of the loop DO m"},
      {"EQ", "equal"},
      {"NE", "not equal"},
      {"GT", "greater than"},
      {"GE", "greater than or equal"},
      {"LT", "less than"},
      {"LE", "less than or equal"},
      {"AND", "bitwise and (logical and of conditions on 30i)"},
      {"OR", "bitwise or"},
      {"XOR", "bitwise exclusive or"},
      {"MOD", "remainder"},
      {"SIN", "sine (degrees)"},
      {"COS", "cosine (degrees)"},
      {"TAN", "tangent (degrees)"},
      {"ASIN", "arc sine (degrees; range set by parameter 6004#0)"},
      {"ACOS", "arc cosine (degrees)"},
      {"ATAN", "arc tangent: ATAN[a]/[b] or ATAN[a,b] (degrees)"},
      {"ATN", "arc tangent (as ATAN)"},
      {"SQRT", "square root"},
      {"SQR", "square root"},
      {"ABS", "absolute value"},
      {"BIN", "BCD to binary"},
      {"BCD", "binary to BCD"},
      {"ROUND", "round to the nearest whole number (in an address: to the least increment)"},
      {"RND", "round (as ROUND)"},
      {"FIX", "round down (towards zero)"},
      {"FUP", "round up (away from zero)"},
      {"LN", "natural logarithm"},
      {"EXP", "e to the power"},
      {"POW", "POW[a,b]: a to the power b"},
      {"ADP", "ADP[#i]: add a decimal point to a value given without one"},
      {"DPRNT", "print text and variables (decimal) to the output (ncvm run --output)"},
      {"BPRNT", "print text and variables (binary) to the output"},
      {"POPEN", "open the output device for DPRNT/BPRNT"},
      {"PCLOS", "close the output device"},
  };
  for (const auto& e : table)
    if (word == e.word) return e.meaning;
  return {};
}

namespace {
std::string gLabel(int code10) {
  std::string s = fmt::format("G{:02d}", code10 / 10);
  if (code10 % 10) s += fmt::format(".{}", code10 % 10);
  return s;
}
}  // namespace

std::optional<std::string> describeGCode(int code10, const Setup& setup) {
  static const char* status[] = {"supported", "accepted (no effect on the path)",
                                 "not executed by ncvm yet (alarm PS0010)"};
  const GCodeInfo* g = findGCode(setup.series(), code10);
  const int call = code10 % 10 == 0 ? setup.gCodeCall(code10 / 10) : -1;
  if (!g && call < 0) return std::nullopt;
  std::string out = gLabel(code10) + ": ";
  if (g)
    out +=
        fmt::format("{} · {} · {}", g->meaning,
                    g->group == 0 ? std::string("one-shot") : fmt::format("group {:02d}", g->group),
                    status[static_cast<int>(g->status)]);
  if (call >= 0)
    out +=
        fmt::format("{}calls macro O{} (parameter {})", g ? " · " : "", call, 6050 + (call - 9010));
  return out;
}

std::string describeMCode(int code, const Setup& setup) {
  std::string out = fmt::format("M{:02d}: ", code);
  const char* meaning = nullptr;
  for (const auto& m : mCodeTable())
    if (m.code == code) meaning = m.meaning;
  if (const int sub = setup.mCodeSubCall(code); sub >= 0)
    return out + fmt::format("calls subprogram O{} (parameter {})", sub, 6071 + (sub - 9001));
  if (const int mac = setup.mCodeMacroCall(code); mac >= 0)
    return out + fmt::format("calls macro O{} (parameter {})", mac, 6080 + (mac - 9020));
  return out + (meaning ? meaning : "machine builder's M code");
}

const std::vector<VariableRange>& variableTable() {
  using I = VariableRange::Index;
  static const std::vector<VariableRange> table = [] {
    std::vector<VariableRange> t = {
        {0, 0, I::None, true, true, false, "null: always vacant"},
        {1, 33, I::Local, true, true, true, "local variable"},
        {100, 199, I::None, true, true, true, "common variable (cleared at power-off)"},
        {200, 499, I::None, true, true, true,
         "common variable of the option (options.common_vars_200), cleared at power-off"},
        {500, 999, I::None, true, true, true,
         "retained common variable (kept at power-off: ncvm run --machine-state)"},
        {1000, 1031, I::None, true, true, false, "interface signal input UI000-UI031, one bit"},
        {1032, 1032, I::None, true, true, false, "interface signal inputs UI000-UI031 as a word"},
        {1100, 1131, I::None, true, true, true, "interface signal output UO000-UO031, one bit"},
        {1132, 1132, I::None, true, true, true, "interface signal outputs UO000-UO031 as a word"},
        {1133, 1133, I::None, true, true, true, "interface signal outputs UO100-UO131 as a word"},
        // Machining centre, tool offset memory C (200 sets here, 999 in the #10000 banks).
        {2001, 2200, I::Row, true, false, true, "tool length (H) wear"},
        {2201, 2400, I::Row, true, false, true, "tool length (H) geometry"},
        {2401, 2600, I::Row, true, false, true, "cutter radius (D) wear"},
        {2601, 2800, I::Row, true, false, true, "cutter radius (D) geometry"},
        {10001, 10999, I::Row, true, false, true, "tool length (H) wear"},
        {11001, 11999, I::Row, true, false, true, "tool length (H) geometry"},
        {12001, 12999, I::Row, true, false, true, "cutter radius (D) wear"},
        {13001, 13999, I::Row, true, false, true, "cutter radius (D) geometry"},
        // Lathe, 64 sets.
        {2001, 2064, I::Row, false, true, true, "X wear offset"},
        {2101, 2164, I::Row, false, true, true, "Z wear offset"},
        {2201, 2264, I::Row, false, true, true, "tool nose radius wear"},
        {2301, 2364, I::Row, false, true, true, "imaginary tool tip direction"},
        {2401, 2464, I::Row, false, true, true, "Y wear offset"},
        {2701, 2764, I::Row, false, true, true, "X geometry offset"},
        {2801, 2864, I::Row, false, true, true, "Z geometry offset"},
        {2901, 2964, I::Row, false, true, true, "tool nose radius geometry"},
        {3000, 3000, I::None, true, true, true,
         "macro alarm: writing n stops with alarm MC(3000+n)"},
        {3001, 3001, I::None, true, true, true, "millisecond timer (simulated time)"},
        {3002, 3002, I::None, true, true, true, "hour timer (simulated time)"},
        {3003, 3003, I::None, true, true, true,
         "single block suppression and auxiliary-function wait control"},
        {3004, 3004, I::None, true, true, true,
         "feed hold, feedrate override and exact stop control"},
        {3005, 3005, I::None, true, true, true, "setting data (bits)"},
        {3006, 3006, I::None, true, true, true, "stop with a message (the comment after it)"},
        {3007, 3007, I::None, true, true, false, "mirror image status (a bit per axis)"},
        {3011, 3011, I::None, true, true, false, "date, YYYYMMDD (setup clock.date)"},
        {3012, 3012, I::None, true, true, false,
         "time, HHMMSS (setup clock.time plus simulated time)"},
        {3100, 3100, I::None, true, true, false, "system constant pi"},
        {3101, 3101, I::None, true, true, false, "system constant e"},
        {3901, 3901, I::None, true, true, true, "parts machined (counted at M30)"},
        {3902, 3902, I::None, true, true, true, "parts required"},
        {4000, 4000, I::None, true, true, false, "main program number"},
        {4001, 4030, I::None, true, true, false,
         "modal G code of group (n - 4000), as of the block read last"},
        {4102, 4102, I::None, true, true, false, "B code, as of the block read last"},
        {4107, 4107, I::None, true, true, false,
         "D code (offset number), as of the block read last"},
        {4108, 4108, I::None, true, true, false, "E code, as of the block read last"},
        {4109, 4109, I::None, true, true, false, "F code (feedrate), as of the block read last"},
        {4111, 4111, I::None, true, true, false,
         "H code (offset number), as of the block read last"},
        {4113, 4113, I::None, true, true, false, "last M code, as of the block read last"},
        {4114, 4114, I::None, true, true, false, "sequence number (N), as of the block read last"},
        {4115, 4115, I::None, true, true, false, "program number, as of the block read last"},
        {4119, 4119, I::None, true, true, false,
         "S code (spindle speed), as of the block read last"},
        {4120, 4120, I::None, true, true, false, "T code, as of the block read last"},
        {4130, 4130, I::None, true, true, false,
         "additional work offset number (G54.1 P), as of the block read last"},
        {4201, 4230, I::None, true, true, false,
         "modal G code of group (n - 4200), of the block running"},
        {4302, 4330, I::None, true, true, false,
         "B, D, E, F, H, M, N, O, S, T or P code (as #4102-#4130), of the block running"},
        {5001, 5020, I::Axis, true, true, false, "block end position (work coordinates)"},
        {5021, 5040, I::Axis, true, true, false, "current position (machine coordinates)"},
        {5041, 5060, I::Axis, true, true, false, "current position (work coordinates)"},
        {5061, 5080, I::Axis, true, true, false,
         "skip position: where G31 stopped (work coordinates)"},
        {5081, 5100, I::Axis, true, true, false,
         "tool offset in effect (tool length or lathe tool offset)"},
        {5101, 5120, I::Axis, true, true, false, "servo deviation (0: a simulation has none)"},
        {5121, 5140, I::Axis, true, true, false, "manual handle interruption (0 in ncvm)"},
        {5201, 5220, I::Axis, true, true, true, "external work offset (EXT)"},
    };
    static const char* works[] = {"G54 work offset", "G55 work offset", "G56 work offset",
                                  "G57 work offset", "G58 work offset", "G59 work offset"};
    for (int k = 0; k < 6; ++k)
      t.push_back({5221 + 20 * k, 5240 + 20 * k, I::Axis, true, true, true, works[k]});
    t.push_back({7001, 7960, I::WorkTable, true, false, true, "additional work offset G54.1"});
    t.push_back({14001, 19980, I::WorkTable, true, false, true, "additional work offset G54.1"});
    return t;
  }();
  return table;
}

namespace {
// The G65 argument letters of specification I, by local variable number (0: none).
char argumentLetter(int64_t n) {
  static const char byVar[34] = {0,   'A', 'B', 'C', 'I', 'J', 'K', 'D', 'E', 'F', 0,   'H',
                                 0,   'M', 0,   0,   0,   'Q', 'R', 'S', 'T', 'U', 'V', 'W',
                                 'X', 'Y', 'Z', 0,   0,   0,   0,   0,   0,   0};
  return n >= 1 && n <= 33 ? byVar[n] : 0;
}

std::string axisName(int axis, const Setup& setup) {
  int seen = 0;
  for (const auto& a : setup.axes)
    if (a.present && ++seen == axis) return std::string(1, a.name);
  return {};
}
}  // namespace

std::optional<std::string> describeVariable(int64_t n, const Setup& setup) {
  const bool lathe = setup.kind == MachineKind::Lathe;
  for (const auto& r : variableTable()) {
    if (n < r.from || n > r.to || (lathe ? !r.lathe : !r.mill)) continue;
    std::string what = r.holds;
    using I = VariableRange::Index;
    switch (r.index) {
      case I::None:
        break;
      case I::Local:
        if (const char c = argumentLetter(n))
          what += fmt::format(" (G65 argument {}, or the caller's level 0 local)", c);
        else
          what += " (G65 argument of specification II only)";
        break;
      case I::Axis: {
        const int axis = static_cast<int>(n - r.from + 1);
        const std::string name = axisName(axis, setup);
        what += name.empty() ? fmt::format(" of axis {} (this machine has no such axis)", axis)
                             : fmt::format(" of axis {} ({})", axis, name);
        break;
      }
      case I::Row:
        what += fmt::format(" of offset {}", n - r.from + 1);
        break;
      case I::WorkTable: {
        const int64_t p = (n - r.from) / 20 + 1, axis = (n - r.from) % 20 + 1;
        const std::string name = axisName(static_cast<int>(axis), setup);
        what += fmt::format(" P{} of axis {}{}", p, axis, name.empty() ? "" : " (" + name + ")");
        break;
      }
    }
    return fmt::format("#{}: {}{}", n, what, r.writable ? "" : " · read-only");
  }
  return std::nullopt;
}

}  // namespace ncvm::lsp
