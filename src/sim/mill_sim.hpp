#pragma once
// A mill stock being cut: the height field, the tools, and the moves queued against them.
// Moves are queued and applied in batches by all cores: every thread runs every move on its
// own stripes of rows (mill_sweep.hpp), so each cell still sees the moves in program order
// and a rapid's collision is judged against the stock as it was when the rapid ran.
#include <cstdint>
#include <map>
#include <vector>

#include "sim/heightfield.hpp"
#include "sim/mill_sweep.hpp"
#include "sim/mill_tools.hpp"

namespace ncvm {

struct MillContact {
  enum Kind : uint8_t { Rapid, Shank, Holder } kind = Rapid;
  uint32_t tag = 0;  // the caller's tag of the move (e.g. an index of its block)
  float depth = 0;   // how deep the part went into the stock, mm
};

class MillSim {
 public:
  // threads = 0: all cores.
  explicit MillSim(HeightField field, int threads = 0);

  void setTool(const MillTool* tool) { tool_ = tool; }  // nullptr: no tool, moves cut nothing
  const MillTool* tool() const { return tool_; }

  // Tool tip from a to b. Rapids are checked for collisions; feed moves for shank and holder
  // contacts when the tool gives their size.
  void line(const Point3& a, const Point3& b, bool rapid, uint32_t tag);
  // Arc in the XY plane around (cx, cy) from angle a0 through `sweep` (ccw positive), the tip
  // going from z0 to z1 (a helix when they differ: cut as chords within `chordTol`).
  void arcXY(double cx, double cy, double radius, double a0, double sweep, double z0, double z1,
             bool rapid, uint32_t tag);

  // Applies everything queued. Called by the accessors below, and every kBatch moves.
  void flush();
  const HeightField& field() {
    flush();
    return field_;
  }
  const std::vector<MillContact>& contacts() {
    flush();
    return contacts_;
  }
  uint64_t moves() const { return moves_; }
  // Moves (distinct tags in a row) that removed material.
  uint64_t cuttingMoves() {
    flush();
    return cuttingMoves_;
  }
  int threads() const { return threads_; }

  static constexpr double kContactDepth = 0.001;  // mm: less is float noise, not a collision
  double chordTol = 0.0005;                       // mm, for helices

 private:
  struct Op {
    const MillTool* tool;
    Point3 a, b;
    double cx, cy, radius, a0, sweep;  // arcs (radius > 0)
    uint32_t tag;
    bool rapid, arc;
    bool startCut = false;  // continues the op before with the same tool (sweepLine)
  };
  void push(const Op& op);
  void run(int index, std::vector<float>& pen);

  static constexpr size_t kBatch = 1 << 15;
  HeightField field_;
  int threads_;
  const MillTool* tool_ = nullptr;
  std::vector<Op> ops_;
  std::vector<MillContact> contacts_;
  uint64_t moves_ = 0, cuttingMoves_ = 0;
  uint32_t lastCutTag_ = 0;
  bool anyCut_ = false;
  const MillTool* lastTool_ = nullptr;  // the tool and end point of the last op queued
  Point3 lastEnd_{};
};

}  // namespace ncvm
