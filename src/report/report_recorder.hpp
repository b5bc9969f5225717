#pragma once
// What the HTML report draws and lists beside the state JSON (`ncvm run --report`): the
// tool path, every G31 and every offset the program wrote. A sink beside the trace; it
// keeps plain values only (file ids, not names), so it may run on the time stage's thread.
//
// The path is kept in the stock's frame (sim/stock_frame.hpp, stock.frame, "work" by
// default): when a program moves work zero after it has begun to cut (a probing macro
// writing G54), the moves after it are drawn where the tool went on the machine, not
// shifted with the offset. Program units of the setup; lathe X as the moves give it.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "canon/events.hpp"
#include "machine/setup.hpp"
#include "sim/stock_frame.hpp"

namespace ncvm {

enum class PathKind : uint8_t { Rapid, Feed, Probe };

struct PathVertex {
  std::array<float, 3> p{};  // X Y Z in the frame
  PathKind kind = PathKind::Feed;
  bool start = false;  // the first vertex of a piece (the path before it does not join it)
};

struct RecordedOrigin {
  uint32_t file = 0, line = 0;
  int32_t n = -1;
};

struct RecordedProbe {
  RecordedOrigin at;
  bool hit = false;
  std::array<double, 3> position{};  // work coordinates as the program reads them (#5061-)
  std::array<float, 3> drawn{};      // the same point in the path's frame
};

struct RecordedOffset {
  RecordedOrigin at;
  std::string kind, name;
  int axis = -1;
  double value = 0;
};

class ReportRecorder final : public EventSink {
 public:
  // maxVertices bounds the memory (16 bytes a vertex); the moves past it are counted.
  explicit ReportRecorder(const Setup& setup, size_t maxVertices = 4'000'000,
                          size_t maxRows = 1000);

  void onMove(const MoveEvent& e) override;
  void onSkip(const SkipEvent& e) override;
  void onOffset(const OffsetEvent& e) override;
  void onWorkOrigin(const WorkOriginEvent& e) override { frame_.origin(e); }

  const std::vector<PathVertex>& path() const { return path_; }
  uint64_t moves() const { return moves_; }
  uint64_t movesNotDrawn() const { return movesNotDrawn_; }
  const std::vector<RecordedProbe>& probes() const { return probes_; }
  uint64_t probeCount() const { return probeCount_; }
  const std::vector<RecordedOffset>& offsets() const { return offsets_; }
  uint64_t offsetCount() const { return offsetCount_; }

 private:
  void add(const AxisArray& a, PathKind kind, bool start);

  StockFrame frame_;
  bool diameterX_;
  size_t maxVertices_, maxRows_;
  std::vector<PathVertex> path_;
  std::array<float, 3> last_{};
  bool haveLast_ = false;
  uint64_t moves_ = 0, movesNotDrawn_ = 0;
  std::vector<RecordedProbe> probes_;
  uint64_t probeCount_ = 0;
  std::vector<RecordedOffset> offsets_;
  uint64_t offsetCount_ = 0;
};

}  // namespace ncvm
