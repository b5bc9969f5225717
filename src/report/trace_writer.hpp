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

 private:
  void begin(const char* type, const EventOrigin& at);
  void end();
  void axes(const char* key, const AxisArray& a);
  void number(double v);  // exactly as fmt's "{}" (report/json_number.hpp), faster
  void number(int64_t v);
  int reportedAxes() const;  // axes_ clamped to 3..kMaxAxes
  void string(std::string_view s);
  const std::string& fileName(uint32_t id);

  const SourceFiles& files_;
  std::FILE* out_;
  uint64_t maxBytes_;
  int axes_;
  std::string buf_;
  uint64_t written_ = 0;
  std::vector<std::string> escapedNames_;
};

}  // namespace ncvm
