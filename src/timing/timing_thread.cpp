#include "timing/timing_thread.hpp"

#include <algorithm>
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
// A waiting side spins this many times (a few microseconds) before it sleeps on the
// condition variable: long enough to catch the other side's next batch, short enough not
// to burn a core while the control is busy elsewhere (a long macro loop, a stock cut).
constexpr int kSpins = 256;
// The control makes its events visible to the worker in batches (one fenced store each).
constexpr uint64_t kBatch = 32;
constexpr uint64_t kWake = TimingThread::kCapacity / 4;
static_assert((TimingThread::kCapacity & (TimingThread::kCapacity - 1)) == 0, "a power of two");
static_assert(kBatch < TimingThread::kCapacity);

// The stage alone (no sink after it) reads a move's head (up to the dog-leg path) and its
// thread flag: the ring carries only those, about 300 of the event's 680 bytes. With a sink
// after the stage the whole event goes, the path only as far as it is used.
constexpr size_t kMoveHead = offsetof(MoveEvent, path);
constexpr size_t kMoveTail = offsetof(MoveEvent, thread);
static_assert(std::is_trivially_copyable_v<MoveEvent>);

inline void copyMove(MoveEvent& to, const MoveEvent& from, bool whole) {
  std::memcpy(static_cast<void*>(&to), &from, kMoveHead);
  if (whole) {
    std::memcpy(static_cast<void*>(to.path.data()), from.path.data(),
                sizeof(AxisArray) * static_cast<size_t>(std::clamp(from.pathPoints, 0, kMaxAxes)));
    std::memcpy(reinterpret_cast<char*>(&to) + kMoveTail,
                reinterpret_cast<const char*>(&from) + kMoveTail, sizeof(MoveEvent) - kMoveTail);
  } else {
    to.thread = from.thread;
    to.skip = from.skip;
    to.compensated = to.nose = false;
  }
}

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}
}  // namespace

bool TimingThread::usable(const EventSink* downstream) {
  return (!downstream || downstream->runsOnAnyThread()) && std::thread::hardware_concurrency() > 1;
}

TimingThread::TimingThread(EventSink* downstream, const SourceFiles& files)
    : downstream_(downstream),
      files_(files),
      limited_(downstream && downstream->byteHeadroom() != UINT64_MAX),
      ring_(std::make_unique<Record[]>(kCapacity)),
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
  waitHead(tail_);
  allowedSeen_ = allowed_.load(std::memory_order_acquire);
  if (failed_.load(std::memory_order_acquire) && !rethrown_) rethrowFailure();
  if (boundSum_ + bound_ <= allowedSeen_) return true;
  direct_ = true;  // from here on the stage runs on this thread, exactly as without the worker
  return false;
}

TimingThread::Record& TimingThread::claim() {
  if (tail_ - headSeen_ == kCapacity) {
    headSeen_ = head_.load(std::memory_order_acquire);
    if (tail_ - headSeen_ == kCapacity) {
      // Full: wait until half of it is free again, not for every single slot.
      publish(true);
      waitHead(tail_ - kCapacity / 2);
    }
  }
  return ring_[tail_ & (kCapacity - 1)];
}

void TimingThread::commit(Record& r) {
  r.bound = bound_;
  boundSum_ += bound_;
  ++tail_;
  if (tail_ - publishedLocal_ >= kBatch) publish();
}

// A sleeping worker is woken only once a quarter of the ring waits for it (or when the
// control must wait for it): one wake-up, a system call, per 128 events rather than per batch.
void TimingThread::publish(bool wake) {
  if (tail_ != publishedLocal_) {
    publishedLocal_ = tail_;
    published_.store(tail_);  // seq_cst: ordered before the load of workerSleeps_
  }
  if (workerSleeps_.load() && (wake || tail_ - head_.load(std::memory_order_relaxed) >= kWake)) {
    std::lock_guard<std::mutex> lock(mutex_);
    workerWake_.notify_one();
  }
}

void TimingThread::waitHead(uint64_t target) {
  for (int k = 0; k < kSpins; ++k) {
    headSeen_ = head_.load(std::memory_order_acquire);
    if (headSeen_ >= target) return;
    relax();
  }
  std::unique_lock<std::mutex> lock(mutex_);
  wantHead_.store(target, std::memory_order_relaxed);  // published by the next store
  producerSleeps_.store(true);
  producerWake_.wait(lock, [&] { return head_.load() >= target; });
  producerSleeps_.store(false, std::memory_order_relaxed);
  headSeen_ = head_.load(std::memory_order_acquire);
}

void TimingThread::onMove(const MoveEvent& e) {
  if (!admit(e.at)) return stage_->onMove(e);
  Record& r = claim();
  r.kind = Kind::Move;
  copyMove(r.move, e, downstream_ != nullptr);
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
  if (!admit(e.at)) return stage_->onSkip(e);
  Record& r = claim();
  r.kind = Kind::Skip;
  r.skip = e;
  commit(r);
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

void TimingThread::work() {
  uint64_t head = 0;
  for (;;) {
    const bool stopping = stop_.load(std::memory_order_acquire);
    uint64_t avail = published_.load(std::memory_order_acquire);
    if (avail == head) {
      if (stopping) return;
      for (int k = 0; k < kSpins && avail == head && !stop_.load(std::memory_order_relaxed); ++k) {
        relax();
        avail = published_.load(std::memory_order_acquire);
      }
      if (avail == head) {
        std::unique_lock<std::mutex> lock(mutex_);
        workerSleeps_.store(true);
        workerWake_.wait(lock, [&] { return published_.load() != head || stop_.load(); });
        workerSleeps_.store(false, std::memory_order_relaxed);
      }
      continue;
    }
    while (head < avail) {
      deliver(ring_[head & (kCapacity - 1)]);
      ++head;
      head_.store(head);  // seq_cst: ordered before the load of producerSleeps_
      if (producerSleeps_.load() && head >= wantHead_.load(std::memory_order_relaxed)) {
        std::lock_guard<std::mutex> lock(mutex_);
        producerWake_.notify_one();
      }
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
