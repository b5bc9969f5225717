// Direct drawing dimension programming (lathe ,A). The angle of a line is measured from the
// +Z axis, counter-clockwise in the ZX plane (X up), on the radius: a drawing's geometry, while
// X stays a diameter in the program. Two forms:
//   - one end coordinate and the angle (`G01 X.. ,A..` or `G01 Z.. ,A..`, also U/W): the
//     other coordinate is where the line through the start point meets it;
//   - the angle alone (`G01 ,A1`), then a block with absolute X, Z and ,A2: the first block
//     ends where its line meets the second block's line through X, Z.
// ncvm rewrites the block with its end point as U (a diameter on a diameter axis) and W, so
// every path after it (plain moves, ,C/,R corners, tool-nose compensation, the G70-G73
// shapes) sees an ordinary block. A line is an angle modulo 180 degrees: only parallel lines
// have no end point.
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "exec/executor.hpp"
#include "exec/words.hpp"

namespace ncvm {

namespace {
AlarmError angleAlarm(AlarmId id, const Words& w, const std::string& what) {
  AlarmError e(id, what);
  e.col = w.commaACol;
  return e;
}

struct Direction {
  double z, x;
};
Direction directionOf(double degrees) {
  const double rad = degrees * std::numbers::pi / 180.0;
  return {std::cos(rad), std::sin(rad)};
}

// The motion code (x10) a block's G codes leave, given the one before it.
int motionAfter(const Words& w, int before) {
  for (int k = 0; k < w.ng; ++k) {
    int code = w.g[static_cast<size_t>(k)];
    if (code == 0 || code == 10 || code == 20 || code == 30) before = code;
  }
  return before;
}

double unitNm(InputUnit u) {
  return u == InputUnit::Inch ? 25.4e6 : 1e6;
}

void setWord(Words& w, char letter, double v) {
  w.present |= Words::bit(letter);
  w.point |= Words::bit(letter);
  w.val[static_cast<size_t>(letter - 'A')] = v;
}
}  // namespace

void Executor::directDrawingHere(Words& w) {
  const Block* second = angleSecond_;
  angleSecond_ = nullptr;
  if (!lathe_)
    throw angleAlarm(AlarmId::ImproperAddress, w,
                     ",A (direct drawing dimensions) is a lathe address");
  if (block_ == second) {
    // The second block of an angle-only pair: its X and Z are its end point (checked when
    // the first block found it), its angle has made the first block's corner.
    w.hasCommaA = false;
    return;
  }
  const bool cycle = modal_.g[9] != 800 || latheCycleKind(modal_.motion) != 0;
  bool oneShot = false;
  for (int k = 0; k < w.ng; ++k) {
    const GCodeInfo* info = gInfo(w.g[static_cast<size_t>(k)]);
    oneShot |= info && info->group == 0;
  }
  if (cycle || oneShot)
    throw angleAlarm(AlarmId::ImproperGCode, w, ",A in a cycle or one-shot G code block");
  if (modal_.plane != 18)
    throw angleAlarm(AlarmId::DirectDrawingPlane, w, ",A outside the G18 plane");
  // Under tool-nose compensation the programmed path is the base, as for U and W.
  const bool comp = modal_.g[7] != 400 || crcBusy();
  const std::array<int64_t, kMaxAxes> here = comp ? programmed_ : programmedHere();
  const lathe::Pt start{static_cast<double>(here[0]) / unitNm(modal_.unit),
                        static_cast<double>(here[2]) / unitNm(modal_.unit)};
  const double diameter = setup_.axes[0].diameter ? 2.0 : 1.0;
  if (w.has('X') || w.has('U') || w.has('Z') || w.has('W')) {
    directDrawing(w, start, modal_.motion, diameter);
    return;
  }
  // The angle alone: the next NC block (empty and skipped blocks aside) gives the corner.
  const Program& prog = *frames_.back().prog;
  wholeProgram(prog);
  const Block* next = nullptr;
  for (size_t k = static_cast<size_t>(block_ - prog.blocks.data()) + 1; k < prog.blocks.size();
       ++k) {
    const Block& b = prog.blocks[k];
    if (b.kind == BlockKind::Empty || (b.skipLevel && setup_.blockSkip[b.skipLevel])) continue;
    next = &b;
    break;
  }
  if (!next || next->kind != BlockKind::Nc)
    throw angleAlarm(AlarmId::EndPointNotFound, w,
                     "an angle-only ,A block must be followed by an NC block with X, Z and ,A");
  Words nw;
  const Block* saved = block_;
  block_ = next;  // an alarm in its words names the next block
  gatherWords(*next, nw);
  block_ = saved;
  bool incremental = modal_.incremental;
  if (series_ != Series::TA)
    for (int k = 0; k < nw.ng; ++k) {
      int code = nw.g[static_cast<size_t>(k)];
      if (code == 900 || code == 910) incremental = code == 910;
    }
  directDrawingCorner(w, modal_.motion, nw, motionAfter(nw, modal_.motion), incremental, start,
                      diameter);
  angleSecond_ = next;
}

void Executor::directDrawing(Words& w, const lathe::Pt& start, int motion, double diameter) const {
  if (motion != 0 && motion != 10)
    throw angleAlarm(AlarmId::ImproperGCode, w, ",A needs G00 or G01");
  const bool hasX = w.has('X') || w.has('U'), hasZ = w.has('Z') || w.has('W');
  if (hasX && hasZ)
    throw angleAlarm(AlarmId::NoEndPointAndAngle, w,
                     ",A with both X and Z, and no angle-only ,A block before it");
  const double unit = unitNm(modal_.unit);
  const Direction d = directionOf(w.commaAngle);
  if (hasX) {
    // The X end (radius) as the move reads it; the line's Z run follows from the angle.
    double dx = 0;
    if (w.has('X')) {
      double x = static_cast<double>(lengthNm(w.value('X'), w.hasPoint('X'), 0)) / diameter / unit;
      dx = modal_.incremental ? x : x - start.x;
    } else {
      dx = static_cast<double>(lengthNm(w.value('U'), w.hasPoint('U'), 0)) / diameter / unit;
    }
    if (std::fabs(d.x) < 1e-9)
      throw angleAlarm(AlarmId::NoSolutionOfBlockEnd, w,
                       fmt::format(",A{} runs along Z: no X end point", w.commaAngle));
    setWord(w, 'W', dx * d.z / d.x);
  } else {
    double dz = 0;
    if (w.has('Z')) {
      double z = static_cast<double>(lengthNm(w.value('Z'), w.hasPoint('Z'), 2)) / unit;
      dz = modal_.incremental ? z : z - start.z;
    } else {
      dz = static_cast<double>(lengthNm(w.value('W'), w.hasPoint('W'), 2)) / unit;
    }
    if (std::fabs(d.z) < 1e-9)
      throw angleAlarm(AlarmId::NoSolutionOfBlockEnd, w,
                       fmt::format(",A{} runs along X: no Z end point", w.commaAngle));
    setWord(w, 'U', dz * d.x / d.z * diameter);
  }
}

void Executor::directDrawingCorner(Words& w, int motion, const Words& next, int nextMotion,
                                   bool nextIncremental, const lathe::Pt& start,
                                   double diameter) const {
  if (motion != 0 && motion != 10)
    throw angleAlarm(AlarmId::ImproperGCode, w, ",A needs G00 or G01");
  if (nextMotion != 0 && nextMotion != 10)
    throw AlarmError(AlarmId::ImproperGCode,
                     "the block after an angle-only ,A block is not G00 or G01");
  // The control needs the second line's point: absolute X and Z, and its angle.
  if (!next.hasCommaA || !next.has('X') || !next.has('Z') || nextIncremental)
    throw angleAlarm(AlarmId::NoEndPointAndAngle, w,
                     "the block after an angle-only ,A block needs absolute X, Z and ,A");
  const double unit = unitNm(modal_.unit);
  const lathe::Pt end{
      static_cast<double>(lengthNm(next.value('X'), next.hasPoint('X'), 0)) / diameter / unit,
      static_cast<double>(lengthNm(next.value('Z'), next.hasPoint('Z'), 2)) / unit};
  const Direction a = directionOf(w.commaAngle), b = directionOf(next.commaAngle);
  // start + t a = end + s b; the cross product of the directions is 0 for parallel lines.
  const double cross = a.z * b.x - a.x * b.z;
  if (std::fabs(cross) < 1e-9)
    throw angleAlarm(
        AlarmId::NoSolutionOfBlockEnd, w,
        fmt::format(",A{} and ,A{} are parallel: no corner", w.commaAngle, next.commaAngle));
  const double t = ((end.z - start.z) * b.x - (end.x - start.x) * b.z) / cross;
  setWord(w, 'U', t * a.x * diameter);
  setWord(w, 'W', t * a.z);
}

// Shape block k of G70-G73 (the shape's own motion mode; X a diameter as latheTarget reads
// it). `second` is the block whose ,A an angle-only block before it has used.
void Executor::shapeDirectDrawing(const Program& prog, int32_t k, int32_t last, Words& w,
                                  const lathe::Pt& at, int motion, int32_t& second) {
  if (k == second) {
    w.hasCommaA = false;
    return;
  }
  if (w.any("XZUW")) {
    directDrawing(w, at, motion, 2.0);
    return;
  }
  int32_t n = k + 1;
  while (n <= last && prog.blocks[static_cast<size_t>(n)].kind == BlockKind::Empty) ++n;
  if (n > last)
    throw angleAlarm(AlarmId::ShapeLastBlockIllegal, w, "angle-only ,A in the last shape block");
  const Block& next = prog.blocks[static_cast<size_t>(n)];
  const Block* saved = block_;
  block_ = &next;  // an alarm in its words names the next block
  if (next.kind != BlockKind::Nc)
    throw AlarmError(AlarmId::CycleUnavailableCommand, "only NC blocks between P and Q");
  Words nw;
  gatherWords(next, nw);
  block_ = saved;
  directDrawingCorner(w, motion, nw, motionAfter(nw, motion), modal_.incremental, at, 2.0);
  second = n;
}

}  // namespace ncvm
