#pragma once
// The machine and the job, as a value: control model, parameters, switches, axes, limits,
// clock and initial variables. Loaded from a TOML file (docs/setup-format.md), then
// adjusted by --set; every run is reproducible from it.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "canon/events.hpp"
#include "core/units.hpp"
#include "machine/offsets.hpp"
#include "machine/series.hpp"
#include "machine/timing_params.hpp"

namespace ncvm {

enum class MachineKind : uint8_t { Mill, Lathe };

struct AxisConfig {
  char name = 'X';
  bool present = false;
  bool rotary = false;
  bool diameter = false;              // lathe X: programmed and shown as a diameter
  double rapidRate = 24000.0;         // units/min (deg/min for rotary)
  std::array<double, 4> reference{};  // G28 / G30 P2..P4 positions, machine coordinates
  double initial = 0.0;               // machine position at cycle start
  // Stored stroke limit 1 (machine coordinates); a move past it alarms before it starts.
  double min = -1e12, max = 1e12;
};

// The physical tool in pocket T, independent of the offset values (seed 002's point: the
// D offset may not be the cutter's real radius).
struct ToolSpec {
  std::string type = "flat";  // flat, ball, bull, face, drill, probe, insert
  double diameter = 0, cornerRadius = 0, length = 0, pointAngle = 118, fluteLength = 0;
  double noseRadius = 0;  // lathe insert
  int tip = 0;            // lathe insert imaginary tip direction
  // Lathe insert body for the stock simulation: included angle of the two cutting edges
  // (symmetric about the tip direction) and their length from the nose.
  double insertAngle = 80, edgeLength = 0;  // edge length 0 = 10 mm (0.4 in)
  double holderDiameter = 0, holderLength = 0;
};

// Geometry the probe can touch (G31). Cylinders, bosses and bores have their axis along Z.
struct SolidSpec {
  std::string kind;               // box, cylinder (= boss), bore, plane
  std::string frame = "machine";  // machine, or a work offset name (EXT, G54.., G54.1 P1..)
  std::vector<double> center, min, max, point, normal;  // X Y (Z) in the frame
  double diameter = 0, outerDiameter = 0;
  double top = 0, bottom = -1e9;
  int line = 0;  // setup file line, for errors
};

struct ProbeSpec {
  int tool = -1;            // T number of the probe; -1: every tool probes as a sphere
  double ballDiameter = 0;  // stylus ball; 0 = the tool's diameter from [tools]
  bool missAlarm = false;   // G31 that touches nothing: alarm PS9010 instead of ending normally
  bool useStock = false;    // G31 touches the simulated stock ([stock]) instead of [[solids]]
  // Mill: where the tool length offset ends on the ball. A probe (and a ball mill) is set on a
  // tool setter or a reference surface, so the length ends at the bottom of the ball and the
  // ball's centre is a radius above the tip; false keeps the centre on the tip.
  bool lengthToBallBottom = true;
};

// The raw material of the stock simulation (src/sim), in program units, in the coordinates
// the moves are reported in (work coordinates; lathe X as a diameter).
struct StockSpec {
  bool present = false;
  std::string frame = "work";  // work, machine or program (sim/stock_frame.hpp)
  // Lathe: a bar (bore 0) or a tube along Z from frontZ back to frontZ - length.
  double diameter = 0, boreDiameter = 0, length = 0, frontZ = 0;
  // Mill: a box between min and max [x, y, z], simulated in cells of `cell`.
  std::vector<double> min, max;
  double cell = 0;  // 0 = the model's default
  int line = 0;
};

// What the stock should become, for the deviation analysis.
struct TargetSpec {
  bool present = false;
  // Lathe: the feed moves of blocks N fromN..toN of the main program (first pass), or a
  // polyline file of X (diameter) Z points; shift [U (diameter), W] moves it (allowances).
  int fromN = -1, toN = -1;
  std::string polyline;
  std::array<double, 2> shift{};
  // Lathe: "sharp" compares with the contour itself; "nose" with the part the insert can
  // make, the contour's concave corners rounded by the tool's nose radius.
  std::string reachable = "sharp";
  // Mill: a flat floor at faceZ, or a height-map file.
  std::optional<double> faceZ;
  std::string heightMap;
  double tolerance = 0;  // deviation band width; 0 = 0.01 mm (0.0004 in)
  int line = 0;
};

// Offsets as the operator enters them: mm (or inch), lathe X as a diameter.
struct ToolOffsetSpec {
  std::array<double, 4> geometry{};
  std::array<double, 4> wear{};
  int tip = 0;
};

struct Limits {
  uint64_t maxBlocks = 100'000'000;   // runaway guard: blocks executed
  double maxTimeSeconds = 360'000.0;  // runaway guard: simulated machine time (100 h)
  uint32_t maxLineLength = 4096;
  uint64_t maxFileBytes = 512ull << 20;
  uint64_t maxTraceBytes = 1ull << 30;  // 1 GiB: a runaway trace stops before it fills a disk
  int macroNesting = 5;                 // G65/G66/code-call levels (locals #1-#33 levels 1..n)
  int subprogramNesting = 10;           // M98 levels
  int totalNesting = 15;                // both together
};

// The machine's interface signals as the macro reads them (#1000-#1031 one input each, #1032
// the 32 inputs UI000-UI031 as one word): per variable, the values successive reads return
// (the last one repeats).
struct SignalSpec {
  std::map<int, std::vector<double>> inputs;
  bool missingAlarm = false;  // an input the setup does not give: alarm, not 0 and a warning
};

struct SetupError : std::runtime_error {
  SetupError(const std::string& what, std::string badKey = {}, int atLine = 0)
      : std::runtime_error(what), key(std::move(badKey)), line(atLine) {}
  std::string key;
  int line;
  int col = 0;
  std::string file;  // set once the message names FILE:LINE:COL
};

// The error as ncvm prints it: FILE:LINE:COL: KEY: WHY (the file known), else "WHY (line N)".
std::string setupErrorText(const SetupError& e);

struct Setup {
  MachineKind kind = MachineKind::Mill;
  std::string control = "0i-F";  // 0i-F, 30i, 16i: sets nesting limits and defaults
  char gcodeSystem = 'A';        // lathes: A, B or C
  int programNumberDigits = 4;   // 8 with the 8-digit program number option
  IncrementSystem increment = IncrementSystem::IsB;
  InputUnit initialUnit = InputUnit::Mm;  // G21 at power-on (machine in mm)
  std::array<AxisConfig, kMaxAxes> axes{};

  // Fanuc parameters as written: "3401#0" -> 1, "3410" -> 10. Typed views below.
  std::map<std::string, double> parameters;

  std::array<bool, 10> blockSkip{};  // [1]..[9]: '/' and '/2'..'/9' switches
  bool optionalStop = true;          // M01 stops (recorded as a message, the run goes on)
  Limits limits;
  int64_t date = 20260101;  // #3011 YYYYMMDD
  int64_t time = 80000;     // #3012 HHMMSS
  std::string dprntPath;    // DPRNT/BPRNT output; empty = <state or program>.out beside it
  std::map<int, double> initialVars;  // #100-#199, (#200-#499), #500-#999 at cycle start
  // The option that adds common variables #200-#499 (0i-F, 30i): off, those numbers alarm
  // PS0115.
  bool commonVars200 = false;
  SignalSpec signals;
  // Work offsets by table index (machine/offsets.hpp); unset axes stay 0.
  std::map<int, std::array<double, kMaxAxes>> workOffsets;
  std::map<int, ToolOffsetSpec> toolOffsets;
  std::map<int, ToolSpec> tools;
  ProbeSpec probe;
  std::vector<SolidSpec> solids;
  StockSpec stock;
  TargetSpec target;
  TimingSetup timing;  // [timing]: the cycle-time model

  Series series() const;
  double param(const std::string& key, double fallback) const;
  bool bit(const std::string& key) const { return param(key, 0) != 0; }
  // Common parameter views.
  bool dpi() const { return bit("3401#0"); }  // calculator-type decimal input
  bool nat() const { return bit("6004#0"); }  // ASIN/ATAN range -90..90 / -180..180
  bool lrp() const { return bit("1401#1"); }  // linear (not dog-leg) rapids
  bool prt() const { return bit("6001#1"); }  // DPRNT: no leading blanks
  bool tcs() const { return bit("6001#5"); }  // T code calls O9000
  int macroDigits() const;      // significant digits of macro values, 0 = double precision
  double arcTolerance() const;  // parameter 3410, in mm
  // Program number called by G code g through 6050-6059 (O9010-O9019), or -1.
  int gCodeCall(int g) const;
  int mCodeMacroCall(int m) const;  // 6080-6089 -> O9020-O9029
  int mCodeSubCall(int m) const;    // 6071-6079 -> O9001-O9009

  int axisSlot(char name) const;  // -1 if the machine has no such axis
  // Positions are reported as [X, Y, Z] plus A, B, C up to the last rotary axis present.
  int reportedAxes() const {
    int n = 3;
    for (int k = 3; k < kMaxAxes; ++k)
      if (axes[static_cast<size_t>(k)].present) n = k + 1;
    return n;
  }
};

// Defaults for a machine kind: axes, rapid rates, control limits.
Setup defaultSetup(MachineKind kind = MachineKind::Mill);
// Loads a setup file. Throws SetupError with the key and line.
Setup loadSetup(const std::string& path);
// Applies a setup file on top of `setup` (several --setup files: a preset, then the job).
void loadSetupInto(Setup& setup, const std::string& path);
// The same from the text of a setup file; `name` stands for the file in error messages.
Setup parseSetup(std::string_view text, const std::string& name);
// Applies "KEY=VALUE": a Fanuc parameter ("3401#0=1", "DPI=1") or a setup key
// ("machine.kind=lathe", "block_skip.1=true", "limits.max_blocks=50", "vars.#500=2").
void applySetting(Setup& setup, const std::string& assignment);

// The physical tool [tools.N] of tool `number`: that entry, else (a lathe's turret number,
// T0101 -> 1) the entry of the whole T word (101, 102, ...: the first such). nullptr: none.
const ToolSpec* physicalTool(const Setup& setup, int number);

}  // namespace ncvm
