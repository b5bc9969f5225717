#include "server/viewer_stream.hpp"

#include <cstring>

#include "machine/setup.hpp"
#include "report/trace_writer.hpp"

namespace ncvm::server {

namespace {

template <class T>
void put(std::string& out, const std::vector<T>& v) {
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

void putU32(std::string& out, uint32_t v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

std::string dump(const nlohmann::json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace

std::string frame(FrameKind kind, std::string_view payload) {
  static_assert(std::endian::native == std::endian::little, "the wire format is little-endian");
  std::string f;
  f.reserve(8 + payload.size() + 8);
  putU32(f, static_cast<uint32_t>(kind));
  putU32(f, static_cast<uint32_t>(payload.size()));
  f.append(payload);
  f.append((8 - payload.size() % 8) % 8, '\0');
  return f;
}

ViewerStream::ViewerStream(const SourceFiles& files, const Setup& setup, uint64_t maxNoteBytes,
                           StreamOutput out, size_t batchEvents)
    : files_(files),
      axes_(setup.reportedAxes()),
      out_(std::move(out)),
      batchEvents_(batchEvents),
      diff_(setup, true),
      unitsPerMm_(setup.initialUnit == InputUnit::Inch ? 1 / 25.4 : 1.0) {
  noteFile_ = ::open_memstream(&noteMem_, &noteSize_);
  if (!noteFile_) throw std::runtime_error("no memory for the viewer stream");
  trace_ = std::make_unique<TraceWriter>(files, noteFile_, maxNoteBytes, axes_);
  out_(frame(
      FrameKind::Hello,
      dump({{"format", "ncvm-viewer"},
            {"version", 1},
            {"axes", axes_},
            {"frame", setup.stock.frame},
            {"machine",
             {{"kind", setup.kind == MachineKind::Lathe ? "lathe" : "mill"}, {"axes", axes_}}}})));
}

ViewerStream::~ViewerStream() {
  trace_.reset();
  if (noteFile_) std::fclose(noteFile_);
  std::free(noteMem_);
}

void ViewerStream::columns(EventKind kind, uint8_t flags, const EventOrigin& at, double dt,
                           bool offsetsChanged) {
  nlohmann::json delta = diff_.next(offsetsChanged);
  if (!delta.is_null()) steps_.push_back(nlohmann::json::array({events_, std::move(delta)}));
  // #5001- is the block end and #5041- the work position, #5021- the machine position: after
  // a plain move they are its end and mend, and only otherwise sent.
  const std::vector<double>& p = diff_.positions();
  bool own = !haveLast_ || p.size() != static_cast<size_t>(3 * axes_);
  for (int a = 0; !own && a < axes_; ++a)
    own = p[static_cast<size_t>(a)] != lastEnd_[static_cast<size_t>(a)] ||
          p[static_cast<size_t>(axes_ + a)] != lastMend_[static_cast<size_t>(a)] ||
          p[static_cast<size_t>(2 * axes_ + a)] != lastEnd_[static_cast<size_t>(a)];
  if (own) {
    flags |= kOwnPositions;
    for (int k = 0; k < 3 * axes_; ++k)
      pos_.push_back(static_cast<size_t>(k) < p.size() ? p[static_cast<size_t>(k)] : 0.0);
  }
  time_.push_back(diff_.time());
  dt_.push_back(dt);
  line_.push_back(at.line);
  block_.push_back(static_cast<uint32_t>(diff_.blocks()));
  n_.push_back(at.n);
  if (at.file >= fileNames_.size()) fileNames_.resize(at.file + 1);
  if (fileNames_[at.file].empty()) fileNames_[at.file] = shown(files_.name(at.file));
  file_.push_back(static_cast<uint16_t>(std::min<uint32_t>(at.file, 65535)));
  kind_.push_back(static_cast<uint8_t>(kind));
  flags_.push_back(flags);
  ++events_;
  if (kind_.size() >= batchEvents_) flushBatch();
}

void ViewerStream::onMove(const MoveEvent& e) {
  const auto A = static_cast<size_t>(axes_);
  uint8_t flags = (e.thread ? kThread : 0) | (e.compensated || e.nose ? kCompensated : 0) |
                  (e.skip ? kProbe : 0);
  bool ownStart = !haveLast_;
  for (size_t a = 0; !ownStart && a < A; ++a) ownStart = e.start[a] != lastEnd_[a];
  if (ownStart) {
    flags |= kOwnStart;
    start_.insert(start_.end(), e.start.begin(), e.start.begin() + static_cast<long>(A));
  }
  end_.insert(end_.end(), e.end.begin(), e.end.begin() + static_cast<long>(A));
  mend_.insert(mend_.end(), e.mend.begin(), e.mend.begin() + static_cast<long>(A));
  if (e.arc) {
    flags |= kArc;
    center_.insert(center_.end(), e.center.begin(), e.center.end());
    plane_.push_back(static_cast<uint8_t>(e.plane));
  }
  feed_.push_back(static_cast<float>(e.feed));
  pathCount_.push_back(static_cast<uint16_t>(e.pathPoints));
  for (int k = 0; k < e.pathPoints; ++k)
    path_.insert(path_.end(), e.path[static_cast<size_t>(k)].begin(),
                 e.path[static_cast<size_t>(k)].begin() + static_cast<long>(A));
  lastEnd_ = e.end;
  lastMend_ = e.mend;
  haveLast_ = true;
  columns(static_cast<EventKind>(e.mode), flags, e.at, e.time, false);
}

template <class Write>
void ViewerStream::note(EventKind kind, const EventOrigin& at, double dt, bool offsetsChanged,
                        Write write) {
  notes_.push_back(events_);
  // The trace line comes first; at the trace limit its event is still recorded (as in the
  // JSON answer), then the limit alarm goes on.
  try {
    write(*trace_);
  } catch (...) {
    columns(kind, 0, at, dt, offsetsChanged);
    throw;
  }
  columns(kind, 0, at, dt, offsetsChanged);
}

void ViewerStream::onDwell(const DwellEvent& e) {
  note(EventKind::Dwell, e.at, e.time, false, [&](TraceWriter& t) { t.onDwell(e); });
}
void ViewerStream::onMessage(const MessageEvent& e) {
  note(EventKind::Message, e.at, 0, false, [&](TraceWriter& t) { t.onMessage(e); });
}
void ViewerStream::onAlarm(const AlarmEvent& e) {
  note(EventKind::Alarm, e.at, 0, false, [&](TraceWriter& t) { t.onAlarm(e); });
}
void ViewerStream::onTool(const ToolEvent& e) {
  note(EventKind::Tool, e.at, 0, false, [&](TraceWriter& t) { t.onTool(e); });
}
void ViewerStream::onSpindle(const SpindleEvent& e) {
  note(EventKind::Spindle, e.at, 0, false, [&](TraceWriter& t) { t.onSpindle(e); });
}
void ViewerStream::onCoolant(const CoolantEvent& e) {
  note(EventKind::Coolant, e.at, 0, false, [&](TraceWriter& t) { t.onCoolant(e); });
}
void ViewerStream::onAux(const AuxEvent& e) {
  note(EventKind::Aux, e.at, 0, false, [&](TraceWriter& t) { t.onAux(e); });
}
void ViewerStream::onOffset(const OffsetEvent& e) {
  note(EventKind::Offset, e.at, 0, true, [&](TraceWriter& t) { t.onOffset(e); });
}
void ViewerStream::onSkip(const SkipEvent& e) {
  note(EventKind::Skip, e.at, 0, false, [&](TraceWriter& t) { t.onSkip(e); });
}

void ViewerStream::onWorkOrigin(const WorkOriginEvent& e) {
  origins_.push_back(nlohmann::json::array(
      {events_, e.mm[0] * unitsPerMm_, e.mm[1] * unitsPerMm_, e.mm[2] * unitsPerMm_}));
}

void ViewerStream::flushBatch() {
  if (kind_.empty() && origins_.empty()) return;
  if (!origins_.empty()) {
    out_(frame(FrameKind::Origins, dump({{"origins", origins_}})));
    origins_ = nlohmann::json::array();
  }
  if (kind_.empty()) return;
  std::string p;
  const uint32_t counts[kBatchHeader] = {
      static_cast<uint32_t>(kind_.size()),
      static_cast<uint32_t>(end_.size() / static_cast<size_t>(axes_)),
      static_cast<uint32_t>(start_.size() / static_cast<size_t>(axes_)),
      static_cast<uint32_t>(pos_.size() / static_cast<size_t>(3 * axes_)),
      static_cast<uint32_t>(plane_.size()),
      static_cast<uint32_t>(path_.size() / static_cast<size_t>(axes_)),
      static_cast<uint32_t>(axes_),
      0};
  p.append(reinterpret_cast<const char*>(counts), sizeof counts);
  put(p, time_), put(p, pos_), put(p, start_), put(p, end_), put(p, mend_), put(p, center_);
  put(p, path_), put(p, dt_);
  put(p, feed_);
  put(p, line_), put(p, block_), put(p, n_);
  put(p, file_), put(p, pathCount_);
  put(p, kind_), put(p, flags_), put(p, plane_);
  out_(frame(FrameKind::Events, p));
  for (auto* v : {&time_, &pos_, &start_, &end_, &mend_, &center_, &path_, &dt_}) v->clear();
  feed_.clear(), line_.clear(), block_.clear(), n_.clear();
  file_.clear(), pathCount_.clear(), kind_.clear(), flags_.clear(), plane_.clear();

  trace_->flush();
  std::fflush(noteFile_);
  if (!steps_.empty() || !notes_.empty()) {
    out_(frame(FrameKind::Steps, shown(dump({{"steps", steps_}, {"notes", notes_}}))));
    steps_ = nlohmann::json::array();
    notes_ = nlohmann::json::array();
  }
  if (noteSize_ > noteSent_) {
    out_(frame(FrameKind::Notes, shown(std::string(noteMem_ + noteSent_, noteSize_ - noteSent_))));
    noteSent_ = noteSize_;
  }
}

void ViewerStream::finish(nlohmann::json tail) {
  flushBatch();
  tail["files"] = fileNames_;
  tail["events"] = events_;
  out_(frame(FrameKind::End, dump(tail)));
}

}  // namespace ncvm::server
