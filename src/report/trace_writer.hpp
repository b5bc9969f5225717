#pragma once
// The JSON Lines trace (docs/trace-format.md): one object per event, in execution order.
// Formats into a buffer that goes to a FILE in large chunks, or stays in memory.
#include <cstdio>
#include <string>
#include <vector>

#include "canon/events.hpp"
#include "core/source.hpp"

namespace ncvm {

class TraceWriter final : public EventSink {
 public:
  // out == nullptr keeps the whole trace in buffer(). maxBytes stops a runaway trace.
  TraceWriter(const SourceFiles& files, std::FILE* out, uint64_t maxBytes, int axes = 3);
  ~TraceWriter() override;
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
  void axes(const char* key, const AxisArray& a);
  void number(double v);  // exactly as fmt's "{}" (report/json_number.hpp), faster
  void number(int64_t v);
  int reportedAxes() const;  // axes_ clamped to 3..kMaxAxes
  void string(std::string_view s);
  const std::string& fileName(uint32_t id);
  const std::string& programName(const std::string& name);
  char* moveHead(char* p, const EventOrigin& at);
  // The text of an axis array ("[1.5,2,-3]") as last written, with its values: a move
  // starts where the last one ended, so its start is usually that end's text again.
  struct AxesText {
    int n = 0;
    AxisArray v{};
    size_t len = 0;
    char text[2 + kMaxAxes * 33];
  };
  char* putAxesCached(char* p, std::string_view key, const AxisArray& a, int n, AxesText* reuse,
                      AxesText* save);

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
};

}  // namespace ncvm
