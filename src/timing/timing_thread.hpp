#pragma once
// The time stage and the sinks after it on a worker thread. The control never reads what the
// stage computes (#3001/#3002 and limits.max_time_s use the executor's own clock), so the
// stage can plan while the control interprets the next blocks: this sink copies every event
// into a bounded single-producer / single-consumer ring, and the worker hands them, in
// order, to the stage. Everything after the stage sees the same events in the same order
// with the same times as on the control's thread.
//
// How far the control runs ahead: at most kCapacity events (the ring is full: the control
// waits). A sink that throws on the worker (an I/O error) stops the control at its next
// event with that exception. A sink with a size limit (the trace) never reaches it on the
// worker: every event carries a bound of the bytes it can add, and before the bytes that the
// events in flight could add pass the sink's headroom, the control waits for the worker to
// empty the ring and goes on with the stage on its own thread (then the limit alarm comes at
// the same event, with the same outputs, as without the worker).
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "canon/events.hpp"
#include "core/source.hpp"

namespace ncvm {

class TimingStage;

class TimingThread final : public EventSink {
 public:
  static constexpr uint64_t kCapacity = 512;  // events in flight at most (a power of two)

  // downstream: the sinks after the stage (may be nullptr), asked for their headroom; files:
  // for the byte bound of an event's names. Build the stage with stageSink() as its next
  // sink, then start() the worker with it.
  TimingThread(EventSink* downstream, const SourceFiles& files);
  EventSink* stageSink();
  void start(TimingStage& stage);
  ~TimingThread() override;
  TimingThread(const TimingThread&) = delete;
  TimingThread& operator=(const TimingThread&) = delete;

  // The program ended: waits for the worker to take every event, then stops it. Afterwards
  // the stage belongs to the caller's thread again. Returns an exception a sink threw that
  // the control has not seen yet (nullptr when none).
  std::exception_ptr finish();
  // True once the events went back to the control's thread (a size limit was near).
  bool wentSynchronous() const { return direct_; }

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
  void onComment(const CommentEvent& e) override;

  // Whether a run with these sinks after the stage may use the worker at all.
  static bool usable(const EventSink* downstream);

 private:
  enum class Kind : uint8_t {
    Move,
    Dwell,
    Message,
    Alarm,
    Tool,
    Spindle,
    Coolant,
    Aux,
    Offset,
    Skip,
    Comment
  };
  // One event in the ring; the texts an event points to are copied into `text` (their
  // capacity is reused, so a full ring allocates nothing more).
  struct Record {
    Kind kind = Kind::Move;
    uint64_t bound = 0;  // trace bytes this event can add (only with a limited sink)
    MoveEvent move;
    DwellEvent dwell;
    MessageEvent message;
    AlarmEvent alarm;
    ToolEvent tool;
    SpindleEvent spindle;
    CoolantEvent coolant;
    AuxEvent aux;
    OffsetEvent offset;
    SkipEvent skip;
    CommentEvent comment;
    std::string text[2];
  };

  // Producer side (the control's thread).
  // Before each event: rethrows a sink's exception from the worker; false when the event
  // goes straight to the stage (on this thread); computes the event's byte bound.
  bool admit(const EventOrigin& at, std::string_view t0 = {}, std::string_view t1 = {});
  Record& claim();  // the next free slot (waits while the ring is full)
  // An event without texts of its own: copied whole into its slot of the record, or (when
  // admit says so) handed straight to the stage.
  template <class E>
  void queueWhole(const E& e, Kind kind, E Record::*slot, void (TimingStage::*direct)(const E&));
  void commit(Record& r);
  void publish(bool wake = false);
  void waitHead(uint64_t target);  // until the worker has taken every event before target
  void goSynchronous();
  void rethrowFailure();
  // Worker side.
  void work();
  void deliver(Record& r);
  void account(const Record& r);

  // Between the stage and the downstream sinks when they have a limit: counts what the stage
  // has passed on (the events it still holds are the ones it was given and has not).
  class Counter final : public EventSink {
   public:
    explicit Counter(EventSink* next) : next_(next) {}
    uint64_t count = 0;
    void onMove(const MoveEvent& e) override { ++count, next_->onMove(e); }
    void onDwell(const DwellEvent& e) override { ++count, next_->onDwell(e); }
    void onMessage(const MessageEvent& e) override { ++count, next_->onMessage(e); }
    void onAlarm(const AlarmEvent& e) override { ++count, next_->onAlarm(e); }
    void onTool(const ToolEvent& e) override { ++count, next_->onTool(e); }
    void onSpindle(const SpindleEvent& e) override { ++count, next_->onSpindle(e); }
    void onCoolant(const CoolantEvent& e) override { ++count, next_->onCoolant(e); }
    void onAux(const AuxEvent& e) override { ++count, next_->onAux(e); }
    void onOffset(const OffsetEvent& e) override { ++count, next_->onOffset(e); }
    void onSkip(const SkipEvent& e) override { ++count, next_->onSkip(e); }
    void onComment(const CommentEvent& e) override { ++count, next_->onComment(e); }

   private:
    EventSink* next_;
  };

  TimingStage* stage_ = nullptr;
  EventSink* downstream_;
  const SourceFiles& files_;
  const bool limited_;  // a sink after the stage has a size limit: events carry bounds
  std::unique_ptr<Record[]> ring_;
  bool direct_ = false;  // the stage runs on this thread again (never goes back)
  bool finished_ = false;
  bool rethrown_ = false;

  // Producer-only counters.
  uint64_t tail_ = 0;            // events written
  uint64_t publishedLocal_ = 0;  // the last tail_ published
  uint64_t bound_ = 0;           // the bound of the event being sent
  uint64_t headSeen_ = 0;        // the worker's head as last read
  uint64_t boundSum_ = 0;        // sum of the bounds of the events written
  uint64_t allowedSeen_ = 0;     // allowed_ as last read
  // Shared; each on its own cache line (one writer each).
  alignas(64) std::atomic<uint64_t> published_{0};  // producer: events the worker may take
  alignas(64) std::atomic<uint64_t> head_{0};       // worker: events taken and delivered
  // Worker: the bound sum up to which events are surely within the sinks' headroom.
  alignas(64) std::atomic<uint64_t> allowed_{0};
  alignas(64) std::atomic<bool> failed_{false};
  std::atomic<bool> stop_{false};
  std::atomic<bool> workerSleeps_{false}, producerSleeps_{false};
  std::atomic<uint64_t> wantHead_{0};  // what a sleeping control waits for
  std::exception_ptr error_;           // written by the worker before failed_
  std::mutex mutex_;
  std::condition_variable workerWake_, producerWake_;

  // Worker-only state for the bound bookkeeping.
  Counter counter_;
  uint64_t inputs_ = 0, maxBound_ = 0, workerBoundSum_ = 0;

  std::thread thread_;  // last: started when everything above is ready
};

}  // namespace ncvm
