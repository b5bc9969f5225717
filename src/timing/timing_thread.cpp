#include "timing/timing_thread.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstddef>
#include <cstring>
#include <type_traits>

#include "report/trace_writer.hpp"
#include "timing/timing_stage.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace ncvm {

namespace {
// A waiting side spins (pause, checking the other side's counter) for a few microseconds
// before it sleeps on the condition variable. The worker sleeps with a timeout (kNap): it
// wakes by itself and takes what the control wrote meanwhile, so the control never pays a
// wake-up (a system call, several microseconds) while it streams moves; it wakes the worker
// only when half of the stream or of the slots waits (or when it must wait itself), and at
// the end. Neither side burns a core while the other is busy elsewhere (a long macro loop,
// a stock cut, other jobs on the machine).
constexpr auto kSpin = std::chrono::microseconds(4);
constexpr auto kNap = std::chrono::microseconds(50);
// The control makes its records visible to the worker in batches (one fenced store each):
// every kBatch words (about 25 compact moves) or kSlotBatch slots. Each publication costs
// the control a cache miss (the worker polls the counter), so not more often.
constexpr uint64_t kBatch = 512;
constexpr uint64_t kSlotBatch = 32;
// The worker tells the control how far it is every kHeadBatch words (and when it is idle).
constexpr uint64_t kHeadBatch = 1024;
static_assert((TimingThread::kWords & (TimingThread::kWords - 1)) == 0, "a power of two");
static_assert((TimingThread::kSlots & (TimingThread::kSlots - 1)) == 0, "a power of two");
static_assert(kBatch <= TimingThread::kWords / 4 && kSlotBatch < TimingThread::kSlots / 4);

// A stream record: its first word is the header, kind | words << 8 | flags << 16 | mode <<
// 24 | MoveEvent's exactStop, inch << 32 | thread, skip << 48 (the bools' bytes). A compact
// move then has: the origin as it is in the event (3 words), feed, length, time; start,
// end, mstart, mend (X Y Z, or all six axes); perRev, surfaceSpeed, rpmLimit (when any is
// set); the arc's centre and plane (arcs).
constexpr uint64_t kPad = 0, kCompact = 1, kSlot = 2;
constexpr uint64_t fSix = 1;   // the axes arrays have six values (an A, B or C is not +0.0)
constexpr uint64_t fSpin = 2;  // perRev, surfaceSpeed, rpmLimit follow
constexpr uint64_t fArc = 4;   // centre and plane follow
constexpr uint64_t kMaxCompact = 7 + 4 * kMaxAxes + 3 + 4;

inline uint64_t bits(double d) {
  return std::bit_cast<uint64_t>(d);
}
inline double real(uint64_t w) {
  return std::bit_cast<double>(w);
}
template <class T>
inline uint64_t word(const T& v) {
  static_assert(sizeof(T) <= sizeof(uint64_t));
  uint64_t w = 0;
  std::memcpy(&w, &v, sizeof(T));
  return w;
}

// The event's start, end, mstart and mend, one after the other (copied as one block).
constexpr size_t kAxesAt = offsetof(MoveEvent, start);
static_assert(offsetof(MoveEvent, end) == kAxesAt + sizeof(AxisArray) &&
              offsetof(MoveEvent, mstart) == kAxesAt + 2 * sizeof(AxisArray) &&
              offsetof(MoveEvent, mend) == kAxesAt + 3 * sizeof(AxisArray));
static_assert(offsetof(MoveEvent, length) == offsetof(MoveEvent, feed) + sizeof(double) &&
              offsetof(MoveEvent, time) == offsetof(MoveEvent, feed) + 2 * sizeof(double));
static_assert(offsetof(MoveEvent, inch) == offsetof(MoveEvent, exactStop) + 1 &&
              offsetof(MoveEvent, skip) == offsetof(MoveEvent, thread) + 1);
static_assert(sizeof(EventOrigin) == 3 * sizeof(uint64_t));

// The value number k of the four arrays, as bits.
inline uint64_t axisWord(const MoveEvent& e, size_t k) {
  uint64_t w;
  std::memcpy(&w, reinterpret_cast<const char*>(&e) + kAxesAt + k * sizeof(double), sizeof w);
  return w;
}
// Whether any A, B or C value of the four arrays has a bit set (-0.0 counts: the worker
// must get exactly the control's values), so the record needs six axes.
inline bool hasAbc(const MoveEvent& e) {
  return (axisWord(e, 3) | axisWord(e, 4) | axisWord(e, 5) | axisWord(e, 9) | axisWord(e, 10) |
          axisWord(e, 11) | axisWord(e, 15) | axisWord(e, 16) | axisWord(e, 17) | axisWord(e, 21) |
          axisWord(e, 22) | axisWord(e, 23)) != 0;
}

// The whole event (for the sinks after the stage), the dog-leg path only as far as it is
// used.
constexpr size_t kMoveHead = offsetof(MoveEvent, path);
constexpr size_t kMoveTail = offsetof(MoveEvent, thread);
static_assert(std::is_trivially_copyable_v<MoveEvent>);

inline void copyMove(MoveEvent& to, const MoveEvent& from) {
  std::memcpy(static_cast<void*>(&to), &from, kMoveHead);
  std::memcpy(static_cast<void*>(to.path.data()), from.path.data(),
              sizeof(AxisArray) * static_cast<size_t>(std::clamp(from.pathPoints, 0, kMaxAxes)));
  std::memcpy(reinterpret_cast<char*>(&to) + kMoveTail,
              reinterpret_cast<const char*>(&from) + kMoveTail, sizeof(MoveEvent) - kMoveTail);
}

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

// Asks for the cache line at p for writing before the control writes it, so the store does
// not wait while the line comes back from the worker's core (a hint: a no-op where the
// instruction does not exist).
inline void prefetchWrite(const void* p) {
#if defined(__x86_64__)
  asm volatile("prefetchw %0" : : "m"(*static_cast<const char*>(p)));
#else
  __builtin_prefetch(p, 1);
#endif
}

// Spins until done() or kSpin has passed; true when done.
template <class F>
bool spinUntil(F done) {
  auto until = std::chrono::steady_clock::now() + kSpin;
  for (;;) {
    for (int k = 0; k < 64; ++k) {
      if (done()) return true;
      relax();
    }
    if (std::chrono::steady_clock::now() >= until) return done();
  }
}
}  // namespace

bool TimingThread::usable(const EventSink* downstream) {
  return (!downstream || downstream->runsOnAnyThread()) && std::thread::hardware_concurrency() > 1;
}

TimingThread::TimingThread(EventSink* downstream, const SourceFiles& files)
    : downstream_(downstream),
      files_(files),
      limited_(downstream && downstream->byteHeadroom() != UINT64_MAX),
      compact_(!downstream),
      slots_(std::make_unique<Record[]>(kSlots)),
      counter_(downstream) {}

EventSink* TimingThread::stageSink() {
  return limited_ ? &counter_ : downstream_;
}

void TimingThread::start(TimingStage& stage) {
  stage_ = &stage;
  allowedSeen_ = limited_ ? downstream_->byteHeadroom() : UINT64_MAX;
  allowed_.store(allowedSeen_, std::memory_order_relaxed);
  thread_ = std::thread([this] { work(); });
}

TimingThread::~TimingThread() {
  if (!thread_.joinable()) return;
  stop_.store(true);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    workerWake_.notify_one();
  }
  thread_.join();
}

std::exception_ptr TimingThread::finish() {
  if (finished_) return nullptr;
  finished_ = true;
  if (thread_.joinable()) {
    publish(true);
    stop_.store(true);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      workerWake_.notify_one();
    }
    thread_.join();
  }
  if (error_ && !rethrown_) {
    rethrown_ = true;
    return error_;
  }
  return nullptr;
}

// ---- the control's side --------------------------------------------------------------------

void TimingThread::rethrowFailure() {
  rethrown_ = true;
  std::rethrow_exception(error_);
}

bool TimingThread::admit(const EventOrigin& at, std::string_view t0, std::string_view t1) {
  if (failed_.load(std::memory_order_acquire) && !rethrown_) rethrowFailure();
  if (direct_) return false;
  if (!limited_) return true;
  bound_ = TraceWriter::kMaxLineFixed +
           6 * (files_.name(at.file).size() + (at.programName ? at.programName->size() : 0) +
                t0.size() + t1.size());
  if (boundSum_ + bound_ <= allowedSeen_) return true;
  allowedSeen_ = allowed_.load(std::memory_order_acquire);
  if (boundSum_ + bound_ <= allowedSeen_) return true;
  // The sinks might reach their limit: let the worker take everything, then see again.
  publish(true);
  waitFor(tail_, slotTail_);
  allowedSeen_ = allowed_.load(std::memory_order_acquire);
  if (failed_.load(std::memory_order_acquire) && !rethrown_) rethrowFailure();
  if (boundSum_ + bound_ <= allowedSeen_) return true;
  direct_ = true;  // from here on the stage runs on this thread, exactly as without the worker
  return false;
}

uint64_t* TimingThread::reserve(uint64_t words) {
  uint64_t off = tail_ & (kWords - 1);
  if (off + words <= kWords && tail_ + words - headSeen_ <= kWords) [[likely]] {
    // The lines the next records go to, a few records ahead.
    prefetchWrite(&ring_[(off + 64) & (kWords - 1)]);
    prefetchWrite(&ring_[(off + 72) & (kWords - 1)]);
    return &ring_[off];
  }
  return reserveSlow(words);
}

uint64_t* TimingThread::reserveSlow(uint64_t words) {
  uint64_t off = tail_ & (kWords - 1);
  uint64_t pad = off + words > kWords ? kWords - off : 0;
  if (tail_ + pad + words - headSeen_ > kWords) {
    headSeen_ = head_.load(std::memory_order_acquire);
    if (tail_ + pad + words - headSeen_ > kWords) {
      // Full: wait until half of it is free again, not for every single record.
      publish(true);
      waitFor(tail_ + pad + words - kWords / 2, 0);
    }
  }
  if (pad) {
    ring_[off] = kPad | pad << 8;
    tail_ += pad;
    off = 0;
  }
  return &ring_[off];
}

void TimingThread::written(uint64_t words) {
  tail_ += words;
  if (tail_ - publishedLocal_ >= kBatch || slotTail_ - slotPublished_ >= kSlotBatch) {
    publish();
    if (failed_.load(std::memory_order_acquire) && !rethrown_) rethrowFailure();
  }
}

TimingThread::Record& TimingThread::claim() {
  if (slotTail_ - slotHeadSeen_ == kSlots) {
    slotHeadSeen_ = slotHead_.load(std::memory_order_acquire);
    if (slotTail_ - slotHeadSeen_ == kSlots) {
      publish(true);
      waitFor(0, slotTail_ - kSlots / 2);
    }
  }
  return slots_[slotTail_ & (kSlots - 1)];
}

void TimingThread::commit(Record& r) {
  r.bound = bound_;
  boundSum_ += bound_;
  uint64_t* w = reserve(1);
  w[0] = kSlot | uint64_t{1} << 8;
  ++slotTail_;
  written(1);
}

// A sleeping worker is woken only once half of the stream or of the slots waits for it (or
// when the control must wait for it); otherwise it wakes by itself (kNap).
void TimingThread::publish(bool wake) {
  if (tail_ != publishedLocal_) {
    publishedLocal_ = tail_;
    slotPublished_ = slotTail_;
    published_.store(tail_);  // seq_cst: ordered before the load of workerSleeps_
  }
  if (workerSleeps_.load() &&
      (wake || tail_ - head_.load(std::memory_order_relaxed) >= kWords / 2 ||
       slotTail_ - slotHead_.load(std::memory_order_relaxed) >= kSlots / 2)) {
    std::lock_guard<std::mutex> lock(mutex_);
    workerWake_.notify_one();
  }
}

void TimingThread::waitFor(uint64_t head, uint64_t slot) {
  auto done = [&] {
    headSeen_ = head_.load(std::memory_order_acquire);
    slotHeadSeen_ = slotHead_.load(std::memory_order_acquire);
    return headSeen_ >= head && slotHeadSeen_ >= slot;
  };
  if (spinUntil(done)) return;
  std::unique_lock<std::mutex> lock(mutex_);
  wantHead_.store(head, std::memory_order_relaxed);  // published by the next store
  wantSlot_.store(slot, std::memory_order_relaxed);
  producerSleeps_.store(true);
  producerWake_.wait(lock, [&] { return head_.load() >= head && slotHead_.load() >= slot; });
  producerSleeps_.store(false, std::memory_order_relaxed);
  done();
}

// Only what the stage reads: the worker rebuilds the event from it (docs/performance.md).
// On a machine without A, B and C (whose events have +0.0 there) three axes of each array.
void TimingThread::queueCompact(const MoveEvent& e) {
  uint64_t* w = reserve(kMaxCompact);
  const auto* from = reinterpret_cast<const char*>(&e);
  std::memcpy(w + 1, &e.at, sizeof(EventOrigin));
  std::memcpy(w + 4, &e.feed, 3 * sizeof(double));
  uint64_t* p = w + 7;
  uint64_t f = 0;
  if (!hasAbc(e)) [[likely]] {
    constexpr size_t kXyz = 3 * sizeof(double), kArray = sizeof(AxisArray);
    std::memcpy(p, from + kAxesAt, kXyz);
    std::memcpy(p + 3, from + kAxesAt + kArray, kXyz);
    std::memcpy(p + 6, from + kAxesAt + 2 * kArray, kXyz);
    std::memcpy(p + 9, from + kAxesAt + 3 * kArray, kXyz);
    p += 12;
  } else {
    f |= fSix;
    std::memcpy(p, from + kAxesAt, 4 * sizeof(AxisArray));
    p += 4 * kMaxAxes;
  }
  if ((bits(e.perRev) | bits(e.surfaceSpeed) | bits(e.rpmLimit)) != 0) [[unlikely]] {
    f |= fSpin;
    p[0] = bits(e.perRev), p[1] = bits(e.surfaceSpeed), p[2] = bits(e.rpmLimit);
    p += 3;
  }
  if (e.arc) {
    f |= fArc;
    p[0] = bits(e.center[0]), p[1] = bits(e.center[1]), p[2] = bits(e.center[2]);
    p[3] = static_cast<uint64_t>(static_cast<uint32_t>(e.plane));
    p += 4;
  }
  uint16_t stopInch, threadSkip;
  std::memcpy(&stopInch, &e.exactStop, 2);
  std::memcpy(&threadSkip, &e.thread, 2);
  const auto words = static_cast<uint64_t>(p - w);
  w[0] = kCompact | words << 8 | f << 16 | word(e.mode) << 24 | uint64_t{stopInch} << 32 |
         uint64_t{threadSkip} << 48;
  written(words);
}

void TimingThread::onMove(const MoveEvent& e) {
  // Nothing after the stage: the stage reads only part of the event (the worker's failure,
  // which only the stage itself could raise here, is looked at once per batch).
  if (compact_) [[likely]]
    return queueCompact(e);
  if (!admit(e.at)) return stage_->onMove(e);
  Record& r = claim();
  r.kind = Kind::Move;
  copyMove(r.move, e);
  commit(r);
}

void TimingThread::onDwell(const DwellEvent& e) {
  if (!admit(e.at)) return stage_->onDwell(e);
  Record& r = claim();
  r.kind = Kind::Dwell;
  r.dwell = e;
  commit(r);
}

void TimingThread::onMessage(const MessageEvent& e) {
  if (!admit(e.at, e.text, e.source)) return stage_->onMessage(e);
  Record& r = claim();
  r.kind = Kind::Message;
  r.text[0].assign(e.text);
  r.text[1].assign(e.source);
  r.message = MessageEvent{e.at, r.text[0], r.text[1]};
  commit(r);
}

void TimingThread::onAlarm(const AlarmEvent& e) {
  if (!admit(e.at, e.code, e.text)) return stage_->onAlarm(e);
  Record& r = claim();
  r.kind = Kind::Alarm;
  r.text[0].assign(e.code);
  r.text[1].assign(e.text);
  r.alarm = AlarmEvent{e.at, r.text[0], r.text[1]};
  commit(r);
}

template <class E>
void TimingThread::queueWhole(const E& e, Kind kind, E Record::*slot,
                              void (TimingStage::*direct)(const E&)) {
  if (!admit(e.at)) return (stage_->*direct)(e);
  Record& r = claim();
  r.kind = kind;
  r.*slot = e;
  commit(r);
}

void TimingThread::onTool(const ToolEvent& e) {
  queueWhole(e, Kind::Tool, &Record::tool, &TimingStage::onTool);
}
void TimingThread::onSpindle(const SpindleEvent& e) {
  queueWhole(e, Kind::Spindle, &Record::spindle, &TimingStage::onSpindle);
}
void TimingThread::onCoolant(const CoolantEvent& e) {
  queueWhole(e, Kind::Coolant, &Record::coolant, &TimingStage::onCoolant);
}
void TimingThread::onAux(const AuxEvent& e) {
  queueWhole(e, Kind::Aux, &Record::aux, &TimingStage::onAux);
}

void TimingThread::onOffset(const OffsetEvent& e) {
  if (!admit(e.at, e.kind, e.name)) return stage_->onOffset(e);
  Record& r = claim();
  r.kind = Kind::Offset;
  r.text[0].assign(e.kind);
  r.text[1].assign(e.name);
  r.offset = e;
  r.offset.kind = r.text[0];
  r.offset.name = r.text[1];
  commit(r);
}

void TimingThread::onSkip(const SkipEvent& e) {
  queueWhole(e, Kind::Skip, &Record::skip, &TimingStage::onSkip);
}

void TimingThread::onComment(const CommentEvent& e) {
  if (!admit(e.at, e.text)) return stage_->onComment(e);
  Record& r = claim();
  r.kind = Kind::Comment;
  r.text[0].assign(e.text);
  r.comment = CommentEvent{e.at, r.text[0]};
  commit(r);
}

// ---- the worker ----------------------------------------------------------------------------

void TimingThread::publishHead(uint64_t head, uint64_t slot) {
  slotHead_.store(slot);
  head_.store(head);  // seq_cst: ordered before the load of producerSleeps_
  if (producerSleeps_.load() && head >= wantHead_.load(std::memory_order_relaxed) &&
      slot >= wantSlot_.load(std::memory_order_relaxed)) {
    std::lock_guard<std::mutex> lock(mutex_);
    producerWake_.notify_one();
  }
}

void TimingThread::work() {
  uint64_t head = 0, slot = 0;
  for (;;) {
    const bool stopping = stop_.load(std::memory_order_acquire);
    uint64_t avail = published_.load(std::memory_order_acquire);
    if (avail == head) {
      if (stopping) return;
      if (spinUntil([&] {
            return published_.load(std::memory_order_relaxed) != head ||
                   stop_.load(std::memory_order_relaxed);
          }))
        continue;
      std::unique_lock<std::mutex> lock(mutex_);
      workerSleeps_.store(true);
      workerWake_.wait_for(lock, kNap, [&] { return published_.load() != head || stop_.load(); });
      workerSleeps_.store(false, std::memory_order_relaxed);
      continue;
    }
    uint64_t told = head, toldSlot = slot;
    while (head < avail) {
      const uint64_t* w = &ring_[head & (kWords - 1)];
      // The lines the control wrote a few records further on, fetched from its core while
      // the stage works on this one.
      __builtin_prefetch(&ring_[(head + 64) & (kWords - 1)]);
      __builtin_prefetch(&ring_[(head + 72) & (kWords - 1)]);
      const uint64_t header = w[0];
      switch (header & 0xff) {
        case kCompact:
          deliverCompact(w, header);
          break;
        case kSlot:
          deliver(slots_[slot & (kSlots - 1)]);
          ++slot;
          break;
        default:
          static_assert(kPad != kCompact && kPad != kSlot);
          break;  // kPad: the rest of the stream before its end
      }
      head += (header >> 8) & 0xff;
      if (head - told >= kHeadBatch || slot - toldSlot >= kSlotBatch) {
        publishHead(head, slot);
        told = head, toldSlot = slot;
      }
    }
    publishHead(head, slot);
  }
}

void TimingThread::deliverCompact(const uint64_t* w, uint64_t header) {
  MoveEvent& e = move_;
  auto* to = reinterpret_cast<char*>(&e);
  const uint64_t f = (header >> 16) & 0xff;
  e.mode = static_cast<MoveMode>((header >> 24) & 0xff);
  std::memcpy(static_cast<void*>(&e.at), w + 1, sizeof(EventOrigin));
  std::memcpy(&e.feed, w + 4, 3 * sizeof(double));
  const uint64_t* p = w + 7;
  // What a record leaves out is zero (or 17 for the plane); the move keeps it from the last
  // record that had it, so it is cleared only when that one did.
  if (!(f & fSix)) {
    for (AxisArray* a : {&e.start, &e.end, &e.mstart, &e.mend}) {
      std::memcpy(a->data(), p, 3 * sizeof(double));
      p += 3;
    }
    if (hadSix_) {
      for (AxisArray* a : {&e.start, &e.end, &e.mstart, &e.mend}) (*a)[3] = (*a)[4] = (*a)[5] = 0;
      hadSix_ = false;
    }
  } else {
    std::memcpy(to + kAxesAt, p, 4 * sizeof(AxisArray));
    p += 4 * kMaxAxes;
    hadSix_ = true;
  }
  if (f & fSpin) {
    e.perRev = real(p[0]), e.surfaceSpeed = real(p[1]), e.rpmLimit = real(p[2]);
    p += 3;
    hadSpin_ = true;
  } else if (hadSpin_) {
    e.perRev = e.surfaceSpeed = e.rpmLimit = 0;
    hadSpin_ = false;
  }
  e.arc = f & fArc;
  if (e.arc) {
    e.center = {real(p[0]), real(p[1]), real(p[2])};
    e.plane = static_cast<int>(static_cast<uint32_t>(p[3]));
    hadArc_ = true;
  } else if (hadArc_) {
    e.center = {};
    e.plane = 17;
    hadArc_ = false;
  }
  const auto stopInch = static_cast<uint16_t>(header >> 32),
             threadSkip = static_cast<uint16_t>(header >> 48);
  std::memcpy(&e.exactStop, &stopInch, 2);
  std::memcpy(&e.thread, &threadSkip, 2);
  try {
    stage_->onMove(e);
  } catch (...) {
    if (!error_) {
      error_ = std::current_exception();
      failed_.store(true, std::memory_order_release);
    }
  }
}

void TimingThread::deliver(Record& r) {
  try {
    switch (r.kind) {
      case Kind::Move:
        stage_->onMove(r.move);
        break;
      case Kind::Dwell:
        stage_->onDwell(r.dwell);
        break;
      case Kind::Message:
        stage_->onMessage(r.message);
        break;
      case Kind::Alarm:
        stage_->onAlarm(r.alarm);
        break;
      case Kind::Tool:
        stage_->onTool(r.tool);
        break;
      case Kind::Spindle:
        stage_->onSpindle(r.spindle);
        break;
      case Kind::Coolant:
        stage_->onCoolant(r.coolant);
        break;
      case Kind::Aux:
        stage_->onAux(r.aux);
        break;
      case Kind::Offset:
        stage_->onOffset(r.offset);
        break;
      case Kind::Skip:
        stage_->onSkip(r.skip);
        break;
      case Kind::Comment:
        stage_->onComment(r.comment);
        break;
    }
  } catch (...) {
    // The control sees it at its next event, as if the sink had thrown there; the events
    // already sent still go on (the alarm the control then raises among them), as they do
    // after a sink's exception on the control's thread.
    if (!error_) {
      error_ = std::current_exception();
      failed_.store(true, std::memory_order_release);
    }
  }
  if (limited_) account(r);
}

// After each event: the bound sum up to which the control may send more. The events the
// stage holds can each add at most the largest bound seen so far; the ones after them add at
// most their own bounds; together they must stay within the sinks' headroom.
void TimingThread::account(const Record& r) {
  ++inputs_;
  workerBoundSum_ += r.bound;
  maxBound_ = std::max(maxBound_, r.bound);
  const uint64_t held =
      stage_->holding() && inputs_ > counter_.count ? inputs_ - counter_.count : 0;
  const uint64_t room = downstream_->byteHeadroom();
  const uint64_t reserve = held * maxBound_;
  const uint64_t extra = room > reserve ? room - reserve : 0;
  allowed_.store(extra > UINT64_MAX - workerBoundSum_ ? UINT64_MAX : workerBoundSum_ + extra,
                 std::memory_order_release);
}

}  // namespace ncvm
