#pragma once
// The JSON Lines trace (docs/trace-format.md): one object per event, in execution order.
// Formats into a buffer that goes to a FILE in large chunks, or stays in memory.
#include <cstdio>
#include <memory>
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
  // The last move's text is found again by offsets into the buffer: not copyable.
  TraceWriter(const TraceWriter&) = delete;
  TraceWriter& operator=(const TraceWriter&) = delete;
  void flush();
  // The errno of the write that failed (a full disk, a file-size limit), 0 while none did.
  int writeError() const { return writeError_; }
  // The trace so far (out == nullptr: all of it), copied out of the buffer.
  const std::string& buffer() const;
  uint64_t bytes() const { return written_ + used_; }

  void onMove(const MoveEvent& e) override;
  void onDwell(const DwellEvent& e) override;
  void onMessage(const MessageEvent& e) override;
  void onAlarm(const AlarmEvent& e) override;
  void onTool(const ToolEvent& e) override;
  void onSpindle(const SpindleEvent& e) override;
  void onCoolant(const CoolantEvent& e) override;
  void onAux(const AuxEvent& e) override;
  void onSignal(const SignalEvent& e) override;
  void onOffset(const OffsetEvent& e) override;
  void onSkip(const SkipEvent& e) override;

 private:
  // A line other than a move's is built in ev_ with appends, from begin() to end().
  void begin(const char* type, const EventOrigin& at);
  void end();
  void append(const std::string& s);  // copies s to the buffer
  // At least n bytes of room after the text; lines are written there, then commit()ed.
  char* room(size_t n) {
    if (cap_ - used_ < n) grow(n);
    return buf_.get() + used_;
  }
  void grow(size_t n);
  void commit(const char* end) { used_ = static_cast<size_t>(end - buf_.get()); }
  // After a line: flush a full chunk, stop at the size limit (the usual case inline).
  void checkLine() {
    if (used_ >= kChunk || written_ + used_ > maxBytes_) checkedLine();
  }
  void checkedLine();
  void axes(const char* key, const AxisArray& a);
  void number(double v);  // exactly as fmt's "{}" (report/json_number.hpp), faster
  void number(int64_t v);
  int reportedAxes() const;  // axes_ clamped to 3..kMaxAxes
  void string(std::string_view s);
  std::string_view fileName(uint32_t id);
  std::string_view programName(const std::string& name);
  // A move's line is written straight into the buffer. Its head is made of two texts kept
  // from the moves before: `{"type":"move","file":F,"line":`, then the line number and N,
  // then `,"prog":P,"mode":"M","start":` (one text for each of the four modes: the mode
  // changes often, the program seldom). moveOrigin() writes them again when F or P is not
  // the last move's (compared inline: the same file id and program text).
  [[gnu::noinline]] void moveOrigin(const EventOrigin& at);
  char* lineNumber(char* p, uint32_t line);
  // The text of an axis array stays in the buffer until it is flushed: a move starts where
  // the last one ended, so its start is usually the text of that end again, and without
  // offsets its machine end is the text of its own end.
  struct AxesText {
    AxisArray v{};
    size_t at = 0;   // offset in buf_
    size_t len = 0;  // 0: none (before the first move, after a flush)
  };
  // Inline, so that the usual n == 3 unrolls (onMove calls movePositions for it apart).
  [[gnu::always_inline]] char* putAxesCached(char* p, const AxisArray& a, int n,
                                             const AxesText* reuse, AxesText* save);
  // start, end, mstart and mend.
  [[gnu::always_inline]] char* movePositions(char* p, const MoveEvent& e, int n);
  // The head (names up to 2048 bytes, else written by begin()), then the rest, which is
  // bounded (six axis arrays, the centre, the path points and a few numbers of at most
  // kNumberChars each); kCopySlack for the 16-byte steps of copyText, which may read and
  // write up to 15 bytes past a text.
  static constexpr size_t kLineBytes = 2048 + 128 + 4096;
  static constexpr size_t kCopySlack = 32;
  static constexpr size_t kChunk = 1 << 20;  // bytes written to the FILE at once
  const SourceFiles& files_;
  std::FILE* out_;
  uint64_t maxBytes_;
  int axes_;
  std::unique_ptr<char[]> buf_;  // the text not yet written, then room (not initialised)
  size_t used_ = 0, cap_ = 0;
  mutable std::string text_;  // buffer()'s copy
  std::string ev_;            // the line of an event other than a move
  uint64_t written_ = 0;
  int writeError_ = 0;
  bool full_ = false;  // the limit was passed (and thrown once)
  std::vector<std::string> escapedNames_;
  std::string lastProgram_, lastProgramEscaped_;  // programName(): the last one escaped
  // moveOrigin(): the last move's file and program, and its texts with kCopySlack.
  uint32_t moveFile_ = ~uint32_t{0};  // none yet
  bool moveHasProgram_ = false;
  bool moveLongNames_ = false;  // over 2048 bytes: begin() writes the head
  std::string moveProgram_, moveHead_;
  std::string moveMiddle_[4];  // by MoveMode
  AxesText lastEnd_, lastMend_;
  uint32_t lastLine_ = 0;  // the last move's line and its text
  size_t lineLen_ = 0;
  char lineText_[kNumberChars + kCopySlack] = {};
  double lastFeed_ = 0;  // the last move's feed and its text
  size_t feedLen_ = 0;
  char feedText_[kNumberChars + kCopySlack] = {};
};

}  // namespace ncvm
