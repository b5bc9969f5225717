#include "report/trace_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstring>

#include "core/alarm.hpp"
#include "report/json_number.hpp"

namespace ncvm {

const char* moveModeName(MoveMode m) {
  switch (m) {
    case MoveMode::Rapid:
      return "rapid";
    case MoveMode::Linear:
      return "linear";
    case MoveMode::Cw:
      return "cw";
    case MoveMode::Ccw:
      return "ccw";
  }
  return "linear";
}

namespace {

// The same program name as the last one: compared inline, as the names are short.
// Eight bytes at a time, the last (overlapping) step ending at the end; shorter names four
// (then two overlapping steps) or one at a time.
bool sameText(const std::string& x, const std::string& y) {
  const size_t n = x.size();
  if (n != y.size()) return false;
  const char* a = x.data();
  const char* b = y.data();
  auto same = [&](size_t at, auto word) {
    decltype(word) u, v;
    std::memcpy(&u, a + at, sizeof u);
    std::memcpy(&v, b + at, sizeof v);
    return u == v;
  };
  if (n >= 8) {
    for (size_t i = 0; i + 8 < n; i += 8)
      if (!same(i, uint64_t{})) return false;
    return same(n - 8, uint64_t{});
  }
  if (n >= 4) return same(0, uint32_t{}) && same(n - 4, uint32_t{});
  for (size_t i = 0; i < n; ++i)
    if (a[i] != b[i]) return false;
  return true;
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
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20)
          out += fmt::format("\\u{:04x}", static_cast<int>(c));
        else
          out += c;
    }
  }
  out += '"';
}
}  // namespace

TraceWriter::TraceWriter(const SourceFiles& files, std::FILE* out, uint64_t maxBytes, int axes)
    : files_(files), out_(out), maxBytes_(maxBytes), axes_(axes) {
  grow(out ? kChunk + kLineBytes + 2 * kCopySlack : 4096);
}

TraceWriter::~TraceWriter() {
  try {
    flush();
  } catch (...) {
  }
}

// Doubling: in memory (out == nullptr) the trace only grows; with a file, once.
void TraceWriter::grow(size_t n) {
  const size_t cap = std::max(2 * cap_, used_ + n);
  auto bigger = std::make_unique_for_overwrite<char[]>(cap);
  if (used_) std::memcpy(bigger.get(), buf_.get(), used_);  // the cached texts' offsets stay
  buf_ = std::move(bigger);
  cap_ = cap;
}

const std::string& TraceWriter::buffer() const {
  text_.assign(buf_.get(), used_);
  return text_;
}

void TraceWriter::flush() {
  if (!out_ || used_ == 0 || writeError_) return;
  if (std::fwrite(buf_.get(), 1, used_, out_) != used_) {
    writeError_ = errno ? errno : EIO;
    throw AlarmError(AlarmId::OutputError, fmt::format("trace: {}", std::strerror(writeError_)));
  }
  written_ += used_;
  used_ = 0;
  // The next lines overwrite the texts the next move could have copied.
  lastEnd_.len = 0;
  lastMend_.len = 0;
}

// The escaped names are kept with kCopySlack bytes after them, for copyText.
std::string_view TraceWriter::fileName(uint32_t id) {
  if (id < escapedNames_.size() && !escapedNames_[id].empty())  // the common case first
    return {escapedNames_[id].data(), escapedNames_[id].size() - kCopySlack};
  if (id >= escapedNames_.size()) escapedNames_.resize(id + 1);
  std::string& s = escapedNames_[id];
  if (s.empty()) {
    escapeInto(s, files_.name(id));
    s.append(kCopySlack, '\0');
  }
  return {s.data(), s.size() - kCopySlack};
}

// A program's name escaped; the same one as the event before is not escaped again.
std::string_view TraceWriter::programName(const std::string& name) {
  if (!sameText(name, lastProgram_) || lastProgramEscaped_.empty()) {
    lastProgram_ = name;
    lastProgramEscaped_.clear();
    escapeInto(lastProgramEscaped_, name);
    lastProgramEscaped_.append(kCopySlack, '\0');
  }
  return {lastProgramEscaped_.data(), lastProgramEscaped_.size() - kCopySlack};
}

void TraceWriter::begin(const char* type, const EventOrigin& at) {
  ev_.clear();
  ev_ += "{\"type\":\"";
  ev_ += type;
  ev_ += "\",\"file\":";
  ev_ += fileName(at.file);
  ev_ += ",\"line\":";
  number(static_cast<int64_t>(at.line));
  ev_ += ",\"n\":";
  if (at.n >= 0)
    number(static_cast<int64_t>(at.n));
  else
    ev_ += "null";
  ev_ += ",\"prog\":";
  if (at.programName)
    ev_ += programName(*at.programName);
  else
    ev_ += "null";
}

void TraceWriter::append(const std::string& s) {
  char* p = room(s.size());
  std::memcpy(p, s.data(), s.size());
  commit(p + s.size());
}

void TraceWriter::end() {
  ev_ += "}\n";
  append(ev_);
  checkLine();
}

void TraceWriter::checkedLine() {
  if (used_ >= kChunk && out_) flush();
  if (written_ + used_ > maxBytes_) {
    // The events the control still sends (the moves the time stage held, the alarm's
    // release of a look-ahead) would only throw again: the trace ends with the alarm.
    full_ = true;
    throw AlarmError(AlarmId::TraceLimit, fmt::format("limits.max_trace_bytes = {}", maxBytes_));
  }
}

void TraceWriter::number(double v) {
  char tmp[kNumberChars];
  ev_.append(tmp, static_cast<size_t>(formatDouble(tmp, v) - tmp));
}

void TraceWriter::number(int64_t v) {
  char tmp[kNumberChars];
  ev_.append(tmp, static_cast<size_t>(formatInt(tmp, v) - tmp));
}

namespace {
// Writers into a caller's buffer: a move is written straight into the trace's buffer.
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

namespace {
// Bit for bit: the text written for one double is the text for the same bits.
bool sameValues(const AxisArray& x, const AxisArray& y, int n) {
  uint64_t diff = 0;
  for (int k = 0; k < n; ++k)
    diff |= std::bit_cast<uint64_t>(x[static_cast<size_t>(k)]) ^
            std::bit_cast<uint64_t>(y[static_cast<size_t>(k)]);
  return diff == 0;
}

// memcpy in 16-byte steps, inline (a call to memcpy costs more than the copy of a short
// text): it may read and write up to 15 bytes past the end, which the slack after every
// text and the room after the line allow.
void copyText(char* to, const char* from, size_t len) {
  for (size_t i = 0; i < len; i += 16) std::memcpy(to + i, from + i, 16);
}
}  // namespace

// The texts of a move's head for its file and program (names of at most 2048 bytes
// together; longer ones are written by begin()).
void TraceWriter::moveOrigin(const EventOrigin& at) {
  const std::string_view file = fileName(at.file);
  const std::string_view prog =
      at.programName ? programName(*at.programName) : std::string_view("null");
  moveFile_ = at.file;
  moveHasProgram_ = at.programName != nullptr;
  moveProgram_ = at.programName ? *at.programName : std::string();
  moveLongNames_ = file.size() + prog.size() > 2048;
  moveHead_ = "{\"type\":\"move\",\"file\":";
  moveHead_ += file;
  moveHead_ += ",\"line\":";
  moveHead_.append(kCopySlack, '\0');
  for (MoveMode mode : {MoveMode::Rapid, MoveMode::Linear, MoveMode::Cw, MoveMode::Ccw}) {
    std::string& s = moveMiddle_[static_cast<int>(mode)];
    s = ",\"prog\":";
    s += prog;
    s += ",\"mode\":\"";
    s += moveModeName(mode);
    s += "\",\"start\":";
    s.append(kCopySlack, '\0');
  }
}

// Moves mostly come from consecutive lines: the last text plus one, when its last digit is
// not a 9.
char* TraceWriter::lineNumber(char* p, uint32_t line) {
  if (line == lastLine_ + 1 && lineLen_ != 0 && lineText_[lineLen_ - 1] != '9') {
    ++lineText_[lineLen_ - 1];
  } else {
    lineLen_ = static_cast<size_t>(formatInt(lineText_, static_cast<int64_t>(line)) - lineText_);
  }
  lastLine_ = line;
  copyText(p, lineText_, lineLen_);
  return p + lineLen_;
}

// The axis array ("[1.5,2,-3]"), its text taken from `reuse` when that holds the same
// values, and remembered in `save` for the next use.
inline char* TraceWriter::putAxesCached(char* p, const AxisArray& a, int n, const AxesText* reuse,
                                        AxesText* save) {
  char* const base = buf_.get();
  if (reuse && reuse->len && sameValues(reuse->v, a, n)) {
    copyText(p, base + reuse->at, reuse->len);
    if (save) {
      save->v = a;
      save->at = static_cast<size_t>(p - base);
      save->len = reuse->len;
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
    save->v = a;
    save->at = static_cast<size_t>(start - base);
    save->len = static_cast<size_t>(p - start);
  }
  return p;
}

int TraceWriter::reportedAxes() const {
  return axes_ < 3 ? 3 : (axes_ > kMaxAxes ? kMaxAxes : axes_);
}

void TraceWriter::axes(const char* key, const AxisArray& a) {
  char tmp[16 + kMaxAxes * (kNumberChars + 1)];
  ev_.append(tmp, static_cast<size_t>(putAxes(tmp, key, a.data(), reportedAxes()) - tmp));
}

void TraceWriter::string(std::string_view s) {
  escapeInto(ev_, s);
}

inline char* TraceWriter::movePositions(char* p, const MoveEvent& e, int n) {
  p = putAxesCached(p, e.start, n, &lastEnd_, nullptr);
  p = putAxesCached(put(p, ",\"end\":"), e.end, n, nullptr, &lastEnd_);
  p = putAxesCached(put(p, ",\"mstart\":"), e.mstart, n, &lastMend_, nullptr);
  // Without offsets the machine end is the work end: the same text again.
  return putAxesCached(put(p, ",\"mend\":"), e.mend, n, &lastEnd_, &lastMend_);
}

void TraceWriter::onMove(const MoveEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  const std::string* const program = e.at.programName;
  if (e.at.file != moveFile_ ||
      (program ? !moveHasProgram_ || !sameText(*program, moveProgram_) : moveHasProgram_))
    moveOrigin(e.at);
  char* p;
  if (!moveLongNames_) {
    p = room(kLineBytes + kCopySlack);
    const size_t headLen = moveHead_.size() - kCopySlack;
    copyText(p, moveHead_.data(), headLen);
    p = put(lineNumber(p + headLen, e.at.line), ",\"n\":");
    p = e.at.n >= 0 ? formatInt(p, e.at.n) : put(p, "null");
    const std::string& middle = moveMiddle_[static_cast<int>(e.mode) & 3];
    const size_t middleLen = middle.size() - kCopySlack;
    copyText(p, middle.data(), middleLen);
    p += middleLen;
  } else {  // very long names: the general (slower) way
    begin("move", e.at);
    p = room(ev_.size() + kLineBytes + kCopySlack);
    std::memcpy(p, ev_.data(), ev_.size());
    p = put(p + ev_.size(), ",\"mode\":\"");
    std::string_view mode = moveModeName(e.mode);
    std::memcpy(p, mode.data(), mode.size());
    p = put(p + mode.size(), "\",\"start\":");
  }
  const int n = reportedAxes();
  p = n == 3 ? movePositions(p, e, 3) : movePositions(p, e, n);
  // Feed, length and times with a fixed number of decimals (docs/trace-format.md).
  p = put(p, ",\"feed\":");
  if (feedLen_ == 0 || std::bit_cast<uint64_t>(e.feed) != std::bit_cast<uint64_t>(lastFeed_)) {
    lastFeed_ = e.feed;  // the feed seldom changes: its text is kept
    feedLen_ = static_cast<size_t>(formatFixed(feedText_, e.feed) - feedText_);
  }
  copyText(p, feedText_, feedLen_);
  p += feedLen_;
  p = formatFixed(put(p, ",\"length\":"), e.length);
  p = put(p, ",\"time\":");
  char* timeText = p;
  p = formatFixed(p, e.time);
  const size_t timeLen = static_cast<size_t>(p - timeText);
  p = put(p, ",\"time_simple\":");
  const double simple = e.timeSimple >= 0 ? e.timeSimple : e.time;
  if (std::bit_cast<uint64_t>(simple) == std::bit_cast<uint64_t>(e.time)) {
    copyText(p, timeText, timeLen);  // the same double: the same text
    p += timeLen;
  } else {
    p = formatFixed(p, simple);
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
  p = put(p, "}\n");
  commit(p);
  checkLine();
}

void TraceWriter::onDwell(const DwellEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  begin("dwell", e.at);
  fmt::format_to(std::back_inserter(ev_), ",\"time\":{}", e.time);
  if (e.revolutions > 0)
    fmt::format_to(std::back_inserter(ev_), ",\"revolutions\":{}", e.revolutions);
  end();
}

void TraceWriter::onMessage(const MessageEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  begin("message", e.at);
  ev_ += ",\"text\":";
  string(e.text);
  ev_ += ",\"source\":";
  string(e.source);
  end();
}

void TraceWriter::onAlarm(const AlarmEvent& e) {
  begin("alarm", e.at);
  ev_ += ",\"code\":";
  string(e.code);
  ev_ += ",\"text\":";
  string(e.text);
  ev_ += "}\n";
  append(ev_);  // no limit check: the alarm must always be written
}

void TraceWriter::onTool(const ToolEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  begin("tool", e.at);
  fmt::format_to(std::back_inserter(ev_), ",\"tool\":{},\"change\":{}", e.tool, e.change);
  end();
}

void TraceWriter::onSpindle(const SpindleEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  static const char* dirs[] = {"stop", "cw", "ccw", "orient"};
  begin("spindle", e.at);
  fmt::format_to(std::back_inserter(ev_), ",\"dir\":\"{}\",\"rpm\":{}",
                 dirs[static_cast<int>(e.dir)], e.rpm);
  end();
}

void TraceWriter::onCoolant(const CoolantEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  static const char* states[] = {"off", "flood", "mist"};
  begin("coolant", e.at);
  fmt::format_to(std::back_inserter(ev_), ",\"state\":\"{}\"", states[static_cast<int>(e.state)]);
  end();
}

void TraceWriter::onAux(const AuxEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  begin("aux", e.at);
  fmt::format_to(std::back_inserter(ev_), ",\"letter\":\"{}\",\"code\":{}", e.letter, e.code);
  end();
}

void TraceWriter::onSignal(const SignalEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  begin("signal", e.at);
  fmt::format_to(std::back_inserter(ev_), ",\"variable\":{},\"value\":{}", e.variable, e.value);
  end();
}

void TraceWriter::onOffset(const OffsetEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  begin("offset", e.at);
  ev_ += ",\"kind\":";
  string(e.kind);
  ev_ += ",\"name\":";
  string(e.name);
  fmt::format_to(std::back_inserter(ev_), ",\"axis\":{},\"value\":{}", e.axis, e.value);
  end();
}

void TraceWriter::onSkip(const SkipEvent& e) {
  if (full_) return;  // past the limit: only the alarm line follows
  begin("skip", e.at);
  fmt::format_to(std::back_inserter(ev_), ",\"hit\":{}", e.hit);
  axes("position", e.position);
  axes("mposition", e.mposition);
  end();
}

}  // namespace ncvm
