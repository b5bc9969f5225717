#include "report/trace_writer.hpp"

#include <fmt/format.h>

#include <cstring>

#include "core/alarm.hpp"
#include "report/json_number.hpp"

namespace ncvm {

namespace {
constexpr size_t kChunk = 1 << 20;

const char* moveModeName(MoveMode m) {
  switch (m) {
    case MoveMode::Rapid: return "rapid";
    case MoveMode::Linear: return "linear";
    case MoveMode::Cw: return "cw";
    case MoveMode::Ccw: return "ccw";
  }
  return "linear";
}

void escapeInto(std::string& out, std::string_view s) {
  out += '"';
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", static_cast<int>(c));
        else out += c;
    }
  }
  out += '"';
}
}  // namespace

TraceWriter::TraceWriter(const SourceFiles& files, std::FILE* out, uint64_t maxBytes, int axes)
    : files_(files), out_(out), maxBytes_(maxBytes), axes_(axes) {
  buf_.reserve(out ? kChunk + 4096 : 4096);
}

TraceWriter::~TraceWriter() {
  try {
    flush();
  } catch (...) {
  }
}

void TraceWriter::flush() {
  if (!out_ || buf_.empty()) return;
  if (std::fwrite(buf_.data(), 1, buf_.size(), out_) != buf_.size())
    throw AlarmError(AlarmId::OutputError, "trace");
  written_ += buf_.size();
  buf_.clear();
}

const std::string& TraceWriter::fileName(uint32_t id) {
  if (id >= escapedNames_.size()) escapedNames_.resize(id + 1);
  std::string& s = escapedNames_[id];
  if (s.empty()) escapeInto(s, files_.name(id));
  return s;
}

void TraceWriter::begin(const char* type, const EventOrigin& at) {
  buf_ += "{\"type\":\"";
  buf_ += type;
  buf_ += "\",\"file\":";
  buf_ += fileName(at.file);
  buf_ += ",\"line\":";
  number(static_cast<int64_t>(at.line));
  buf_ += ",\"n\":";
  if (at.n >= 0)
    number(static_cast<int64_t>(at.n));
  else
    buf_ += "null";
  buf_ += ",\"prog\":";
  if (at.programName) escapeInto(buf_, *at.programName);
  else buf_ += "null";
}

void TraceWriter::end() {
  buf_ += "}\n";
  if (buf_.size() >= kChunk && out_) flush();
  if (written_ + buf_.size() > maxBytes_) throw AlarmError(AlarmId::TraceLimit, "limits.max_trace_bytes");
}

void TraceWriter::number(double v) {
  char tmp[kNumberChars];
  buf_.append(tmp, static_cast<size_t>(formatDouble(tmp, v) - tmp));
}

void TraceWriter::number(int64_t v) {
  char tmp[kNumberChars];
  buf_.append(tmp, static_cast<size_t>(formatInt(tmp, v) - tmp));
}

void TraceWriter::axes(const char* key, const AxisArray& a) {
  // One buffer for the whole array: this runs four times per move.
  char tmp[16 + kMaxAxes * (kNumberChars + 1)];
  char* p = tmp;
  *p++ = ',';
  *p++ = '"';
  size_t len = std::strlen(key);
  std::memcpy(p, key, len);
  p += len;
  *p++ = '"';
  *p++ = ':';
  *p++ = '[';
  int n = axes_ < 3 ? 3 : (axes_ > kMaxAxes ? kMaxAxes : axes_);
  for (int k = 0; k < n; ++k) {
    if (k) *p++ = ',';
    p = formatDouble(p, a[static_cast<size_t>(k)]);
  }
  *p++ = ']';
  buf_.append(tmp, static_cast<size_t>(p - tmp));
}

void TraceWriter::string(std::string_view s) { escapeInto(buf_, s); }

void TraceWriter::onMove(const MoveEvent& e) {
  begin("move", e.at);
  buf_ += ",\"mode\":\"";
  buf_ += moveModeName(e.mode);
  buf_ += '"';
  axes("start", e.start);
  axes("end", e.end);
  axes("mstart", e.mstart);
  axes("mend", e.mend);
  buf_ += ",\"feed\":";
  number(e.feed);
  buf_ += ",\"length\":";
  number(e.length);
  buf_ += ",\"time\":";
  number(e.time);
  if (e.arc)
    fmt::format_to(std::back_inserter(buf_), ",\"center\":[{},{},{}],\"plane\":{}", e.center[0], e.center[1],
                   e.center[2], e.plane);
  if (e.compensated) axes("prog_end", e.programmedEnd);
  if (e.thread) buf_ += ",\"thread\":true";
  if (e.pathPoints > 0) {
    buf_ += ",\"path\":[";
    for (int k = 0; k < e.pathPoints; ++k) {
      const AxisArray& p = e.path[static_cast<size_t>(k)];
      fmt::format_to(std::back_inserter(buf_), "{}[{},{},{}]", k ? "," : "", p[0], p[1], p[2]);
    }
    buf_ += ']';
  }
  end();
}

void TraceWriter::onDwell(const DwellEvent& e) {
  begin("dwell", e.at);
  fmt::format_to(std::back_inserter(buf_), ",\"time\":{}", e.time);
  if (e.revolutions > 0) fmt::format_to(std::back_inserter(buf_), ",\"revolutions\":{}", e.revolutions);
  end();
}

void TraceWriter::onMessage(const MessageEvent& e) {
  begin("message", e.at);
  buf_ += ",\"text\":";
  string(e.text);
  buf_ += ",\"source\":";
  string(e.source);
  end();
}

void TraceWriter::onAlarm(const AlarmEvent& e) {
  begin("alarm", e.at);
  buf_ += ",\"code\":";
  string(e.code);
  buf_ += ",\"text\":";
  string(e.text);
  buf_ += "}\n";  // no limit check: the alarm must always be written
}

void TraceWriter::onTool(const ToolEvent& e) {
  begin("tool", e.at);
  fmt::format_to(std::back_inserter(buf_), ",\"tool\":{},\"change\":{}", e.tool, e.change);
  end();
}

void TraceWriter::onSpindle(const SpindleEvent& e) {
  static const char* dirs[] = {"stop", "cw", "ccw", "orient"};
  begin("spindle", e.at);
  fmt::format_to(std::back_inserter(buf_), ",\"dir\":\"{}\",\"rpm\":{}", dirs[static_cast<int>(e.dir)], e.rpm);
  end();
}

void TraceWriter::onCoolant(const CoolantEvent& e) {
  static const char* states[] = {"off", "flood", "mist"};
  begin("coolant", e.at);
  fmt::format_to(std::back_inserter(buf_), ",\"state\":\"{}\"", states[static_cast<int>(e.state)]);
  end();
}

void TraceWriter::onAux(const AuxEvent& e) {
  begin("aux", e.at);
  fmt::format_to(std::back_inserter(buf_), ",\"letter\":\"{}\",\"code\":{}", e.letter, e.code);
  end();
}

void TraceWriter::onOffset(const OffsetEvent& e) {
  begin("offset", e.at);
  buf_ += ",\"kind\":";
  string(e.kind);
  buf_ += ",\"name\":";
  string(e.name);
  fmt::format_to(std::back_inserter(buf_), ",\"axis\":{},\"value\":{}", e.axis, e.value);
  end();
}

void TraceWriter::onSkip(const SkipEvent& e) {
  begin("skip", e.at);
  fmt::format_to(std::back_inserter(buf_), ",\"hit\":{}", e.hit);
  axes("position", e.position);
  axes("mposition", e.mposition);
  end();
}

}  // namespace ncvm
