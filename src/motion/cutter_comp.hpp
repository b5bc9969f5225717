#pragma once
// Cutter radius compensation C (fanuc-reference E.1) as a stream transformer on plane
// geometry: programmed segments go in, tool-centre segments come out once the control
// has read far enough ahead to place each corner. The executor feeds it the plane
// components of every block while G41/G42 is active (including non-moving blocks, which
// limit what the control can see) and emits what comes out. Nothing here knows about
// programs or the trace.
//
// Coordinates are (u, v) in the selected plane (G17: X Y, G18: Z X, G19: Y Z), in program
// units. A positive radius with G41 keeps the tool on the left of the direction of travel.
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/alarm.hpp"

namespace ncvm::crc {

struct P2 {
  double u = 0, v = 0;
};

enum class Kind { Line, Cw, Ccw };
enum class Side { Off, Left, Right };  // G40, G41, G42

struct InSeg {
  Kind kind = Kind::Line;
  P2 start, end;
  P2 center;               // arcs
  bool rapid = false;      // G00 (start-up and cancel blocks may be G00 or G01)
  Side side = Side::Off;   // G40/G41/G42 in effect for this block
  double radius = 0;       // D value in effect (program units; negative swaps sides)
  int tag = -1;            // caller's id for the block (returned on the output)
  bool cornerArc = false;  // G39 in this block (a corner arc at its start)
  // G39 I J (K): the corner arc ends perpendicular to this direction instead of to the
  // block's start (16/18-C manual: the new vector is at right angles to (I, J)).
  bool cornerHasDir = false;
  P2 cornerDir;
  bool hasIJK = false;
  P2 ijk;  // G40 with I/J/K: the direction the cancel vector points
};

struct OutSeg {
  Kind kind = Kind::Line;
  P2 start, end, center;
  bool rapid = false;
  int tag = -1;             // the programmed block this piece belongs to
  bool inserted = false;    // an extra corner move the control adds (outer acute corners)
  bool vectorAtEnd = true;  // false: the piece ends on the programmed point (no vector)
};

struct Options {
  bool startupTypeB = false;  // parameter 5003#0 SUP: 0 = type A, 1 = type B
  int lookahead = 3;          // blocks the control reads ahead (16i: 3)
  double epsilon = 1e-9;
};

struct CrcError : std::runtime_error {
  // Parameter names differ from the members: -Wshadow (an error here) rejects the same name.
  CrcError(AlarmId alarm, const std::string& detail, int blockTag)
      : std::runtime_error(detail), id(alarm), tag(blockTag) {}
  AlarmId id;
  int tag;  // block that raised it
};

class Compensator {
 public:
  explicit Compensator(Options o, std::function<void(const OutSeg&)> out);
  // A moving block (in the plane). Blocks whose side is Off and that follow an Off block
  // pass straight through.
  void push(const InSeg& s);
  // A block that does not move in the plane (M code, dwell, macro statement counted by
  // the control, other-axis move): it limits the lookahead.
  void pushNonMoving(int tag);
  // End of program or a buffering stop (M00, M30, G53 ...): emit everything held.
  void flush();
  // Lathe cycles start from their programmed start point: the held block ends there, with
  // no vector, and the next compensated block is a new start-up (src/exec/tnrc_exec.cpp).
  void suspend();
  bool active() const;  // compensation vectors in effect (between start-up and cancel)

 private:
  struct Impl;
  std::shared_ptr<Impl> impl_;
};

}  // namespace ncvm::crc
