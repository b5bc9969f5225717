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

// A stream record: its first word is the header, whose low byte is the kind and the next
// one the record's length in words; a compact move is laid out as move_codec.hpp says.
constexpr uint64_t kPad = 0, kCompact = 1, kSlot = 2;

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

TimingThread::TimingThread(EventSink* downstream, const SourceFiles& files, bool abcAxes)
    : downstream_(downstream),
      files_(files),
      limited_(downstream && downstream->byteHeadroom() != UINT64_MAX),
      compact_(!downstream),
      six_(abcAxes),
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

// roomEnd_ is where the free part of the stream ends, or the stream itself (a record does
// not wrap): the lesser of the two as last computed (the worker's head only moves on, so
// an old value is too small, never too large).
inline uint64_t* TimingThread::reserve(uint64_t words) {
  if (tail_ + words <= roomEnd_) [[likely]] {
    // The line the records about 10 moves on go to (one a record: most are shorter than a
    // line).
    prefetchWrite(&ring_[(tail_ + 64) & (kWords - 1)]);
    return &ring_[tail_ & (kWords - 1)];
  }
  return reserveSlow(words);
}

uint64_t* TimingThread::reserveSlow(uint64_t words) {
  uint64_t off = tail_ & (kWords - 1);
  uint64_t pad = off + words > kWords ? kWords - off : 0;
  headSeen_ = head_.load(std::memory_order_acquire);  // roomEnd_ from a fresh head
  if (tail_ + pad + words - headSeen_ > kWords) {
    // Full: wait until half of it is free again, not for every single record.
    publish(true);
    waitFor(tail_ + pad + words - kWords / 2, 0);
  }
  if (pad) {
    ring_[off] = kPad | pad << 8;
    tail_ += pad;
    off = 0;
  }
  roomEnd_ = std::min(headSeen_ + kWords, (tail_ & ~(kWords - 1)) + kWords);
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
    // When the control must have the worker awake (it waits for it, or the run ends) the
    // store is seq_cst, ordered before the load of workerSleeps_. Otherwise a plain release
    // store: a seq_cst one is a fence that waits for every record store before it to reach
    // the cache (each line first taken back from the worker's core), once a batch; a worker
    // that falls asleep just then and is not woken wakes by itself within kNap.
    if (wake)
      published_.store(tail_);
    else
      published_.store(tail_, std::memory_order_release);
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

// Only what the stage reads, and of that only what the moves before do not say
// (move_codec.hpp); the worker rebuilds the event from it. The batch is published (and the
// worker's failure looked at: only the stage itself could raise one here) every kBatch words.
// onMove tried the usual move's test already (or found no room for it).
void TimingThread::queueCompact(const MoveEvent& e) {
  uint64_t* w = reserve(movecodec::kMaxWords);
  tail_ += six_ ? movecodec::encodeAny<kMaxAxes>(e, w, sent_, kCompact)
                : movecodec::encodeAny<3>(e, w, sent_, kCompact);
  if (tail_ - publishedLocal_ >= kBatch) publishMoves();
}

void TimingThread::publishMoves() {
  publish();
  if (failed_.load(std::memory_order_acquire) && !rethrown_) rethrowFailure();
}

// The usual move of a compact stream takes the path without calls (the others are tail
// calls), so it pays no register saves.
void TimingThread::onMove(const MoveEvent& e) {
  if (compact_ && tail_ + movecodec::kMaxWords <= roomEnd_) [[likely]] {
    uint64_t* w = &ring_[tail_ & (kWords - 1)];
    // The line the records about 10 moves on go to (one a record: most are shorter).
    prefetchWrite(&ring_[(tail_ + 64) & (kWords - 1)]);
    const uint64_t words = six_ ? movecodec::encodeUsual<kMaxAxes>(e, w, sent_)
                                : movecodec::encodeUsual<3>(e, w, sent_);
    if (words != 0) [[likely]] {
      tail_ += words;
      if (tail_ - publishedLocal_ >= kBatch) [[unlikely]]
        return publishMoves();
      return;
    }
  }
  return onMoveSlow(e);
}

void TimingThread::onMoveSlow(const MoveEvent& e) {
  if (compact_) return queueCompact(e);
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

void TimingThread::onSignal(const SignalEvent& e) {
  queueWhole(e, Kind::Signal, &Record::signal, &TimingStage::onSignal);
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

void TimingThread::deliverCompact(const uint64_t* w, uint64_t) {
  MoveEvent& e = move_;
  if (six_)
    movecodec::decode<kMaxAxes>(w, e);
  else
    movecodec::decode<3>(w, e);
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
      case Kind::Signal:
        stage_->onSignal(r.signal);
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
