#include "report/report_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "canon/arc_sweep.hpp"

namespace ncvm {

namespace {

RecordedOrigin origin(const EventOrigin& at) {
  return {at.file, at.line, at.n};
}

std::array<float, 3> point(const AxisArray& a) {
  return {static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2])};
}

// Chords every 5 degrees: a picture of at most ~1000 pixels shows no facets at that.
constexpr double kArcStep = std::numbers::pi / 36;

}  // namespace

ReportRecorder::ReportRecorder(const Setup& setup, size_t maxVertices, size_t maxRows)
    : frame_(setup, setup.kind == MachineKind::Lathe && setup.axes[0].diameter),
      diameterX_(setup.kind == MachineKind::Lathe && setup.axes[0].diameter),
      maxVertices_(maxVertices),
      maxRows_(maxRows) {}

void ReportRecorder::add(const AxisArray& a, PathKind kind, bool start) {
  auto p = point(a);
  // A vertex where the last one is adds nothing. A vertex's kind is that of the segment
  // that ends there.
  if (!start && haveLast_ && p == last_) return;
  path_.push_back({p, kind, start});
  last_ = p;
  haveLast_ = true;
}

void ReportRecorder::onMove(const MoveEvent& in) {
  ++moves_;
  frame_.move(in);
  // Each move needs at most its arc chords or dog-leg corners plus two vertices.
  if (path_.size() + 2 + kMaxAxes + static_cast<size_t>(2 * std::numbers::pi / kArcStep) + 1 >
      maxVertices_) {
    ++movesNotDrawn_;
    return;
  }
  MoveEvent scratch;
  const MoveEvent& e = frame_.place(in, scratch);
  const PathKind kind = e.skip                      ? PathKind::Probe
                        : e.mode == MoveMode::Rapid ? PathKind::Rapid
                                                    : PathKind::Feed;
  // The move starts where the last one ended unless work zero moved between them (the frame
  // shifts only between moves): then it is a new piece.
  const bool joined = haveLast_ && point(e.start) == last_;
  if (!joined) add(e.start, kind, true);
  if (e.arc) {
    const ArcSweep arc = arcSweepOf(e);
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(arc.sweep) / kArcStep)));
    for (int k = 1; k < n; ++k) {
      AxisArray q = e.end;
      arc.place(static_cast<double>(k) / n, q);
      add(q, kind, false);
    }
  } else {
    for (int k = 0; k < e.pathPoints; ++k) add(e.path[static_cast<size_t>(k)], kind, false);
  }
  add(e.end, kind, false);
}

void ReportRecorder::onSkip(const SkipEvent& e) {
  ++probeCount_;
  if (probes_.size() >= maxRows_) return;
  RecordedProbe r;
  r.at = origin(e.at);
  r.hit = e.hit;
  for (size_t k = 0; k < 3; ++k) r.position[k] = e.position[k];
  const auto& s = frame_.shift();
  r.drawn = {static_cast<float>(e.position[0] + (diameterX_ ? 2 * s[0] : s[0])),
             static_cast<float>(e.position[1] + s[1]), static_cast<float>(e.position[2] + s[2])};
  probes_.push_back(r);
}

void ReportRecorder::onOffset(const OffsetEvent& e) {
  ++offsetCount_;
  if (offsets_.size() >= maxRows_) return;
  offsets_.push_back({origin(e.at), std::string(e.kind), std::string(e.name), e.axis, e.value});
}

}  // namespace ncvm
