#pragma once
// The run answer for the web page (POST /api/run.bin) as a stream of binary frames, written
// while the program runs: the page draws a million moves from typed arrays instead of parsing
// a JSON object per event. docs/web-viewer.md ("Wire format") describes every field.
//
//   frame   := u32 kind, u32 length, payload[length], zero bytes up to a multiple of 8
//   kind 0  hello: JSON {"format": "ncvm-viewer", "version": 1, "axes": A, "machine": {"kind",
//           "axes"}}
//   kind 1  events: a batch of events as columns (little-endian; kBatchHeader u32 counts,
//           then the f64, f32, u32/i32, u16 and u8 columns, so that each is aligned)
//   kind 2  steps: JSON {"steps": [[event, delta], ...], "notes": [event, ...]}; the deltas
//           of state_diff.hpp (only non-empty ones), the events whose trace line is in kind 3
//   kind 3  notes: the trace lines (docs/trace-format.md) of the events that are not moves
//   kind 4  end: JSON, the rest of the answer (state, check, printed, machine, stock, files)
//           or {"ok": false, "error"}; always the last frame
//   kind 5  origins: JSON {"origins": [[event, x, y, z], ...]}: where work zero is on the
//           machine (work offset, EXT, G52, G92/G50; no tool offset) from that event on, in
//           the setup's units, X a radius; sent before the events frame of its batch, so the
//           page can draw the path fixed on the machine as the stock is (stock.frame)
//   kind 6  stock: the stock as cut by the first k moves of the run, a snapshot of the stock
//           simulation along the timeline (server/stock_snapshots.hpp has the layout); sent
//           before the end frame, in the order of k
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "canon/events.hpp"
#include "core/source.hpp"
#include "server/state_diff.hpp"

namespace ncvm {
class TraceWriter;
}

namespace ncvm::server {

enum class FrameKind : uint32_t {
  Hello = 0,
  Events = 1,
  Steps = 2,
  Notes = 3,
  End = 4,
  Origins = 5,
  Stock = 6
};

// Event kinds of the `kind` column: 0-3 are moves (MoveMode), the others one per event type.
enum class EventKind : uint8_t {
  Rapid = 0,
  Linear = 1,
  Cw = 2,
  Ccw = 3,
  Dwell = 8,
  Message = 9,
  Alarm = 10,
  Tool = 11,
  Spindle = 12,
  Coolant = 13,
  Aux = 14,
  Offset = 15,
  Skip = 16,
};

// Bits of the `flags` column.
enum EventFlag : uint8_t {
  kThread = 1,         // a move synchronised with the spindle
  kCompensated = 2,    // under cutter / nose radius compensation (end is the tool centre)
  kProbe = 4,          // the G31 move
  kOwnStart = 8,       // the move does not start where the last move ended: its start is sent
  kOwnPositions = 16,  // #5001-/#5021-/#5041- are not the last move's end, mend, end: sent
  kArc = 32,           // an arc: its centre and plane are sent
};

// u32 counts at the head of an events payload: events, moves, own starts, own positions,
// arcs, dog-leg corner points, axes, 0.
constexpr size_t kBatchHeader = 8;

using StreamOutput = std::function<void(std::string_view)>;

// One frame, header and padding included.
std::string frame(FrameKind kind, std::string_view payload);

class ViewerStream final : public EventSink {
 public:
  // Every frame goes to `out` as soon as it is complete. maxNoteBytes bounds the kind 3
  // text (the run's trace limit).
  ViewerStream(const SourceFiles& files, const Setup& setup, uint64_t maxNoteBytes,
               StreamOutput out, size_t batchEvents = 16384);
  ~ViewerStream() override;
  ViewerStream(const ViewerStream&) = delete;
  ViewerStream& operator=(const ViewerStream&) = delete;
  void attach(Executor* exec) { diff_.attach(exec); }
  // How text the client sees is shown: file names and the notes' and steps' text pass
  // through `rename` (the server names its folders by their roots: run_job.cpp).
  void renameText(std::function<std::string(std::string)> rename) { rename_ = std::move(rename); }
  // The last batch, then the end frame with `tail` and "files" (the names of the file ids).
  void finish(nlohmann::json tail);
  uint64_t events() const { return events_; }

  void onMove(const MoveEvent& e) override;
  void onDwell(const DwellEvent& e) override;
  void onMessage(const MessageEvent& e) override;
  void onAlarm(const AlarmEvent& e) override;
  void onTool(const ToolEvent& e) override;
  void onSpindle(const SpindleEvent& e) override;
  void onCoolant(const CoolantEvent& e) override;
  void onAux(const AuxEvent& e) override;
  void onOffset(const OffsetEvent& e) override;
  void onSkip(const SkipEvent& e) override;
  void onWorkOrigin(const WorkOriginEvent& e) override;

 private:
  // A non-move event: its trace line (into notes), then its columns.
  template <class Write>
  void note(EventKind kind, const EventOrigin& at, double dt, bool offsetsChanged, Write write);
  void columns(EventKind kind, uint8_t flags, const EventOrigin& at, double dt,
               bool offsetsChanged);
  void flushBatch();

  std::string shown(std::string text) const { return rename_ ? rename_(std::move(text)) : text; }

  const SourceFiles& files_;
  std::function<std::string(std::string)> rename_;
  const int axes_;
  StreamOutput out_;
  const size_t batchEvents_;
  StateDiff diff_;
  // The notes' trace lines go through a TraceWriter into a memory FILE.
  char* noteMem_ = nullptr;
  size_t noteSize_ = 0, noteSent_ = 0;
  std::FILE* noteFile_ = nullptr;
  std::unique_ptr<TraceWriter> trace_;

  uint64_t events_ = 0;  // events before this batch and in it
  std::vector<std::string> fileNames_;
  AxisArray lastEnd_{}, lastMend_{};
  bool haveLast_ = false;
  // The batch's columns.
  std::vector<double> time_, pos_, start_, end_, mend_, center_, path_, dt_;
  std::vector<float> feed_;
  std::vector<uint32_t> line_, block_;
  std::vector<int32_t> n_;
  std::vector<uint16_t> file_, pathCount_;
  std::vector<uint8_t> kind_, flags_, plane_;
  const double unitsPerMm_;  // the setup's units, as the stock frame counts them
  nlohmann::json origins_ = nlohmann::json::array();
  nlohmann::json steps_ = nlohmann::json::array();
  nlohmann::json notes_ = nlohmann::json::array();
};

}  // namespace ncvm::server
