#pragma once
// What the control makes the machine do while a program runs, one call per event, in order,
// on the thread that called Job::run. The string views and the file name are valid only
// during the call. Positions are work coordinates in program units (a lathe's X as a
// diameter), axes X Y Z A B C; times in seconds (the cycle-time model's when it is on).
#include <array>
#include <cstdint>
#include <string_view>

#include "ncvm/export.hpp"

namespace ncvm::api {

using Axes = std::array<double, 6>;  // X Y Z A B C

// The block an event comes from.
struct Origin {
  std::string_view file;
  uint32_t line = 0;
  int32_t n = -1;  // its N number, -1 when it has none
};

enum class MoveKind { Rapid, Linear, ArcCw, ArcCcw };

struct Move {
  Origin at;
  MoveKind kind = MoveKind::Linear;
  Axes start{}, end{};
  double feed = 0;    // units/min (feed per revolution converted), 0 for rapids
  double length = 0;  // path length in program units (arcs and helices along the path)
  double time = 0;    // seconds
  // Arcs: the centre (X Y Z, work coordinates) and the plane (17, 18 or 19).
  std::array<double, 3> center{};
  int plane = 17;
  bool probing = false;  // the G31 measuring move
};

struct Dwell {
  Origin at;
  double seconds = 0;
};

struct ToolSelect {
  Origin at;
  int tool = 0;
  bool change = false;  // M06 (a change) rather than a T selection
};

struct Message {
  Origin at;
  std::string_view text;
  std::string_view source;  // "#3006", "M00", "M01"
};

// A block that is only a comment in the main program, as CAM systems name operations.
struct Comment {
  Origin at;
  std::string_view text;
};

struct AlarmEvent {
  Origin at;
  std::string_view code;
  std::string_view message;
};

// Receives the events of Job::run: override what you need; the others do nothing.
class NCVM_API EventHandler {
 public:
  virtual ~EventHandler();
  virtual void onMove(const Move&) {}
  virtual void onDwell(const Dwell&) {}
  virtual void onTool(const ToolSelect&) {}
  virtual void onMessage(const Message&) {}
  virtual void onComment(const Comment&) {}
  virtual void onAlarm(const AlarmEvent&) {}
};

}  // namespace ncvm::api
