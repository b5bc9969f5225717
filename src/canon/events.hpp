#pragma once
// Canonical machine events: what the control makes the machine do, as plain values. The
// control emits them to an EventSink; the trace writer, statistics, and later the cycle-time
// model, stock simulator and viewer are sinks. None of them ever sees G-code.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ncvm {

constexpr int kMaxAxes = 6;  // X Y Z A B C slots; a lathe uses X and Z (and C, Y)
using AxisArray = std::array<double, kMaxAxes>;

// Where an event came from. `programName` points into the program store (stable).
struct EventOrigin {
  uint32_t file = 0;
  uint32_t line = 0;
  int32_t n = -1;  // N number of the block, -1 if none
  const std::string* programName = nullptr;
};

enum class MoveMode : uint8_t { Rapid, Linear, Cw, Ccw };

struct MoveEvent {
  EventOrigin at;
  MoveMode mode = MoveMode::Linear;
  AxisArray start{}, end{};    // work coordinates, program units (lathe X as diameter)
  AxisArray mstart{}, mend{};  // machine coordinates, program units
  double feed = 0;             // units/min after any per-revolution conversion
  double length = 0;           // path length in program units (helix and dog-leg included)
  double time = 0;             // seconds (simple model: length / feed; rapid per-axis rates)
  // The cycle-time model (src/timing) puts its modelled time in `time` and keeps the simple
  // one here; -1 while no timing stage has seen the event (then `time` is the simple one).
  double timeSimple = -1;
  // What the time model needs from the block: G09/G61 exact stop, inch units, and feed per
  // revolution (units/rev) with G96's surface speed (m/min or ft/min) and G50/G92 S clamp.
  bool exactStop = false;
  bool inch = false;
  double perRev = 0, surfaceSpeed = 0, rpmLimit = 0;
  // Arcs: centre (work coordinates) and plane (17, 18, 19).
  bool arc = false;
  std::array<double, 3> center{};
  int plane = 17;
  // Rapids with per-axis (dog-leg) interpolation: the corner points in between, work
  // coordinates, in the order the tool passes them.
  int pathPoints = 0;
  std::array<AxisArray, kMaxAxes> path{};
  bool thread = false;  // G32/G33 and threading cycles: synchronised with the spindle
  bool skip = false;    // the G31 measuring move (it may touch; any other probe move must not)
  // Cutter compensation: end is the tool centre; programmedEnd is the programmed point.
  bool compensated = false;
  AxisArray programmedEnd{};
  // Lathe tool-nose radius compensation: end is the imaginary tip, noseEnd the nose centre.
  bool nose = false;
  AxisArray noseEnd{};
};

struct DwellEvent {
  EventOrigin at;
  double time = 0;         // seconds
  double revolutions = 0;  // when programmed in spindle revolutions, else 0
};

struct MessageEvent {
  EventOrigin at;
  std::string_view text;
  std::string_view source;  // "#3006", "M00", "M01"
};

// A block with nothing but a comment (and perhaps N) on its line, as CAM systems name their
// operations: `(ROUGH FACE)`. Only the main program's, outside WHILE loops (not one in a
// subprogram, a macro or a loop body); the program's title after O is not one.
struct CommentEvent {
  EventOrigin at;
  std::string_view text;
};

struct AlarmEvent {
  EventOrigin at;
  std::string_view code;
  std::string_view text;
};

struct ToolEvent {
  EventOrigin at;
  int tool = 0;         // T number selected
  bool change = false;  // M06 (tool change) rather than T selection
};

enum class SpindleDir : uint8_t { Stop, Cw, Ccw, Orient };
struct SpindleEvent {
  EventOrigin at;
  SpindleDir dir = SpindleDir::Stop;
  double rpm = 0;
  bool follows = false;  // G96: the rpm following X after a move, not an S or M command
};

enum class CoolantState : uint8_t { Off, Flood, Mist };
struct CoolantEvent {
  EventOrigin at;
  CoolantState state = CoolantState::Off;
};

// An M (or B) code the control passes to the machine without further meaning to ncvm.
struct AuxEvent {
  EventOrigin at;
  char letter = 'M';
  int code = 0;
};

// Any write of a work or tool offset (G10, system variables, G92/G52 shifts).
struct OffsetEvent {
  EventOrigin at;
  std::string_view kind;  // "work", "tool_length", ...
  std::string_view name;  // "G54", "H12 wear", ...
  int axis = -1;          // axis slot, -1 when not per axis
  double value = 0;
};

// Where work zero is on the machine: the work offset in use, EXT, G52 and G92/G50 shifts,
// without the tool offset (Executor::workOriginMm), mm, X Y Z with lathe X as a radius. Sent
// as the control starts and whenever it changes, so a stock fixed on the machine
// (sim/stock_frame.hpp) can place the moves, which come in work coordinates.
struct WorkOriginEvent {
  EventOrigin at;
  std::array<double, 3> mm{};
};

// G31: where the skip signal came (or that it never did).
struct SkipEvent {
  EventOrigin at;
  bool hit = false;
  AxisArray position{};   // latched position, work coordinates (#5061-)
  AxisArray mposition{};  // machine coordinates
};

// A write of an interface signal output (#1100-#1131 one bit, #1132/#1133 32 bits): what
// the program sends the machine's PMC (a pallet changer, a bar feeder, a door).
struct SignalEvent {
  EventOrigin at;
  int variable = 1100;
  double value = 0;  // as stored: 0 or 1 for a bit, the 32-bit word for #1132/#1133
};

class EventSink {
 public:
  virtual ~EventSink() = default;
  virtual void onMove(const MoveEvent&) {}
  virtual void onDwell(const DwellEvent&) {}
  virtual void onMessage(const MessageEvent&) {}
  virtual void onAlarm(const AlarmEvent&) {}
  virtual void onTool(const ToolEvent&) {}
  virtual void onSpindle(const SpindleEvent&) {}
  virtual void onCoolant(const CoolantEvent&) {}
  virtual void onAux(const AuxEvent&) {}
  virtual void onOffset(const OffsetEvent&) {}
  virtual void onSkip(const SkipEvent&) {}
  virtual void onComment(const CommentEvent&) {}
  virtual void onWorkOrigin(const WorkOriginEvent&) {}
  virtual void onSignal(const SignalEvent&) {}
};

// Forwards every event to several sinks in order.
class FanoutSink final : public EventSink {
 public:
  void add(EventSink* s) { sinks_.push_back(s); }
  void onMove(const MoveEvent& e) override {
    for (auto* s : sinks_) s->onMove(e);
  }
  void onDwell(const DwellEvent& e) override {
    for (auto* s : sinks_) s->onDwell(e);
  }
  void onMessage(const MessageEvent& e) override {
    for (auto* s : sinks_) s->onMessage(e);
  }
  void onAlarm(const AlarmEvent& e) override {
    for (auto* s : sinks_) s->onAlarm(e);
  }
  void onTool(const ToolEvent& e) override {
    for (auto* s : sinks_) s->onTool(e);
  }
  void onSpindle(const SpindleEvent& e) override {
    for (auto* s : sinks_) s->onSpindle(e);
  }
  void onCoolant(const CoolantEvent& e) override {
    for (auto* s : sinks_) s->onCoolant(e);
  }
  void onAux(const AuxEvent& e) override {
    for (auto* s : sinks_) s->onAux(e);
  }
  void onOffset(const OffsetEvent& e) override {
    for (auto* s : sinks_) s->onOffset(e);
  }
  void onSkip(const SkipEvent& e) override {
    for (auto* s : sinks_) s->onSkip(e);
  }
  void onComment(const CommentEvent& e) override {
    for (auto* s : sinks_) s->onComment(e);
  }
  void onSignal(const SignalEvent& e) override {
    for (auto* s : sinks_) s->onSignal(e);
  }
  void onWorkOrigin(const WorkOriginEvent& e) override {
    for (auto* s : sinks_) s->onWorkOrigin(e);
  }

 private:
  std::vector<EventSink*> sinks_;
};

}  // namespace ncvm
