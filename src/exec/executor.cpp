#include "exec/executor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "lang/program_stream.hpp"

namespace ncvm {

const char* endReasonName(EndReason r) {
  switch (r) {
    case EndReason::M30:
      return "M30";
    case EndReason::M02:
      return "M02";
    case EndReason::M99:
      return "M99";
    case EndReason::Alarm:
      return "alarm";
    case EndReason::Eof:
      return "eof";
    case EndReason::Limit:
      return "limit";
  }
  return "eof";
}

EventSink& Executor::sink() {
  return deferring_ ? static_cast<EventSink&>(deferSink_) : realSink_;
}

Executor::Executor(const Setup& setup, ProgramStore& store, EventSink& sink)
    : setup_(setup),
      store_(store),
      realSink_(sink),
      series_(setup.series()),
      lathe_(setup.kind == MachineKind::Lathe),
      dpi_(setup.dpi()) {
  for (const auto& g : gcodeTable())
    if ((g.seriesMask & seriesBit(series_)) && g.code10 >= 0 && g.code10 < 1000)
      gInfo_[static_cast<size_t>(g.code10)] = &g;
  for (int k = 0; k < kMaxAxes; ++k) {
    bool rot = setup.axes[static_cast<size_t>(k)].rotary;
    nmPerIncMm_[static_cast<size_t>(k)] = nmPerIncrement(setup.increment, InputUnit::Mm, rot);
    nmPerIncInch_[static_cast<size_t>(k)] = nmPerIncrement(setup.increment, InputUnit::Inch, rot);
  }
  for (int c = 0; c < 1000; ++c) {
    int g = setup.gCodeCall(c), mm = setup.mCodeMacroCall(c), ms = setup.mCodeSubCall(c);
    gCall_[static_cast<size_t>(c)] = static_cast<int16_t>(g < 0 ? 0 : g);
    mMacroCall_[static_cast<size_t>(c)] = static_cast<int16_t>(mm < 0 ? 0 : mm);
    mSubCall_[static_cast<size_t>(c)] = static_cast<int16_t>(ms < 0 ? 0 : ms);
  }
  nat_ = setup.nat();
  lrp_ = setup.lrp();
  tcs_ = setup.tcs();
  macroDigits_ = setup.macroDigits();
  arcTolerance_ = setup.arcTolerance();
  frames_.reserve(32);
  modalCalls_.reserve(8);
  // Power-on modal state.
  modal_.unit = setup.initialUnit;
  auto set = [&](int code10) {
    if (const GCodeInfo* g = gInfo_[static_cast<size_t>(code10)])
      modal_.g[g->group] = static_cast<int16_t>(code10);
  };
  for (int c : {0, 400, 490, 500, 501, 540, 640, 670, 690, 800, 970, 150, 230, 131}) set(c);
  set(lathe_ ? 180 : 170);
  set(modal_.unit == InputUnit::Inch ? (series_ == Series::TC ? 700 : 200)
                                     : (series_ == Series::TC ? 710 : 210));
  if (series_ == Series::M || series_ == Series::TB || series_ == Series::TC) set(900);
  if (series_ == Series::M) set(940), set(980);
  if (series_ == Series::TA) set(990);  // lathes power on in feed per revolution
  if (series_ == Series::TB || series_ == Series::TC) set(950), set(980);
  deriveModal();
  for (int k = 0; k < kMaxAxes; ++k) {
    const AxisConfig& a = setup.axes[static_cast<size_t>(k)];
    if (!a.present) continue;
    machine_[static_cast<size_t>(k)] = lengthNm(a.initial, true, k) / (a.diameter ? 2 : 1);
  }
  initMemoryFromSetup();
  // #200-#499 without their option are refused by the session before the run.
  for (const auto& [n, v] : setup.initialVars)
    if (n < 500 && (n < 200 || setup.commonVars200)) writeVar(n, Value::num(v));
  restartFromMemory();
}

void Executor::restartFromMemory() {
  // Solids in a work frame are placed with the offsets the run starts with.
  probeWorld_ = SolidWorld::fromSetup(setup_, [&](int index) {
    Vec3 v{};
    for (size_t k = 0; k < 3; ++k)
      v[k] =
          static_cast<double>(mem_.work[kWorkExt][k] + mem_.work[static_cast<size_t>(index)][k]) /
          1e6;
    return v;
  });
  recomputeOffset();
  for (size_t k = 0; k < kMaxAxes; ++k) programmed_[k] = machine_[k] - offset_[k];
}

Executor::~Executor() = default;

void Executor::warn(const char* code, std::string text) {
  SourceLoc loc = block_ ? block_->loc : SourceLoc{};
  warnings_.push_back(Warning{code, std::move(text), loc});
}

const Program* Executor::findProgram(int32_t number, int32_t nameIdx) {
  const Program* p = nullptr;
  if (nameIdx >= 0) {
    const std::string& name = frames_.back().prog->strings[static_cast<size_t>(nameIdx)];
    p = store_.byName(name);
    if (!p) throw AlarmError(AlarmId::ProgramNotFound, "<" + name + ">");
  } else {
    p = store_.byNumber(number);
    if (!p) throw AlarmError(AlarmId::ProgramNotFound, fmt::format("O{:04d}", number));
  }
  return p;
}

// A streamed program holds only the piece that runs (program_stream.hpp): before anything
// reaches another block of it, it is compiled whole. Its frames' block indices become indices
// in the whole program, and block_ the same block there (the piece's arrays stay alive, so a
// reference to the running block held further up the stack still reads the same words).
void Executor::wholeProgram(const Program& p) {
  if (!p.stream) return;
  const auto window = reinterpret_cast<uintptr_t>(p.blocks.data());
  const auto windowEnd = window + p.blocks.size() * sizeof(Block);
  const auto at = reinterpret_cast<uintptr_t>(block_);
  const uint32_t base = p.stream->materialize();
  for (Frame& f : frames_)
    if (f.prog == &p) f.pc += base;
  if (at >= window && at < windowEnd) block_ = &p.blocks[base + (at - window) / sizeof(Block)];
}

// The compiler's DO/END and literal GOTO errors, by block, looked up the first time a block
// of a program that has any runs (blocks are in source order; each error is at its block's
// start).
const Alarm* Executor::structuralError(const Program& p, uint32_t k) {
  auto [it, fresh] = structuralAt_.try_emplace(&p);
  auto& byBlock = it->second;
  if (fresh) {
    for (uint32_t i = 0; i < p.structural.size(); ++i) {
      const SourceLoc& at = p.structural[i].loc;
      auto b = std::lower_bound(
          p.blocks.begin(), p.blocks.end(), at, [](const Block& blk, const SourceLoc& l) {
            return blk.loc.line != l.line ? blk.loc.line < l.line : blk.loc.col < l.col;
          });
      if (b != p.blocks.end() && b->loc.line == at.line && b->loc.col == at.col)
        byBlock.emplace_back(static_cast<uint32_t>(b - p.blocks.begin()), i);
    }
    std::stable_sort(byBlock.begin(), byBlock.end(),
                     [](auto& x, auto& y) { return x.first < y.first; });
  }
  auto e = std::lower_bound(byBlock.begin(), byBlock.end(), k,
                            [](auto& x, uint32_t v) { return x.first < v; });
  return e != byBlock.end() && e->first == k ? &p.structural[e->second] : nullptr;
}

void Executor::raiseStructural(const Alarm& a) {
  AlarmError e(a.code, a.text);
  e.hasLoc = true;
  e.loc = a.loc;
  e.n = a.n.value_or(-1);
  throw e;
}

void Executor::enter(const Program* p, FrameKind kind, int repeats, bool codeCalled) {
  if (!frames_.empty()) wholeProgram(*p);  // a streamed program called from within itself
  Frame f;
  f.prog = p;
  f.kind = kind;
  f.repeatsLeft = repeats - 1;
  f.codeCalled = codeCalled;
  if (!frames_.empty()) {
    f.level = frames_.back().level;
    f.modalFloor = frames_.back().modalFloor;
  }
  frames_.push_back(f);
}

void Executor::callSub(const Program* p, int repeats, bool codeCalled, int32_t startLabel) {
  if (subDepth_ + 1 > setup_.limits.subprogramNesting ||
      subDepth_ + macroDepth_ + 1 > setup_.limits.totalNesting)
    throw AlarmError(AlarmId::TooManySubNesting, fmt::format("more than {} subprogram levels",
                                                             setup_.limits.subprogramNesting));
  int32_t start = 0;
  if (startLabel >= 0) {
    // M98 Q: the sequence number is searched in the called program from its start (the
    // caller's own program for M98 Q without P); not found: PS0078.
    wholeProgram(*p);
    start = p->findLabel(startLabel, 0);
    if (start < 0)
      throw AlarmError(AlarmId::SequenceNotFound,
                       fmt::format("N{} in {}", startLabel, p->displayName()));
  }
  enter(p, FrameKind::Sub, repeats, codeCalled);
  frames_.back().pc = frames_.back().startPc = static_cast<uint32_t>(start);
  ++subDepth_;
}

void Executor::callMacro(const Program* p, int repeats, const std::array<Value, 33>& args,
                         const std::array<double, 33>& scale, FrameKind kind, bool codeCalled) {
  if (macroDepth_ + 1 > setup_.limits.macroNesting)
    throw AlarmError(AlarmId::TooManyMacroNesting,
                     fmt::format("more than {} macro levels", setup_.limits.macroNesting));
  if (subDepth_ + macroDepth_ + 1 > setup_.limits.totalNesting)
    throw AlarmError(AlarmId::TooManySubNesting,
                     "more than " + std::to_string(setup_.limits.totalNesting) + " call levels");
  int16_t floor = frames_.back().modalFloor;
  enter(p, kind, repeats, codeCalled);
  ++macroDepth_;
  int8_t level = static_cast<int8_t>(macroDepth_);
  Frame& f = frames_.back();
  f.level = level;
  if (kind == FrameKind::ModalMacro)
    f.modalFloor = static_cast<int16_t>(modalCalls_.size());
  else
    f.modalFloor = floor;
  vars_.enterCall(level, args, scale);
}

void Executor::doReturn(int32_t label) {
  Frame& f = frames_.back();
  if (f.kind == FrameKind::Main) {
    // M99 in a main program starts it again (or jumps to N label); only the block and time
    // limits end such a loop.
    wholeProgram(*f.prog);
    if (label >= 0) {
      int32_t t = f.prog->findLabel(label, 0);
      if (t < 0) throw AlarmError(AlarmId::SequenceNotFound, "N" + std::to_string(label));
      f.pc = static_cast<uint32_t>(t);
    } else {
      f.pc = 0;
    }
    return;
  }
  if (f.repeatsLeft > 0 && label < 0) {
    --f.repeatsLeft;
    f.pc = f.startPc;
    if (f.kind != FrameKind::Sub) vars_.repeatCall(f.level);
    return;
  }
  if (f.kind == FrameKind::Sub)
    --subDepth_;
  else
    --macroDepth_;
  frames_.pop_back();
  if (label >= 0) {
    Frame& caller = frames_.back();
    wholeProgram(*caller.prog);
    int32_t t = caller.prog->findLabel(label, caller.pc);
    if (t < 0) throw AlarmError(AlarmId::SequenceNotFound, "N" + std::to_string(label));
    caller.pc = static_cast<uint32_t>(t);
  }
}

void Executor::jumpTo(int32_t label, bool computed) {
  Frame& f = frames_.back();
  wholeProgram(*f.prog);
  const Block& b = *block_;
  int32_t t = -1;
  if (!computed) {
    // A literal target that is missing or inside a loop: the alarm comes when the GOTO runs.
    if (!f.prog->structural.empty()) [[unlikely]]
      if (const Alarm* a = structuralError(*f.prog, f.pc)) raiseStructural(*a);
    t = f.prog->ops(b).target;
    if (t < 0) [[unlikely]]
      throw AlarmError(AlarmId::IllegalMacroSequence, "N" + std::to_string(label) + " not found");
  } else {
    if (label < 1 || label > 99999999)
      throw AlarmError(AlarmId::IllegalMacroSequence, std::to_string(label));
    t = f.prog->findLabel(label, f.pc);
    if (t < 0)
      throw AlarmError(AlarmId::IllegalMacroSequence, "N" + std::to_string(label) + " not found");
    // A jump into a loop the GOTO is not inside is illegal.
    // (block_ is blocks[f.pc]: the GOTO's own block.)
    for (int32_t l = f.prog->loopParent(static_cast<size_t>(t)); l >= 0;
         l = f.prog->loopParent(static_cast<size_t>(l))) {
      bool inside = false;
      for (int32_t s = f.prog->loopParent(f.pc); s >= 0;
           s = f.prog->loopParent(static_cast<size_t>(s)))
        inside |= s == l;
      if (!inside) throw AlarmError(AlarmId::IllegalLoopNumber, "GOTO jumps into a loop");
    }
  }
  f.pc = static_cast<uint32_t>(t);
}

// A computed variable or sequence number, rounded. Values far outside every range are
// clamped (llround of 1e300 is undefined) so the range alarm names a number, not garbage.
static int64_t roundedIndex(double v) {
  constexpr double kMax = 1e9;
  return v > kMax    ? static_cast<int64_t>(kMax)
         : v < -kMax ? -static_cast<int64_t>(kMax)
                     : std::llround(v);
}

EndReason Executor::run(const Program& main) {
  try {
    enter(&main, FrameKind::Main, 1, false);
    while (step()) {
    }
    if (cornerHold_ || crcCorner_)
      throw AlarmError(AlarmId::MissingMoveAfterChamfer, "the program ends after a ,C/,R block");
    crcDrain();  // the end of the program releases whatever compensation still holds
  } catch (const AlarmError& e) {
    Alarm a;
    a.code = e.code();
    a.text = e.text();
    if (e.hasLoc) {
      a.loc = e.loc;
      if (e.n >= 0) a.n = e.n;
    } else if (block_) {
      a.loc = block_->loc;
      if (e.col) a.loc.col = e.col;
      if (block_->n >= 0) a.n = block_->n;
    }
    a.program = frames_.empty() ? main.number : frames_.back().prog->number;
    alarm_ = a;
    EventOrigin at = origin_;
    at.file = a.loc.file;
    at.line = a.loc.line;
    at.n = a.n ? static_cast<int32_t>(*a.n) : -1;
    if (!at.programName) at.programName = &main.label;
    // Under cutter compensation the control still runs the held blocks whose path was
    // complete when the alarm came; what follows the first incomplete one never happens.
    try {
      releasePending(false);
    } catch (const AlarmError&) {
    }
    pending_.clear();
    deferring_ = false;
    realSink_.onAlarm(AlarmEvent{at, a.code, a.text});
    endReason_ =
        (a.code == alarmCode(AlarmId::BlockLimit) || a.code == alarmCode(AlarmId::TimeLimit))
            ? EndReason::Limit
            : EndReason::Alarm;
  }
  return endReason_;
}

// Executes one block. Returns false when the program has ended.
bool Executor::step() {
  Frame& f = frames_.back();
  const Program& prog = *f.prog;
  if (f.pc >= prog.blocks.size()) {
    // A streamed program's next piece (only its main frame gets here: entering it again
    // makes it whole).
    if (prog.stream && prog.stream->advance()) {
      f.pc = 0;
      return true;
    }
    if (f.kind == FrameKind::Main) {
      endReason_ = EndReason::Eof;
      return false;
    }
    // A subprogram without M99: return as if it had one.
    warn("W003", fmt::format("{} ends without M99", prog.displayName()));
    doReturn(-1);
    return true;
  }
  const Block& b = prog.blocks[f.pc];
  block_ = &b;
  if (stats_.blocks >= setup_.limits.maxBlocks) blockLimitAlarm();
  ++stats_.blocks;
  if (b.skipLevel && setup_.blockSkip[b.skipLevel]) {
    ++f.pc;
    return true;
  }
  if (b.n >= 0) lastN_ = b.n;
  origin_.file = b.loc.file;
  origin_.line = b.loc.line;
  origin_.n = b.n;
  origin_.programName = &prog.label;
  deferring_ = crcBusy();
  const MacroOps& o = prog.ops(b);
  switch (b.kind) {
    case BlockKind::Empty:
      // A comment alone on a line of the main program, outside WHILE loops, names the
      // operation that follows (the time report's operations). One in a subprogram or macro,
      // or in a loop, describes a step of it: a drilling macro's "(END OF THE PECK)" is no
      // operation.
      if (b.comment >= 0 && frames_.size() == 1 && prog.loopParent(f.pc) < 0)
        sink().onComment(CommentEvent{origin_, prog.strings[static_cast<size_t>(b.comment)]});
      ++f.pc;
      break;
    case BlockKind::Error: {
      const Alarm& a = prog.errors[static_cast<size_t>(o.error)];
      AlarmError e(a.code, a.text);
      e.hasLoc = true;
      e.loc = a.loc;
      e.n = a.n.value_or(-1);
      throw e;
    }
    case BlockKind::Assign: {
      Value v = eval(o.rhs);
      int64_t n = o.lhsVar;
      if (o.lhsExpr >= 0) n = roundedIndex(eval(o.lhsExpr).asNumber());
      ++f.pc;
      writeVar(n, v);
      break;
    }
    case BlockKind::If:
      if (!evalCond(o.cond)) {
        ++f.pc;
      } else if (o.thenAssign) {
        Value v = eval(o.rhs);
        int64_t n = o.lhsVar;
        if (o.lhsExpr >= 0) n = roundedIndex(eval(o.lhsExpr).asNumber());
        ++f.pc;
        writeVar(n, v);
      } else {
        jumpTo(o.gotoExpr >= 0 ? static_cast<int32_t>(roundedIndex(eval(o.gotoExpr).asNumber()))
                               : o.gotoLabel,
               o.gotoExpr >= 0);
      }
      break;
    case BlockKind::Goto:
      jumpTo(o.gotoExpr >= 0 ? static_cast<int32_t>(roundedIndex(eval(o.gotoExpr).asNumber()))
                             : o.gotoLabel,
             o.gotoExpr >= 0);
      break;
    case BlockKind::While: {
      // A wrong loop number is found when the DO runs; a missing END when the loop is left
      // (the control looks for the END then), so a loop left by a GOTO needs none.
      const Alarm* bad = prog.structural.empty() ? nullptr : structuralError(prog, f.pc);
      if (bad && bad->code != alarmCode(AlarmId::MissingEnd)) raiseStructural(*bad);
      if (o.cond < 0 || evalCond(o.cond)) {
        ++f.pc;
      } else {
        if (bad) raiseStructural(*bad);
        if (o.target < 0) [[unlikely]]
          throw AlarmError(AlarmId::MissingEnd, "DO " + std::to_string(b.loopId));
        f.pc = static_cast<uint32_t>(o.target);
      }
      break;
    }
    case BlockKind::End:
      if (!prog.structural.empty()) [[unlikely]]
        if (const Alarm* a = structuralError(prog, f.pc)) raiseStructural(*a);
      if (o.target < 0) [[unlikely]]
        throw AlarmError(AlarmId::IllegalLoopNumber, "END " + std::to_string(b.loopId));
      f.pc = static_cast<uint32_t>(o.target);
      break;
    case BlockKind::Print:
      print(b);
      ++f.pc;
      break;
    case BlockKind::Popen:
    case BlockKind::Pclos:
      ++f.pc;  // the output "device" is the DPRNT file, always open
      break;
    case BlockKind::Nc:
      if (straightMove(b)) {
        // The plain blocks after a straight move run in straightRun's loop.
        if (simTime_ > setup_.limits.maxTimeSeconds) timeLimitAlarm();
        return straightRun();
      }
      execNcGeneral(b);
      break;
  }
  if (simTime_ > setup_.limits.maxTimeSeconds) timeLimitAlarm();
  return !ended_;
}

void Executor::blockLimitAlarm() const {
  throw AlarmError(AlarmId::BlockLimit,
                   fmt::format("limits.max_blocks = {}", setup_.limits.maxBlocks));
}

void Executor::timeLimitAlarm() const {
  throw AlarmError(AlarmId::TimeLimit,
                   fmt::format("limits.max_time_s = {}", setup_.limits.maxTimeSeconds));
}

void Executor::advanceTime(double seconds) {
  simTime_ += seconds;
  stats_.time += seconds;
}

std::vector<std::pair<int, double>> Executor::userVariables() const {
  return vars_.userVariables();
}

}  // namespace ncvm
