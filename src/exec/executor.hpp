#pragma once
// The control: runs compiled programs block by block in Fanuc order and emits canonical
// events. Jobs are split by file: executor.cpp (run loop, flow, calls), eval.cpp
// (expressions), macro_variables.hpp (the component that owns #0-#999), variables.cpp (the
// system variables), block_words.cpp (a block's words and the calls they make), nc_block.cpp
// (modal state, M/S/T, the order of a block), motion.cpp (positions and moves),
// reference_return.cpp (G27-G30, G53), print.cpp (DPRNT/BPRNT). docs/architecture.md maps
// the components.
#include <array>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "canon/events.hpp"
#include "core/alarm.hpp"
#include "core/value.hpp"
#include "exec/gcode_table.hpp"
#include "exec/interface_signals.hpp"
#include "exec/macro_variables.hpp"
#include "exec/modal_state.hpp"
#include "lang/ir.hpp"
#include "lang/program_store.hpp"
#include "machine/offsets.hpp"
#include "machine/setup.hpp"
#include "motion/cutter_comp.hpp"
#include "motion/lathe_cycles.hpp"
#include "motion/transform.hpp"
#include "sim/probe_world.hpp"

namespace ncvm {

struct Words;

enum class EndReason : uint8_t { M30, M02, M99, Alarm, Eof, Limit };
const char* endReasonName(EndReason r);

struct Warning {
  std::string code;  // "W001"
  std::string text;
  SourceLoc loc;
};

struct RunStats {
  uint64_t blocks = 0;
  uint64_t moves = 0;
  double rapidLength = 0, feedLength = 0;  // program units
  double time = 0;                         // seconds, simple model
};

class Executor {
 public:
  Executor(const Setup& setup, ProgramStore& store, EventSink& sink);
  ~Executor();

  // Runs `main` to its end. Alarms end the run; they are returned, not thrown.
  EndReason run(const Program& main);

  // Everything a report needs after the run.
  const std::optional<Alarm>& alarm() const { return alarm_; }
  const RunStats& stats() const { return stats_; }
  const ModalState& modal() const { return modal_; }
  const std::vector<Warning>& warnings() const { return warnings_; }
  const Setup& setup() const { return setup_; }
  AxisArray workPosition() const;     // program units, lathe X as diameter
  AxisArray machinePosition() const;  // program units
  // Non-vacant level-0 locals and common variables, for the state file.
  std::vector<std::pair<int, double>> userVariables() const;
  // The interface signal outputs as the program left them: 0 = UO000-UO031, 1 = UO100-UO131.
  uint32_t signalOutputs(int word) const { return signals_.outputs(word); }
  // #1-#33 of the current call level and #100-#199, as readVar gives them: the web viewer
  // compares them after every event (src/server/state_diff.cpp), where 133 calls would cost.
  const std::array<Value, 33>& currentLocals() const {
    return vars_.locals(frames_.empty() ? 0 : frames_.back().level);
  }
  const std::array<Value, 100>& common100() const { return vars_.common100(); }
  // The control's persistent memory (offsets, #500-#999, part counters). Replace it before
  // run() to start from a saved machine state; read it after run() to save one.
  MachineMemory& memory() { return mem_; }
  const MachineMemory& memory() const { return mem_; }
  // Offsets in the setup's units (mm or inch; lathe X as a diameter), for reports.
  AxisArray workOffsetValues(int index) const;
  // Call after replacing memory() so the current offsets follow it.
  void restartFromMemory();
  // What DPRNT/BPRNT wrote; the caller saves it (atomically) where the setup says.
  const std::string& printed() const { return printed_; }
  // G31 also touches `world` (the simulated stock, probe.use_stock; machine mm, not owned);
  // with [[solids]] too, the first contact of either counts.
  void setStockProbe(const ProbeWorld* world) { stockProbe_ = world; }
  // Machine position (mm, X Y Z; lathe X as a radius) of the active work system's origin:
  // work offset, EXT, G52 and G92 shifts, without the tool offset. A tool tip at machine
  // position P is at work position P - this.
  Vec3 workOriginMm() const;

 private:
  friend struct ExecutorAccess;  // unit tests
  // ---- configuration ----
  const Setup& setup_;
  ProgramStore& store_;
  EventSink& realSink_;
  // Events go to the caller's sink, or are deferred while cutter compensation holds blocks.
  EventSink& sink();
  Series series_;
  bool lathe_;
  bool dpi_;
  std::array<const GCodeInfo*, 1000> gInfo_{};  // by G code x10
  const GCodeInfo* gInfo(int code10) const {
    return code10 >= 0 && code10 < 1000 ? gInfo_[static_cast<size_t>(code10)] : nullptr;
  }
  std::array<int64_t, kMaxAxes> nmPerIncMm_{}, nmPerIncInch_{};
  // Parameter-driven calls, looked up once: program number by G code (x1) / M code.
  std::array<int16_t, 1000> gCall_{};
  std::array<int16_t, 1000> mMacroCall_{}, mSubCall_{};
  bool nat_ = false, lrp_ = false, tcs_ = false;
  double arcTolerance_ = 0.01;

  // ---- call stack ----
  enum class FrameKind : uint8_t { Main, Sub, Macro, ModalMacro };
  struct Frame {
    const Program* prog = nullptr;
    uint32_t pc = 0;
    FrameKind kind = FrameKind::Main;
    int32_t repeatsLeft = 0;
    int8_t level = 0;         // local variable level
    bool codeCalled = false;  // entered through a G/M/T code call
    int16_t modalFloor = 0;   // G66 entries at or above this index may trigger here
    uint32_t startPc = 0;     // where a repeat (L) starts again: M98 Q's block, else 0
  };
  std::vector<Frame> frames_;
  int macroDepth_ = 0, subDepth_ = 0;

  // ---- variables ----
  // #0-#999 are the MacroVariables component's (vars_, below); the system variables keep
  // their state here.
  int localLevel() const { return frames_.empty() ? 0 : frames_.back().level; }
  double timerMsOffset_ = 0, timerHourOffset_ = 0;
  InterfaceSignals signals_{setup_.signals};  // #1000-#1032, #1100-#1133
  std::array<Value, 64> evalStack_{};
  double sys3003_ = 0, sys3004_ = 0, sys3005_ = 0;

  // ---- modal calls (G66) ----
  struct ModalCall {
    const Program* prog = nullptr;
    int32_t repeats = 1;
    std::array<Value, 33> args{};
    std::array<double, 33> scale{};
  };
  std::vector<ModalCall> modalCalls_;

  // ---- machine state ----
  ModalState modal_;
  std::array<int64_t, kMaxAxes> machine_{};  // nm / micro-degree, physical (lathe X radius)
  std::array<int64_t, kMaxAxes> offset_{};   // machine = work + offset_ (sum of the below)
  MachineMemory mem_;
  // #0-#999 (macro_variables.hpp); declared after mem_, whose #500-#999 it keeps.
  MacroVariables vars_{mem_.common500, setup_.commonVars200};
  int workIndex_ = kWorkG54;                     // selected work offset table
  std::array<int64_t, kMaxAxes> g52_{}, g92_{};  // local system and G92/G50 shift
  std::array<int64_t, kMaxAxes> toolShift_{};    // tool length (mill) or tool offset (lathe)
  std::array<int64_t, 3> originSent_{};          // the work origin last sent (WorkOriginEvent)
  bool originKnown_ = false;                     // one has been sent
  std::unique_ptr<SolidWorld> probeWorld_;
  const ProbeWorld* stockProbe_ = nullptr;
  std::string eventName_;                       // storage behind OffsetEvent::name
  std::array<int64_t, kMaxAxes> programmed_{};  // work position of the last block end (#5001)
  std::array<int64_t, kMaxAxes> skip_{};
  std::array<int64_t, kMaxAxes> g28Mid_{};
  bool g28MidSet_ = false;
  bool spindleOn_ = false;
  SpindleDir spindleDir_ = SpindleDir::Cw;
  int32_t lastN_ = 0;  // #4114: the last sequence number read
  double rpm_ = 0;
  double spindleClamp_ = 0;  // G50/G92 S (lathe), 0 = none
  bool warnedRevFeed_ = false;
  bool exactStop_ = false;  // G09 in this block or G61 modal: MoveEvent::exactStop

  // ---- run ----
  const Block* block_ = nullptr;
  void wholeProgram(const Program& p);  // a streamed program compiled whole (executor.cpp)
  std::optional<Alarm> alarm_;
  RunStats stats_;
  std::vector<Warning> warnings_;
  double simTime_ = 0;
  EventOrigin origin_;
  std::string printed_;

  // executor.cpp
  void enter(const Program* p, FrameKind kind, int repeats, bool codeCalled);
  bool step();  // one block; false when the run ends
  // step() for the plain blocks after a straight move, as long as the straight path takes
  // them: the same bookkeeping per block, no second modal test (a straight block changes
  // nothing it reads). A plain block it refuses runs the general way and ends the run; so does
  // any other block (step() runs it). False when the program ended.
  bool straightRun();
  [[noreturn]] void blockLimitAlarm() const;
  [[noreturn]] void timeLimitAlarm() const;
  void jumpTo(int32_t label, bool computed);
  // The DO/END or literal GOTO error the compiler found in block `k` of `p` (nullptr: none):
  // the control finds it when the block runs, so it is raised then (fanuc-decisions.md).
  const Alarm* structuralError(const Program& p, uint32_t k);
  [[noreturn]] static void raiseStructural(const Alarm& a);
  std::unordered_map<const Program*, std::vector<std::pair<uint32_t, uint32_t>>> structuralAt_;
  void doReturn(int32_t label);  // M99 [P]
  // startLabel >= 0: M98 Q, the subprogram runs from sequence number startLabel.
  void callSub(const Program* p, int repeats, bool codeCalled, int32_t startLabel = -1);
  void callMacro(const Program* p, int repeats, const std::array<Value, 33>& args,
                 const std::array<double, 33>& scale, FrameKind kind, bool codeCalled);
  const Program* findProgram(int32_t number, int32_t nameIdx);
  EndReason endReason_ = EndReason::Eof;
  bool ended_ = false;
  void warn(const char* code, std::string text);

  // eval.cpp
  Value eval(int32_t expr);
  // An expression in the NC address `letter`: ROUND in it rounds to that address's least
  // input increment instead of to a whole number.
  Value evalAddress(int32_t expr, char letter);
  double roundPerUnit_ = 1;  // ROUND's steps per unit: 1 in a macro statement
  // Significant decimal digits of every macro value and result (16i class: 8), 0 = double.
  int macroDigits_ = 0;
  // Inline so the default (doubles) costs one test per value on the macro hot path.
  Value macroPrecision(Value v) const { return macroDigits_ ? roundedToMacroDigits(v) : v; }
  Value roundedToMacroDigits(Value v) const;
  bool evalCond(int32_t expr);
  double callFn(Fn fn, double a, double b, int32_t arg);

  // variables.cpp
 public:
  Value readVar(int64_t n);
  void writeVar(int64_t n, Value v);

 private:
  Value readSystem(int64_t n);
  void writeSystem(int64_t n, Value v);
  int axisByNumber(int n) const;  // 1-based controlled axis -> slot, -1 if none

  // nc_block.cpp
  // An NC block the straight path (straightMove) did not take.
  void execNcGeneral(const Block& b);
  bool plainMotion(Words& w);  // execNcGeneral's fast path for plain G00-G03 blocks
  void gatherWords(const Block& b, Words& w);
  void gatherPlainWords(const Block& b, Words& w) const;   // a kPlainBlock block's words
  void checkDigits(const Word& wd, bool macroCall) const;  // PS0003 for a kLongNumber word
  bool codeCall(const Block& b, Words& w);
  void buildArgs(const Words& w, int callingM, std::array<Value, 33>& args,
                 std::array<double, 33>& scale) const;
  void macroCallFromWords(const Program* p, int repeats, const Words& w, FrameKind kind,
                          bool codeCalled, int callingM = -1);
  void applyModalG(int code10, const GCodeInfo& info);
  void deriveModal();
  void auxFunctions(Words& w);
  void programControl(Words& w, bool moved);

  // motion.cpp
  int64_t lengthNm(double v, bool point, int slot) const;
  static constexpr int64_t kMaxTravelNm = int64_t{2'000'000'000'000'000'000};
  // Increments to nanometres; PS0003 past kMaxTravelNm (motion.cpp says why).
  static int64_t checkedNm(int64_t increments, int64_t nmPerIncrement) {
    int64_t nm = 0;
    if (__builtin_mul_overflow(increments, nmPerIncrement, &nm) || nm > kMaxTravelNm ||
        nm < -kMaxTravelNm) [[unlikely]]
      travelAlarm();
    return nm;
  }
  [[noreturn, gnu::cold]] static void travelAlarm();
  double toProgramUnits(int64_t nm, int slot, bool diameter) const;
  // Targets of the block's axis words; incremental words count from `base` (default: the
  // current work position).
  bool axisTargets(const Words& w, std::array<int64_t, kMaxAxes>& target, uint32_t& axesMask,
                   const std::array<int64_t, kMaxAxes>* base = nullptr);
  void polarTargets(const Words& w, std::array<int64_t, kMaxAxes>& target, uint32_t& axesMask,
                    const std::array<int64_t, kMaxAxes>* base);
  bool plainTargets(const Words& w, std::array<int64_t, kMaxAxes>& target, uint32_t& axesMask);
  void moveTo(const std::array<int64_t, kMaxAxes>& targetWork, MoveMode mode, uint32_t axesMask);
  void arcTo(const std::array<int64_t, kMaxAxes>& targetWork, const Words& w, bool cw);
  // G02/G03 in effect and the block is an arc: with neither R nor I/J/K it is a line
  // unless parameter 3403#5 (CIR) asks for PS0022.
  bool arcBlock(const Words& w) const;
  void arcWithCenter(const std::array<int64_t, kMaxAxes>& targetWork, double cu, double cv,
                     bool cw);
  void rapidMachine(const std::array<int64_t, kMaxAxes>& targetMachine, uint32_t axesMask);
  void emitMove(MoveEvent& e, const std::array<int64_t, kMaxAxes>& fromMachine,
                const std::array<int64_t, kMaxAxes>& toMachine);
  // The end of the last move emitMove converted, reused as the next move's start.
  struct LastEmit {
    bool valid = false, inch = false;
    std::array<int64_t, kMaxAxes> toMachine{}, offset{};
    AxisArray mend{}, end{};
  };
  LastEmit lastEmit_;
  // The straight path for plain G00/G01 blocks and G17 arcs (straight_move.cpp) and what it
  // keeps between blocks: the stroke limits as nanometre bounds per unit (the same test as
  // checkStroke's) and the one event it fills in place.
  // modalChecked: the block before was a straight move (straightRun), so the modal state
  // still passes the test (a straight block changes only its motion group, feed and position).
  bool straightMove(const Block& b, bool modalChecked = false);
  // What straightMove read of the block's words: literal values, or those of #variables and
  // expressions as gatherWords reads them (a vacant variable drops its word; a value counts
  // as written with a decimal point).
  struct StraightWords {
    struct Number {
      double v = 0;
      bool given = false, point = false;
    };
    int code = -1, motion = 10;  // G code x10 in the block (-1: none); the motion it gives
    const GCodeInfo* info = nullptr;
    Number axis[3];  // X Y Z
    Number feed, i, j, r;
  };
  // gatherWords for a block that is not kPlainBlock but could be one with its variables read:
  // false, having read nothing, for any other block.
  bool straightVariableWords(const Block& b, const Word* words, StraightWords& w);
  static StraightWords::Number* numberFor(StraightWords& w, char letter);
  template <bool Arc, bool Rapid>
  bool straightBlock(const StraightWords& w);
  // A G00's time, feed, length and dog-leg corners as rapidMachine computes them (X Y Z only).
  void straightRapid(MoveEvent& e, const int64_t* fromM, const int64_t* toM, const double* dist,
                     double sq, bool inch);
  // Per unit (mm, inch), each axis's constants as lengthNm, toProgramUnits and emitMove use
  // them, and its stroke limits as nanometre bounds (the same test as checkStroke's).
  struct StraightAxes {
    bool valid = false;
    struct Axis {
      bool present = false, diameter = false;
      int64_t perIncrement = 0, nmPerIncrement = 0, lo = 0, hi = 0;
      double per = 1, dia = 1;
    };
    std::array<Axis, kMaxAxes> axis{};
  };
  const StraightAxes& straightAxes(bool inch) {
    const StraightAxes& t = straightAxes_[inch ? 1 : 0];
    return t.valid ? t : fillStraightAxes(inch);
  }
  const StraightAxes& fillStraightAxes(bool inch);
  std::array<StraightAxes, 2> straightAxes_{};
  MoveEvent straight_;
  // Where the axes after Z were (and their offsets, the unit) when straight_ and lastEmit_'s
  // slots for them were last filled; lastEmitTail_ is cleared when emitMove writes lastEmit_.
  struct StraightTail {
    bool valid = false, inch = false;
    std::array<int64_t, kMaxAxes - 3> machine{}, offset{};
  };
  StraightTail straightTail_;
  bool lastEmitTail_ = false;
  double effectiveFeed();
  void dwell(const Words& w);
  void referenceReturn(const Words& w, int which);
  void referencePositionCheck(const Words& w);
  int64_t referenceNm(size_t axis, int which) const;
  void returnFromReference(const Words& w);
  void machinePositioning(const Words& w);
  void advanceTime(double seconds);

  // coords.cpp
  void initMemoryFromSetup();
  void recomputeOffset();
  int64_t offsetNm(double v, bool point, int slot) const;  // offset value -> nm (radius)
  void writeWorkOffset(int index, int slot, int64_t nm, bool add);
  void writeToolOffset(int row, int field, bool wear, int64_t nm, bool add);
  void setTip(int row, int tip);
  void applyToolShift();
  void programmableDataInput(const Words& w);  // G10
  void localCoordinates(const Words& w);       // G52
  void coordinateSetting(const Words& w);      // G92 / lathe G50
  void coordinatePreset(const Words& w);       // G92.1: back to the work offsets
  bool offsetVariable(int64_t n, Value* read, const Value* write);
  double cssRpmAt(int64_t xMachine) const;
  void checkStroke(const std::array<int64_t, kMaxAxes>& toMachine);

  // direct_drawing.cpp: a lathe G00/G01 block with ,A gets its end point as U and W. One end
  // coordinate: the other from the start point (x radius, z in program units); the angle
  // alone: the corner with the next block's line (angleSecond_ is that block, whose ,A has
  // then been used). `diameter` is 2 when U counts a diameter.
  void directDrawingHere(Words& w);
  void directDrawing(Words& w, const lathe::Pt& start, int motion, double diameter) const;
  void directDrawingCorner(Words& w, int motion, const Words& next, int nextMotion,
                           bool nextIncremental, const lathe::Pt& start, double diameter) const;
  void shapeDirectDrawing(const Program& prog, int32_t k, int32_t last, Words& w,
                          const lathe::Pt& at, int motion, int32_t& second);
  const Block* angleSecond_ = nullptr;
  // probe.cpp
  void skipMove(const Words& w);
  // position_offset.cpp: G45-G48 (the one-shot code x10); true when the block moved
  bool toolPositionOffset(const Words& w, int code10);

  // Lathe T code: tool (geometry) number and wear offset number. Four digits Tttoo; two
  // digits T to (tool t, offset o).
  static int latheToolNumber(int t) { return t >= 100 ? t / 100 : t / 10; }
  static int latheWearNumber(int t) { return t >= 100 ? t % 100 : t % 10; }
  // The geometry row: the offset number oo like the wear (parameter 5002#1 LGN = 0, the
  // default), or the tool number tt (LGN = 1).
  int latheGeometryNumber(int t) const {
    return setup_.bit("5002#1") ? latheToolNumber(t) : latheWearNumber(t);
  }

  // drill_cycles.cpp
  struct DrillCycle {
    bool active = false;
    int axis = 2;
    int64_t initial = 0, r = 0, bottom = 0, q = 0;
    bool haveR = false, haveZ = false;
    double dwellMs = 0;
  };
  DrillCycle cycle_;
  void cancelCycle();
  bool drillCycle(const Words& w, bool cycleCommanded);
  // hole: where the tool drills (after any transform); the levels likewise.
  void drillOneHole(const std::array<int64_t, kMaxAxes>& hole, int code, int axis, int64_t initial,
                    int64_t rLevel, int64_t bottom);
  bool rigidTap_ = false;  // M29 given: the next G84/G74 (lathe G84/G88) is rigid tapping
  // lathe_drill_cycles.cpp
  bool latheDrillCycle(const Words& w, bool cycleCommanded);

  // lathe_cycle_exec.cpp
  enum LatheCycleKind {
    kNoCycle = 0,
    kTurn,
    kThread,
    kFace,
    kFinish,
    kRoughTurn,
    kRoughFace,
    kPattern,
    kFacePeck,
    kGroove,
    kMultiThread
  };
  struct LatheCycleState {
    double depth = 1.0, retract = 0.5;  // G71/G72 first block (parameters 5132/5133)
    double reliefX = 0, reliefZ = 0;    // G73 first block
    int divisions = 1;
    double taper = 0;    // G90/G92/G94 R, modal
    int singleKind = 0;  // the single cycle the modal X/Z/R belong to
    bool haveEnd = false;
    lathe::Pt lastEnd;           // G90/G92/G94 X/Z, modal
    double peckRetract = 0;      // G74/G75 first block (parameter 5139)
    lathe::ThreadParams thread;  // G76 first block
    bool paramsLoaded = false;   // the above start from parameters 5130-5143
  };
  LatheCycleState latheCyc_;
  int latheCycleKind(int code10) const;
  lathe::Pt latheHere() const;
  lathe::Pt latheTarget(const Words& w, const lathe::Pt& from) const;
  double latheLength(const Words& w, char letter, bool diameter) const;
  double latheIncrements(const Words& w, char letter) const;
  lathe::Contour readContour(int ns, int nf, std::vector<double>& feeds, uint32_t& lastBlock);
  void runLathePlan(const std::vector<lathe::Move>& moves, const std::vector<double>* contourFeeds,
                    double lead);
  bool latheCycle(const Words& w, int kind);
  void loadLatheCycleParams();

  // crc_exec.cpp: cutter compensation C
  struct DeferSink final : EventSink {
    Executor* ex;
    explicit DeferSink(Executor* e) : ex(e) {}
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
    void onWorkOrigin(const WorkOriginEvent& e) override;
    void onSignal(const SignalEvent& e) override;
  };
  struct Pending {
    int tag = -1;         // >= 0: a compensated move waiting for its path
    bool closed = false;  // its path is complete
    std::vector<crc::OutSeg> segs;
    std::function<void()> action;  // tag < 0: anything else the block did
  };
  struct CrcBlock {
    crc::P2 tip;  // lathe: imaginary tip minus nose centre (plane units) while compensated
    EventOrigin origin;
    std::array<int64_t, kMaxAxes> target{};
    double feed = 0;
    int plane = 17;
    AxisArray programmedEnd{};
    bool cornerArc = false;  // G39 before this block: its corner arc has the G39 block's line
    EventOrigin cornerOrigin;
  };
  DeferSink deferSink_{this};
  bool deferring_ = false;
  std::deque<Pending> pending_;
  std::unordered_map<int, CrcBlock> crcBlocks_;
  std::unique_ptr<crc::Compensator> crc_;
  int crcTag_ = 0;
  const AxisArray* programmedEnd_ = nullptr;  // set while emitting a compensated move
  bool threadMove_ = false;                   // set while emitting a threading move
  bool warnedNoRadius_ = false;
  void deferEvent(std::function<void(EventSink&)> replay);
  bool crcBusy() const;
  double crcRadius() const;
  void ensureCompensator();
  void crcOutput(const crc::OutSeg& s);
  void releasePending(bool all);
  void crcDrain();
  std::array<int64_t, kMaxAxes> crcTransform(crc::InSeg& s,
                                             const std::array<int64_t, kMaxAxes>& target);
  bool crcBlock(const Words& w, const std::array<int64_t, kMaxAxes>& target, uint32_t mask,
                bool arc, bool cw);
  void arcCenter(const std::array<int64_t, kMaxAxes>& startW,
                 const std::array<int64_t, kMaxAxes>& targetWork, const Words& w, bool cw,
                 double& cu, double& cv);

  bool g39Pending_ = false;  // G39 read: the next compensated block starts with a corner arc
  EventOrigin g39Origin_;
  bool g39HasDir_ = false;  // G39 I/J/K: the direction the corner arc ends perpendicular to
  crc::P2 g39Dir_;

  // transforms.cpp: G51.1 mirror, G51 scaling, G68 rotation (mill)
  xform::Transform xf_;
  double xfAngleDeg_ = 0;  // G68 R as programmed (G91 R adds to it with 5400#0)
  bool transformBlock(const Words& w, int oneShot);  // true: the block's axis words were its data
  void transformRestrictions(int oneShot, bool workChanged) const;
  std::array<int64_t, kMaxAxes> transformed(const std::array<int64_t, kMaxAxes>& p) const;
  std::array<int64_t, kMaxAxes> programmedHere() const;   // where the program thinks the tool is
  void untransformProgrammed();                           // programmed_ from the tool position
  const std::array<int64_t, kMaxAxes>* moveBase() const;  // base of incremental words
  // One programmed move (work coordinates before the transforms; arcs with their centre).
  struct PlannedMove {
    int mode = 10;  // 0 rapid, 10 line, 20 CW, 30 CCW (x10 like group 01)
    std::array<int64_t, kMaxAxes> end{};
    double cu = 0, cv = 0;  // arc centre in the plane (nm)
    uint32_t mask = 0;
  };
  void runPlanned(const PlannedMove& m);

  // corner_words.cpp: ,C and ,R
  struct CornerHold {
    PlannedMove move;
    std::array<int64_t, kMaxAxes> start{};
    bool chamfer = true;
    int64_t amount = 0;  // nm
    EventOrigin origin;
    double feed = 0;
    int plane = 17;
    const Block* block = nullptr;  // alarms about the corner point at the ,C/,R block
  };
  std::optional<CornerHold> cornerHold_;
  // ,C/,R in cutter compensation offset mode: the programmed block waits for the next one.
  struct CrcCorner {
    crc::InSeg seg;
    bool chamfer = true;
    double amount = 0;  // program units
    const Block* block = nullptr;
    int plane = 17;
  };
  std::optional<CrcCorner> crcCorner_;
  bool crcPush(crc::InSeg s, const Words& w);  // false: held for its ,C/,R
  bool plannedBlock(const Words& w, const std::array<int64_t, kMaxAxes>& target, uint32_t mask,
                    bool arc, bool cw);
  void cornerCheckBlock(const Words& w, int oneShot, bool crcMode) const;
  struct ContourCorner {
    size_t seg;  // the shape segment the ,C/,R block made
    bool chamfer;
    double amount;  // program units
    const Block* block;
  };
  void applyContourCorners(lathe::Contour& c, std::vector<double>& feeds,
                           const std::vector<ContourCorner>& corners);

  // print.cpp
  void print(const Block& b);

  // tnrc_exec.cpp: lathe tool-nose radius compensation (the compensator above places the
  // nose centre; these add the imaginary tip and handle the lathe cycles)
  const AxisArray* noseEnd_ = nullptr;  // set while emitting a move under G41/G42 (lathe)
  // G70 under G41/G42: per compensated contour piece, the programmed end and the nose centre.
  std::vector<std::pair<lathe::Pt, lathe::Pt>> tnrcProgrammed_;
  int tnrcOffsetRow() const;
  double tnrcRadius() const;
  crc::P2 tnrcTipVector(double radius) const;
  AxisArray tnrcNoseEnd(const std::array<int64_t, kMaxAxes>& tipWork, const crc::P2& tip) const;
  void tnrcBeforeCycle(int kind, const Words& w);
  bool tnrcActive() const;
  std::vector<lathe::Move> tnrcSingleCycle(const lathe::Pt& start,
                                           const std::vector<lathe::Move>& moves, bool face);
  lathe::Contour tnrcContour(const lathe::Contour& c, std::vector<double>& feeds);
};

}  // namespace ncvm
