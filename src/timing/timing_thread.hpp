#pragma once
// The time stage and the sinks after it on a worker thread. The control never reads what the
// stage computes (#3001/#3002 and limits.max_time_s use the executor's own clock), so the
// stage can plan while the control interprets the next blocks: this sink writes every event
// into a bounded single-producer / single-consumer stream, and the worker hands them, in
// order, to the stage. Everything after the stage sees the same events in the same order
// with the same times as on the control's thread.
//
// What crosses between the cores is what costs (each cache line the control writes is read
// on the other core): without a sink after the stage a move goes as a compact record of
// 8-byte words, only the fields the stage reads and of those only what the moves before do
// not say (move_codec.hpp: 9 words, 72 bytes, for a plain three-axis line), written one
// after the other. Every other event, and
// every move when a sink follows the stage (the trace needs the whole event), goes into a
// slot of a small side ring, and the stream carries one word saying "the next slot".
//
// How far the control runs ahead: at most kWords words of the stream and kSlots whole
// events (then the control waits). A sink that throws on the worker (an I/O error) stops
// the control at its next event with that exception. A sink with a size limit (the trace)
// never reaches it on the worker: every event carries a bound of the bytes it can add, and
// before the bytes that the events in flight could add pass the sink's headroom, the control
// waits for the worker to empty the stream and goes on with the stage on its own thread
// (then the limit alarm comes at the same event, with the same outputs, as without the
// worker).
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
#include "timing/move_codec.hpp"

namespace ncvm {

class TimingStage;

class TimingThread final : public EventSink {
 public:
  // The stream of 8-byte words (128 KB: more than the control writes while the worker naps,
  // and it stays in the cores' second-level caches) and the side ring of whole events; both
  // powers of two.
  static constexpr uint64_t kWords = 16384;
  static constexpr uint64_t kSlots = 256;

  // downstream: the sinks after the stage (may be nullptr), asked for their headroom; files:
  // for the byte bound of an event's names; abcAxes: the machine has an A, B or C axis (else
  // the compact records carry three axes). Build the stage with stageSink() as its next
  // sink, then start() the worker with it.
  TimingThread(EventSink* downstream, const SourceFiles& files, bool abcAxes = true);
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
  void onSignal(const SignalEvent& e) override;

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
    Comment,
    Signal
  };
  // One whole event in the side ring; the texts an event points to are copied into `text`
  // (their capacity is reused, so a full ring allocates nothing more).
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
    SignalEvent signal;
    std::string text[2];
  };

  // Producer side (the control's thread).
  // Before each event: rethrows a sink's exception from the worker; false when the event
  // goes straight to the stage (on this thread); computes the event's byte bound.
  bool admit(const EventOrigin& at, std::string_view t0 = {}, std::string_view t1 = {});
  // Room for a record of at most `words` words, contiguous (a record never wraps: the rest
  // of the stream before its end is skipped); waits while the stream is full.
  uint64_t* reserve(uint64_t words);
  uint64_t* reserveSlow(uint64_t words);  // the stream's end, or full
  void written(uint64_t words);           // the record reserve() returned is complete
  void queueCompact(const MoveEvent& e);
  void publishMoves();                  // a batch of compact records is complete
  void onMoveSlow(const MoveEvent& e);  // every move but the usual compact one
  Record& claim();                      // the next free slot (waits while the side ring is full)
  // An event without texts of its own: copied whole into its slot of the record, or (when
  // admit says so) handed straight to the stage.
  template <class E>
  void queueWhole(const E& e, Kind kind, E Record::*slot, void (TimingStage::*direct)(const E&));
  void commit(Record& r);
  void publish(bool wake = false);
  // Until the worker has taken the stream up to word `head` and the slots up to `slot`.
  void waitFor(uint64_t head, uint64_t slot);
  void rethrowFailure();
  // Worker side.
  void work();
  void deliverCompact(const uint64_t* w, uint64_t header);
  void deliver(Record& r);
  void account(const Record& r);
  void publishHead(uint64_t head, uint64_t slot);

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
    void onSignal(const SignalEvent& e) override { ++count, next_->onSignal(e); }

   private:
    EventSink* next_;
  };

  TimingStage* stage_ = nullptr;
  EventSink* downstream_;
  const SourceFiles& files_;
  const bool limited_;  // a sink after the stage has a size limit: events carry bounds
  const bool compact_;  // no sink after the stage: moves go as compact records
  const bool six_;      // compact records carry six axes (the machine has A, B or C)
  std::unique_ptr<Record[]> slots_;
  bool direct_ = false;  // the stage runs on this thread again (never goes back)
  bool finished_ = false;
  bool rethrown_ = false;

  // Producer-only state, on cache lines of its own: the control writes tail_ and sent_ at
  // every move, and the worker reads the fields above (stage_, six_) at every record, so
  // sharing a line would move it between the cores once a move.
  alignas(64) uint64_t tail_ = 0;  // stream words written
  uint64_t roomEnd_ = 0;           // a record fits when it ends here at most (reserveSlow)
  uint64_t publishedLocal_ = 0;    // the last tail_ published
  uint64_t headSeen_ = 0;          // the worker's head as last read
  uint64_t slotTail_ = 0;          // slots written
  uint64_t slotPublished_ = 0;     // slotTail_ when tail_ was last published
  uint64_t slotHeadSeen_ = 0;      // the worker's slot head as last read
  uint64_t bound_ = 0;             // the bound of the event being sent
  uint64_t boundSum_ = 0;          // sum of the bounds of the events written
  uint64_t allowedSeen_ = 0;       // allowed_ as last read
  movecodec::History sent_;        // what the compact records so far said

  // Shared; each group on its own cache line, written by one side only.
  alignas(64) std::atomic<uint64_t> published_{0};  // producer: stream words the worker may take
  alignas(64) std::atomic<uint64_t> head_{0};       // worker: stream words taken and delivered
  std::atomic<uint64_t> slotHead_{0};               // worker: slots delivered
  // Worker: the bound sum up to which events are surely within the sinks' headroom.
  alignas(64) std::atomic<uint64_t> allowed_{0};
  alignas(64) std::atomic<bool> workerSleeps_{false};    // worker
  alignas(64) std::atomic<bool> producerSleeps_{false};  // producer, with what it waits for
  std::atomic<uint64_t> wantHead_{0}, wantSlot_{0};
  alignas(64) std::atomic<bool> failed_{false};  // written once each
  std::atomic<bool> stop_{false};
  std::exception_ptr error_;  // written by the worker before failed_
  std::mutex mutex_;
  std::condition_variable workerWake_, producerWake_;

  // Worker-only state: the move a compact record is read into (the fields the stage does not
  // read keep their defaults), and the bound bookkeeping.
  alignas(64) MoveEvent move_;
  Counter counter_;
  uint64_t inputs_ = 0, maxBound_ = 0, workerBoundSum_ = 0;

  // The stream itself: written by the producer only, read by the worker only.
  // (Not cleared: the worker reads only words the control has published.)
  alignas(64) uint64_t ring_[kWords];

  std::thread thread_;  // last: started when everything above is ready
};

}  // namespace ncvm
