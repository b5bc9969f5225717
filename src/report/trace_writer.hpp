#pragma once
// The JSON Lines trace (docs/trace-format.md): one object per event, in execution order.
// Formats into a buffer that goes to a FILE in large chunks, or stays in memory.
#include <cstdio>
#include <string>
#include <vector>

#include "canon/events.hpp"
#include "core/source.hpp"
#include "report/json_number.hpp"

namespace ncvm {

// The trace's name of a move mode: "rapid", "linear", "cw", "ccw".
const char* moveModeName(MoveMode m);

class TraceWriter final : public EventSink {
 public:
  // out == nullptr keeps the whole trace in buffer(). maxBytes stops a runaway trace.
  TraceWriter(const SourceFiles& files, std::FILE* out, uint64_t maxBytes, int axes = 3);
  ~TraceWriter() override;
  // The last move's text is kept as pointers into lines_: not copyable.
  TraceWriter(const TraceWriter&) = delete;
  TraceWriter& operator=(const TraceWriter&) = delete;
  void flush();
  const std::string& buffer() const { return buf_; }
  uint64_t bytes() const { return written_ + buf_.size(); }

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
  // Formats into its own buffer and writes its own FILE: it may run on a worker thread.
  bool runsOnAnyThread() const override { return true; }
  uint64_t byteHeadroom() const override { return bytes() >= maxBytes_ ? 0 : maxBytes_ - bytes(); }
  // No event's line is longer than this plus six times (an escaped byte is at most \u00XX)
  // its file and program names and texts: the worker's bound (src/timing/timing_thread.cpp).
  static constexpr uint64_t kMaxLineFixed = 4096 + 512;

 private:
  void begin(const char* type, const EventOrigin& at);
  void end();
  void checkLine();  // after a line: flush a full chunk, stop at the size limit
  void axes(const char* key, const AxisArray& a);
  void number(double v);  // exactly as fmt's "{}" (report/json_number.hpp), faster
  void number(int64_t v);
  int reportedAxes() const;  // axes_ clamped to 3..kMaxAxes
  void string(std::string_view s);
  std::string_view fileName(uint32_t id);
  std::string_view programName(const std::string& name);
  char* moveHead(char* p, std::string_view file, std::string_view prog, const EventOrigin& at);
  // A move's line is built in one of two buffers, in turn, and appended to buf_ once. The
  // text of an axis array stays readable there until the move after next: a move starts
  // where the last one ended, so its start is usually the text of that end again, and
  // without offsets its machine end is the text of its own end.
  struct AxesText {
    AxisArray v{};
    const char* text = nullptr;  // in lines_, or nullptr before the first move
    size_t len = 0;
  };
  char* putAxesCached(char* p, const AxisArray& a, int n, const AxesText* reuse, AxesText* save);
  // The head (names up to 2048 bytes, else written by begin()), then the rest, which is
  // bounded (six axis arrays, the centre, the path points and a few numbers of at most
  // kNumberChars each); kCopySlack for the 16-byte steps of copyText.
  static constexpr size_t kLineBytes = 2048 + 128 + 4096;
  static constexpr size_t kCopySlack = 32;
  const SourceFiles& files_;
  std::FILE* out_;
  uint64_t maxBytes_;
  int axes_;
  std::string buf_;
  uint64_t written_ = 0;
  bool full_ = false;  // the limit was passed (and thrown once)
  std::vector<std::string> escapedNames_;
  std::string lastProgram_, lastProgramEscaped_;  // programName(): the last one escaped
  AxesText lastEnd_, lastMend_;
  char lines_[2][kLineBytes + kCopySlack] = {};
  int line_ = 0;           // the buffer of lines_ the next move is built in
  uint32_t lastLine_ = 0;  // the last move's line and its text
  size_t lineLen_ = 0;
  char lineText_[kNumberChars + kCopySlack] = {};
  double lastFeed_ = 0;  // the last move's feed and its text
  size_t feedLen_ = 0;
  char feedText_[kNumberChars + kCopySlack] = {};
};

}  // namespace ncvm
