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

// Length of the well-formed UTF-8 sequence at s[i], or 0 if it is not one.
size_t utf8Length(std::string_view s, size_t i) {
  auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  unsigned char c = byte(i);
  size_t n = (c >= 0xC2 && c <= 0xDF)   ? 2
             : (c >= 0xE0 && c <= 0xEF) ? 3
             : (c >= 0xF0 && c <= 0xF4) ? 4
                                        : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  // No overlong forms, no UTF-16 surrogates, nothing past U+10FFFF.
  unsigned char d = byte(i + 1);
  if ((c == 0xE0 && d < 0xA0) || (c == 0xED && d > 0x9F) || (c == 0xF0 && d < 0x90) ||
      (c == 0xF4 && d > 0x8F))
    return 0;
  return n;
}

// Program text is not always UTF-8 (old tapes, Latin-1 comments): a byte that does not
// start a well-formed sequence becomes U+FFFD, so every trace line stays valid JSON.
void escapeInto(std::string& out, std::string_view s) {
  out += '"';
  for (size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (static_cast<unsigned char>(c) >= 0x80) {
      size_t n = utf8Length(s, i);
      if (n == 0) {
        out += "\\ufffd";
      } else {
        out.append(s.substr(i, n));
        i += n - 1;
      }
      continue;
    }
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

// A program's name escaped; the same one as the event before is not escaped again.
const std::string& TraceWriter::programName(const std::string& name) {
  if (name != lastProgram_ || lastProgramEscaped_.empty()) {
    lastProgram_ = name;
    lastProgramEscaped_.clear();
    escapeInto(lastProgramEscaped_, name);
  }
  return lastProgramEscaped_;
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
  if (at.programName)
    buf_ += programName(*at.programName);
  else buf_ += "null";
}

void TraceWriter::end() {
  buf_ += "}\n";
  if (buf_.size() >= kChunk && out_) flush();
  if (written_ + buf_.size() > maxBytes_) {
    // The events the control still sends (the moves the time stage held, the alarm's
    // release of a look-ahead) would only throw again: the trace ends with the alarm.
    full_ = true;
    throw AlarmError(AlarmId::TraceLimit, "limits.max_trace_bytes");
  }
}

void TraceWriter::number(double v) {
  char tmp[kNumberChars];
  buf_.append(tmp, static_cast<size_t>(formatDouble(tmp, v) - tmp));
}

void TraceWriter::number(int64_t v) {
  char tmp[kNumberChars];
  buf_.append(tmp, static_cast<size_t>(formatInt(tmp, v) - tmp));
}

namespace {
// Writers into a caller's buffer: a move is formatted on the stack and appended once.
template <size_t N>
char* put(char* p, const char (&literal)[N]) {
  std::memcpy(p, literal, N - 1);
  return p + N - 1;
}

char* putAxes(char* p, std::string_view key, const double* a, int n) {
  *p++ = ',';
  *p++ = '"';
  std::memcpy(p, key.data(), key.size());
  p += key.size();
  p = put(p, "\":[");
  for (int k = 0; k < n; ++k) {
    if (k) *p++ = ',';
    p = formatDouble(p, a[k]);
  }
  *p++ = ']';
  return p;
}
}  // namespace

// begin("move", at), written into a caller's buffer (the names are at most a few kB, which
// moveHead's caller leaves room for).
char* TraceWriter::moveHead(char* p, const EventOrigin& at) {
  p = put(p, "{\"type\":\"move\",\"file\":");
  const std::string& file = fileName(at.file);
  std::memcpy(p, file.data(), file.size());
  p = put(p + file.size(), ",\"line\":");
  p = formatInt(p, static_cast<int64_t>(at.line));
  p = put(p, ",\"n\":");
  p = at.n >= 0 ? formatInt(p, static_cast<int64_t>(at.n)) : put(p, "null");
  p = put(p, ",\"prog\":");
  if (!at.programName) return put(p, "null");
  const std::string& prog = programName(*at.programName);
  std::memcpy(p, prog.data(), prog.size());
  return p + prog.size();
}

// putAxes, taking the text from `reuse` when it holds the same values (bit for bit) and
// keeping the text written in `save`.
char* TraceWriter::putAxesCached(char* p, std::string_view key, const AxisArray& a, int n,
                                 AxesText* reuse, AxesText* save) {
  *p++ = ',';
  *p++ = '"';
  std::memcpy(p, key.data(), key.size());
  p += key.size();
  p = put(p, "\":");
  const auto bytes = static_cast<size_t>(n) * sizeof(double);
  if (reuse && reuse->len && reuse->n == n && std::memcmp(reuse->v.data(), a.data(), bytes) == 0) {
    std::memcpy(p, reuse->text, reuse->len);
    if (save && save != reuse) {
      save->n = n;
      save->v = a;
      save->len = reuse->len;
      std::memcpy(save->text, reuse->text, reuse->len);
    }
    return p + reuse->len;
  }
  char* start = p;
  *p++ = '[';
  for (int k = 0; k < n; ++k) {
    if (k) *p++ = ',';
    p = formatDouble(p, a[static_cast<size_t>(k)]);
  }
  *p++ = ']';
  if (save) {
    save->n = n;
    save->v = a;
    save->len = static_cast<size_t>(p - start);
    std::memcpy(save->text, start, save->len);
  }
  return p;
}

int TraceWriter::reportedAxes() const { return axes_ < 3 ? 3 : (axes_ > kMaxAxes ? kMaxAxes : axes_); }

void TraceWriter::axes(const char* key, const AxisArray& a) {
  char tmp[16 + kMaxAxes * (kNumberChars + 1)];
  buf_.append(tmp, static_cast<size_t>(putAxes(tmp, key, a.data(), reportedAxes()) - tmp));
}

void TraceWriter::string(std::string_view s) { escapeInto(buf_, s); }

void TraceWriter::onMove(const MoveEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  // The head holds the file and program names, whatever their length; everything after it
  // has a bounded size: six axis arrays, the centre, the path points and a few numbers, each
  // at most kNumberChars long.
  const size_t names =
      fileName(e.at.file).size() + (e.at.programName ? programName(*e.at.programName).size() : 0);
  if (names > 2048) {
    begin("move", e.at);  // very long names: the general (slower) way
  } else {
    char head[2048 + 128];
    buf_.append(head, static_cast<size_t>(moveHead(head, e.at) - head));
  }
  char tmp[4096];
  char* p = put(tmp, ",\"mode\":\"");
  std::string_view mode = moveModeName(e.mode);
  std::memcpy(p, mode.data(), mode.size());
  p += mode.size();
  *p++ = '"';
  const int n = reportedAxes();
  p = putAxesCached(p, "start", e.start, n, &lastEnd_, nullptr);
  p = putAxesCached(p, "end", e.end, n, nullptr, &lastEnd_);
  p = putAxesCached(p, "mstart", e.mstart, n, &lastMend_, nullptr);
  // Without offsets the machine end is the work end: the same text again.
  p = putAxesCached(p, "mend", e.mend, n, &lastEnd_, &lastMend_);
  p = formatDouble(put(p, ",\"feed\":"), e.feed);
  p = formatDouble(put(p, ",\"length\":"), e.length);
  p = put(p, ",\"time\":");
  char* timeText = p;
  p = formatDouble(p, e.time);
  const size_t timeLen = static_cast<size_t>(p - timeText);
  p = put(p, ",\"time_simple\":");
  const double simple = e.timeSimple >= 0 ? e.timeSimple : e.time;
  if (std::memcmp(&simple, &e.time, sizeof simple) == 0) {
    std::memmove(p, timeText, timeLen);  // the same double: the same text
    p += timeLen;
  } else {
    p = formatDouble(p, simple);
  }
  if (e.arc) {
    p = putAxes(p, "center", e.center.data(), 3);
    p = formatInt(put(p, ",\"plane\":"), e.plane);
  }
  if (e.compensated) p = putAxes(p, "prog_end", e.programmedEnd.data(), n);
  if (e.nose) p = putAxes(p, "nose_end", e.noseEnd.data(), n);
  if (e.thread) p = put(p, ",\"thread\":true");
  if (e.pathPoints > 0) {
    p = put(p, ",\"path\":[");
    for (int k = 0; k < e.pathPoints && k < kMaxAxes; ++k) {
      if (k) *p++ = ',';
      const AxisArray& q = e.path[static_cast<size_t>(k)];
      *p++ = '[';
      p = formatDouble(p, q[0]);
      *p++ = ',';
      p = formatDouble(p, q[1]);
      *p++ = ',';
      p = formatDouble(p, q[2]);
      *p++ = ']';
    }
    *p++ = ']';
  }
  buf_.append(tmp, static_cast<size_t>(p - tmp));
  end();
}

void TraceWriter::onDwell(const DwellEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  begin("dwell", e.at);
  fmt::format_to(std::back_inserter(buf_), ",\"time\":{}", e.time);
  if (e.revolutions > 0) fmt::format_to(std::back_inserter(buf_), ",\"revolutions\":{}", e.revolutions);
  end();
}

void TraceWriter::onMessage(const MessageEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
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
  if (full_) return;  // past the limit: only the alarm line follows
  begin("tool", e.at);
  fmt::format_to(std::back_inserter(buf_), ",\"tool\":{},\"change\":{}", e.tool, e.change);
  end();
}

void TraceWriter::onSpindle(const SpindleEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  static const char* dirs[] = {"stop", "cw", "ccw", "orient"};
  begin("spindle", e.at);
  fmt::format_to(std::back_inserter(buf_), ",\"dir\":\"{}\",\"rpm\":{}", dirs[static_cast<int>(e.dir)], e.rpm);
  end();
}

void TraceWriter::onCoolant(const CoolantEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  static const char* states[] = {"off", "flood", "mist"};
  begin("coolant", e.at);
  fmt::format_to(std::back_inserter(buf_), ",\"state\":\"{}\"", states[static_cast<int>(e.state)]);
  end();
}

void TraceWriter::onAux(const AuxEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  begin("aux", e.at);
  fmt::format_to(std::back_inserter(buf_), ",\"letter\":\"{}\",\"code\":{}", e.letter, e.code);
  end();
}

void TraceWriter::onOffset(const OffsetEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  begin("offset", e.at);
  buf_ += ",\"kind\":";
  string(e.kind);
  buf_ += ",\"name\":";
  string(e.name);
  fmt::format_to(std::back_inserter(buf_), ",\"axis\":{},\"value\":{}", e.axis, e.value);
  end();
}

void TraceWriter::onSkip(const SkipEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  begin("skip", e.at);
  fmt::format_to(std::back_inserter(buf_), ",\"hit\":{}", e.hit);
  axes("position", e.position);
  axes("mposition", e.mposition);
  end();
}

}  // namespace ncvm
