// One NC block, in the control's order: gather and check every word first, then code
// calls and G65/G66, modal G codes, F/S/T/H/D, auxiliary M functions, the one-shot or
// modal motion, and last the program-control M codes (M00/M01/M02/M30/M98/M99).
#include <fmt/format.h>

#include <cmath>

#include "exec/executor.hpp"
#include "exec/words.hpp"

namespace ncvm {

namespace {
constexpr uint32_t bit(char letter) {
  return 1u << (letter - 'A');
}
}  // namespace

void Executor::deriveModal() {
  modal_.motion = modal_.g[1];
  modal_.plane = lathe_ ? modal_.g[16] / 10 : modal_.g[2] / 10;
  modal_.incremental = modal_.g[3] == 910;
  if (series_ == Series::TA)
    modal_.feedPerRev = modal_.g[5] == 990;
  else
    modal_.feedPerRev = modal_.g[5] == 950;
  modal_.css = (lathe_ ? modal_.g[2] : modal_.g[13]) == 960;
  int unitCode = modal_.g[6];
  modal_.unit = (unitCode == 200 || unitCode == 700) ? InputUnit::Inch : InputUnit::Mm;
}

// A block of nothing but G00/G01/G02/G03 and X Y Z F I J K R words on a mill, with no
// cutter compensation, transform, polar coordinates (G16), canned cycle, modal call (G66),
// comma word (,C/,R/,A) or code call of its G code in effect: of execNcGeneral's generic
// order only the modal G code, F and the move do anything, so they run here without the walk
// through every other word and mode (the bulk of a CAM program). Returns false, having
// changed nothing, for any other block.
bool Executor::plainMotion(Words& w) {
  constexpr uint32_t kPlain = bit('G') | bit('X') | bit('Y') | bit('Z') | bit('F') | bit('I') |
                              bit('J') | bit('K') | bit('R');
  if (lathe_ || (w.present & ~kPlain) || w.nm || w.ng > 1 || w.nameIdx >= 0 || w.hasCorner() ||
      w.hasCommaA)
    return false;
  if (modal_.g[7] != 400 || modal_.g[9] != 800 || modal_.g[17] != 150 || !modalCalls_.empty() ||
      xf_.active() || cornerHold_ || crcCorner_ || crcBusy())
    return false;
  if (w.ng == 1) {
    const int code = w.g[0];
    if ((code != 0 && code != 10 && code != 20 && code != 30) ||
        gCall_[static_cast<size_t>(code / 10)] > 0)
      return false;
    const GCodeInfo* info = gInfo(code);
    if (!info || info->status == GStatus::NotYet || info->group != 1) return false;
    applyModalG(code, *info);
  }
  deriveModal();
  exactStop_ = modal_.g[15] == 610;  // G61 (a G09 block is not plain)
  if (w.has('F')) {
    double fv = w.value('F');
    if (fv < 0) throw AlarmError(AlarmId::IllegalMinus, "F");
    if (!w.hasPoint('F') && !dpi_ && modal_.feedPerRev)
      fv *= leastIncrement(setup_.increment, modal_.unit);
    modal_.feed = fv;
  }
  std::array<int64_t, kMaxAxes> target{};
  uint32_t mask = 0;
  const bool arc = arcBlock(w);
  const bool hasAxes = plainTargets(w, target, mask);
  if (arc && (hasAxes || w.any("IJKR"))) {
    plannedBlock(w, target, mask, true, modal_.motion == 20);
  } else if (hasAxes) {
    // plannedBlock without a held corner or a transform is the move itself.
    moveTo(target, modal_.motion == 0 ? MoveMode::Rapid : MoveMode::Linear, mask);
    programmed_ = target;
  }
  ++frames_.back().pc;  // programControl without M codes, G66 or a code call
  return true;
}

void Executor::execNcGeneral(const Block& b) {
  Words w;
  if (b.flags & kPlainBlock) {
    gatherPlainWords(b, w);
    if (plainMotion(w)) return;
    w = Words{};  // a mode the fast path does not handle: the generic path from the start
  }
  gatherWords(b, w);
  if (plainMotion(w)) return;
  Frame& f = frames_.back();

  if (!f.codeCalled && codeCall(b, w)) return;

  // Macro calls: G65 simple call, G66 modal call set-up, G67 cancel.
  bool g65 = false, g66 = false, g67 = false;
  for (int k = 0; k < w.ng; ++k) {
    g65 |= w.g[static_cast<size_t>(k)] == 650;
    g66 |= w.g[static_cast<size_t>(k)] == 660;
    g67 |= w.g[static_cast<size_t>(k)] == 670;
  }
  if (g65 || g66) {
    if (w.ng > 1) {
      AlarmError e(AlarmId::GAsArgument);
      e.col = w.gcol[1];
      throw e;
    }
    if (!w.has('P') && w.nameIdx < 0)
      throw AlarmError(AlarmId::ProgramNotFound, "G65/G66 without P");
    const Program* p = findProgram(w.has('P') ? integerWord(w, 'P') : -1, w.nameIdx);
    int repeats = w.has('L') ? integerWord(w, 'L') : 1;
    if (repeats < 0 || repeats > 9999) throw AlarmError(AlarmId::IntegerOverflow, "L");
    ++f.pc;
    if (g65) {
      if (repeats == 0) return;
      macroCallFromWords(p, repeats, w, FrameKind::Macro, false);
    } else {
      // Arguments are fixed now; the call happens after each later block that moves.
      ModalCall mc;
      mc.prog = p;
      mc.repeats = repeats;
      buildArgs(w, -1, mc.args, mc.scale);
      modalCalls_.push_back(mc);
      modal_.g[12] = 660;
    }
    return;
  }
  if (g67) {
    if (!modalCalls_.empty()) modalCalls_.pop_back();
    if (modalCalls_.empty()) modal_.g[12] = 670;
  }

  // G codes: modal ones change state (the last of a group wins), one-shot ones are noted.
  const int16_t workBefore = modal_.g[14], lengthBefore = modal_.g[8];
  const int32_t hBefore = modal_.hOffset;
  const int planeBefore = modal_.plane;
  int oneShot = -1;
  bool cycleCommanded = false;
  for (int k = 0; k < w.ng; ++k) {
    int code = w.g[static_cast<size_t>(k)];
    if (!gInfo(code)) {
      // Only reachable for a macro-call G code inside a code-called program: executed as
      // an ordinary G code, which the control does not have.
      AlarmError e(AlarmId::ImproperGCode, fmt::format("G{}", code / 10));
      e.col = w.gcol[static_cast<size_t>(k)];
      throw e;
    }
    const GCodeInfo& info = *gInfo(code);
    if (info.status == GStatus::NotYet) {
      AlarmError e(AlarmId::ImproperGCode,
                   fmt::format("G{:02d}{} ({}) is not supported by ncvm yet", code / 10,
                               code % 10 ? fmt::format(".{}", code % 10) : "", info.meaning));
      e.col = w.gcol[static_cast<size_t>(k)];
      throw e;
    }
    if (code == 670) continue;
    if (info.group == 0)
      oneShot = code;
    else
      applyModalG(code, info);
    if (info.group == 9) {
      if (code == 800)
        cancelCycle();
      else
        cycleCommanded = true;
    }
    // A group-01 code ends canned-cycle mode (mill and lathe drilling cycles).
    if (info.group == 1 && modal_.g[9] != 800) cancelCycle();
  }
  deriveModal();
  exactStop_ = oneShot == 90 || (!lathe_ && modal_.g[15] == 610);  // G09 / G61 (time model)
  const bool crcMode = modal_.g[7] != 400 || crcBusy();
  if (!lathe_ && modal_.plane != planeBefore && crc_ && crc_->active())
    throw AlarmError(AlarmId::CannotChangePlaneInCrc,
                     fmt::format("G{} while G41/G42 vectors are in effect", modal_.plane));
  cornerCheckBlock(w, oneShot, crcMode);
  if (!lathe_) transformRestrictions(oneShot, modal_.g[14] != workBefore);
  if (crcMode) {
    deferring_ = true;
    // Blocks that stop buffering end the lookahead before they run.
    // G27 too: it moves to a checked point, not along the compensated contour.
    bool stop =
        oneShot == 270 || oneShot == 280 || oneShot == 300 || oneShot == 290 || oneShot == 530;
    // G31 after G40: the probe may touch the simulated stock, which must have every held move.
    stop |= oneShot == 310 && modal_.g[7] == 400;
    for (int k = 0; k < w.nm; ++k) {
      int m = w.m[static_cast<size_t>(k)];
      stop |= m == 0 || m == 1 || m == 2 || m == 30;
    }
    if (stop) {
      crcDrain();
      deferring_ = crcBusy();
    }
  }
  if (modal_.g[14] != workBefore || (w.has('P') && modal_.g[14] >= 540 && oneShot < 0 && [&] {
        for (int k = 0; k < w.ng; ++k)
          if (w.g[static_cast<size_t>(k)] / 10 == 54) return true;
        return false;
      }())) {
    // G54-G59, G54.1 Pn (and the 30i spelling G54 Pn) select a work offset table.
    int code = modal_.g[14];
    if (code == 541 || (code == 540 && w.has('P'))) {
      int p = w.has('P') ? integerWord(w, 'P') : 1;
      if (p < 1 || p > 300)
        throw AlarmError(AlarmId::IllegalOffsetNumber, fmt::format("G54.1 P{}", p));
      modal_.g[14] = 541;
      modal_.workP = p;
      workIndex_ = kWorkP1 + p - 1;
    } else {
      workIndex_ = kWorkG54 + (code - 540) / 10;
    }
    recomputeOffset();
    for (size_t k = 0; k < kMaxAxes; ++k) programmed_[k] = machine_[k] - offset_[k];
  }

  if (w.has('F')) {
    double fv = w.value('F');
    if (fv < 0) throw AlarmError(AlarmId::IllegalMinus, "F");
    // F without a decimal point: whole units per minute, but least increments per revolution.
    if (!w.hasPoint('F') && !dpi_ && modal_.feedPerRev)
      fv *= leastIncrement(setup_.increment, modal_.unit);
    modal_.feed = fv;
  }
  if (w.has('E')) modal_.e = w.value('E');
  if (w.has('B') && setup_.axisSlot('B') < 0) {
    // Without a B axis, B is the second auxiliary function, passed to the machine.
    modal_.b = w.value('B');
    sink().onAux(AuxEvent{origin_, 'B', static_cast<int>(std::llround(modal_.b))});
  }
  if (w.has('H') && !lathe_) {
    int h = integerWord(w, 'H');
    if (h < 0 || h >= kToolRows)
      throw AlarmError(AlarmId::IllegalOffsetNumber, fmt::format("H{}", h));
    modal_.hOffset = h;
  }
  if (!lathe_ && (modal_.g[8] != lengthBefore || modal_.hOffset != hBefore)) applyToolShift();
  if (w.has('D')) modal_.dOffset = integerWord(w, 'D');
  if (lathe_ && (oneShot == 500 || oneShot == 920)) {
    // Lathe G50 S / G92 S: maximum spindle speed for constant surface speed.
    spindleClamp_ = w.has('S') ? integerWord(w, 'S') : spindleClamp_;
  } else if (w.has('S')) {
    modal_.speed = integerWord(w, 'S');
    double before = rpm_;
    rpm_ = modal_.css ? cssRpmAt(machine_[0]) : modal_.speed;
    if (spindleOn_ && rpm_ != before) {
      sink().onSpindle(SpindleEvent{origin_, spindleDir_, rpm_});
    }
  }
  if (w.has('T')) {
    modal_.tool = integerWord(w, 'T');
    if (tcs_ && !f.codeCalled) {
      // T code call (6001#5): the rest of the block runs first, then O9000 with #149 = T.
      w.tCall = true;
    }
    if (!w.tCall)
      sink().onTool(ToolEvent{origin_, lathe_ ? latheToolNumber(modal_.tool) : modal_.tool, false});
    if (lathe_ && !w.tCall)
      applyToolShift();  // Tttoo: geometry tt and wear oo shift the coordinates
  }
  auxFunctions(w);
  if (ended_) return;

  if (!lathe_ && transformBlock(w, oneShot)) {
    programControl(w, false);
    return;
  }
  bool moved = false;
  std::array<int64_t, kMaxAxes> target{};
  uint32_t mask = 0;
  if (w.hasCommaA) directDrawingHere(w);  // ,A: the missing end coordinate, or its alarm
  // Lathe drilling cycles (G83-G89, modal until G80 or group 01).
  if (lathe_ && modal_.g[9] != 800 && oneShot < 0) {
    moved = latheDrillCycle(w, cycleCommanded);
    programControl(w, moved);
    return;
  }
  // Lathe multiple repetitive cycles (one-shot) and single cycles (modal group 01).
  if (lathe_) {
    int kind = oneShot >= 0 ? latheCycleKind(oneShot) : 0;
    int modalKind = latheCycleKind(modal_.motion);
    if (kind || modalKind) {
      tnrcBeforeCycle(kind ? kind : modalKind, w);  // the held blocks end before the cycle
      moved = latheCycle(w, kind ? kind : modalKind);
      programControl(w, moved);
      return;
    }
  }
  switch (oneShot) {
    case 40:
      dwell(w);
      break;
    case 280:
    case 300:
      referenceReturn(w, oneShot == 280 ? 1 : (w.has('P') ? integerWord(w, 'P') : 2));
      moved = true;
      break;
    case 270:
      referencePositionCheck(w);
      moved = true;
      break;
    case 290:
      returnFromReference(w);
      moved = true;
      break;
    case 530:
      machinePositioning(w);
      if (xf_.active()) untransformProgrammed();
      moved = true;
      break;
    case 390:
      // G39 corner arc: the next compensated block starts with an arc around its corner.
      if (crc_ && crc_->active()) {
        g39Pending_ = true;
        g39Origin_ = origin_;
        // I/J/K in the plane (G17 I J, G18 K I, G19 J K), incremental from the corner.
        const xform::PlaneAxes pa = xform::planeAxes(modal_.plane);
        auto ijk = [&](size_t k) {
          const char c = "IJK"[k];
          return w.has(c)
                     ? static_cast<double>(lengthNm(w.value(c), w.hasPoint(c), static_cast<int>(k)))
                     : 0.0;
        };
        g39HasDir_ = w.any("IJK");
        g39Dir_ = {ijk(pa.u), ijk(pa.v)};
      }
      break;
    case 100:
      programmableDataInput(w);
      break;
    case 520:
      localCoordinates(w);
      break;
    case 921:
      coordinatePreset(w);
      break;
    case 500:
    case 920:
      coordinateSetting(w);  // a lathe G50/G92 with only S was the spindle clamp above
      break;
    case 310:
      skipMove(w);
      moved = true;
      break;
    case 450:
    case 460:
    case 470:
    case 480:
      moved = toolPositionOffset(w, oneShot);
      break;
    default: {
      const bool latheThread = lathe_ && (modal_.motion == 320 || modal_.motion == 330);
      if (latheThread) tnrcBeforeCycle(0, w);  // threading moves are not nose-compensated
      if (!latheThread && (modal_.g[7] != 400 || crcBusy())) {
        bool arc = arcBlock(w);
        axisTargets(w, target, mask, &programmed_);
        moved = crcBlock(w, target, mask, arc, modal_.motion == 20);
        break;
      }
      if (!lathe_ && modal_.g[9] != 800) {
        moved = drillCycle(w, cycleCommanded);
        break;
      }
      if (lathe_ && (modal_.motion == 320 || modal_.motion == 330)) {
        // G32/G33: one threading move; F (or E) is the lead per spindle revolution.
        if (axisTargets(w, target, mask)) {
          double feed = modal_.feed;
          bool perRev = modal_.feedPerRev;
          modal_.feed = w.has('E') ? w.value('E') : modal_.feed;
          modal_.feedPerRev = true;
          threadMove_ = true;
          moveTo(target, MoveMode::Linear, mask);
          threadMove_ = false;
          modal_.feed = feed;
          modal_.feedPerRev = perRev;
          moved = true;
        }
        break;
      }
      bool arc = arcBlock(w);
      bool hasAxes = axisTargets(w, target, mask, moveBase());
      if (arc && (hasAxes || w.any("IJKR"))) {
        moved = plannedBlock(w, target, mask, true, modal_.motion == 20);
      } else if (hasAxes) {
        moved = plannedBlock(w, target, mask, false, false);
      } else if (cornerHold_) {
        throw AlarmError(AlarmId::MissingMoveAfterChamfer, "the block after ,C/,R does not move");
      } else if (w.hasCorner()) {
        throw AlarmError(AlarmId::ChamferMoveTooShort, ",C/,R in a block without a move");
      }
      break;
    }
  }
  programControl(w, moved);
}

void Executor::applyModalG(int code10, const GCodeInfo& info) {
  modal_.g[info.group] = static_cast<int16_t>(code10);
  if (code10 == 541) modal_.workP = 1;
}

void Executor::auxFunctions(Words& w) {
  for (int k = 0; k < w.nm; ++k) {
    int m = w.m[static_cast<size_t>(k)];
    switch (m) {
      case 0:
      case 1:
      case 2:
      case 30:
      case 98:
      case 99:
        break;  // program control, after the motion
      case 3:
      case 4:
        spindleOn_ = true;
        spindleDir_ = m == 3 ? SpindleDir::Cw : SpindleDir::Ccw;
        modal_.lastM = m;
        rpm_ = modal_.css ? cssRpmAt(machine_[0]) : modal_.speed;
        sink().onSpindle(SpindleEvent{origin_, m == 3 ? SpindleDir::Cw : SpindleDir::Ccw, rpm_});
        break;
      case 5:
        spindleOn_ = false;
        modal_.lastM = m;
        sink().onSpindle(SpindleEvent{origin_, SpindleDir::Stop, 0});
        break;
      case 19:
        spindleOn_ = false;
        modal_.lastM = m;
        sink().onSpindle(SpindleEvent{origin_, SpindleDir::Orient, 0});
        break;
      case 6:
        modal_.lastM = m;
        sink().onTool(
            ToolEvent{origin_, lathe_ ? latheToolNumber(modal_.tool) : modal_.tool, true});
        break;
      case 29:  // rigid tapping: the next G84/G74 (lathe G84/G88) follows the spindle
        rigidTap_ = true;
        modal_.lastM = m;
        sink().onAux(AuxEvent{origin_, 'M', m});
        break;
      case 7:
      case 8:
      case 9:
        modal_.lastM = m;
        sink().onCoolant(CoolantEvent{origin_, m == 9   ? CoolantState::Off
                                               : m == 7 ? CoolantState::Mist
                                                        : CoolantState::Flood});
        break;
      default:
        if (int prog = m >= 0 && m < 1000 ? mSubCall_[static_cast<size_t>(m)] : 0;
            prog > 0 && !frames_.back().codeCalled) {
          // Subprogram-type M code call: the block's other words run first, then the call,
          // which happens with programControl's ordering below (treated as M98).
          w.subCallProgram = prog;
          break;
        }
        modal_.lastM = m;
        sink().onAux(AuxEvent{origin_, 'M', m});
        break;
    }
  }
}

void Executor::programControl(Words& w, bool moved) {
  Frame& f = frames_.back();
  ++f.pc;
  const std::string_view comment =
      block_->comment >= 0 ? std::string_view(f.prog->strings[static_cast<size_t>(block_->comment)])
                           : std::string_view();
  for (int k = 0; k < w.nm; ++k) {
    int m = w.m[static_cast<size_t>(k)];
    if (m == 0) {
      modal_.lastM = 0;
      sink().onMessage(MessageEvent{origin_, comment, "M00"});
    } else if (m == 1) {
      modal_.lastM = 1;
      if (setup_.optionalStop) sink().onMessage(MessageEvent{origin_, comment, "M01"});
    } else if (m == 2 || m == 30) {
      modal_.lastM = m;
      if (f.kind == FrameKind::Main || true) {
        ended_ = true;
        endReason_ = m == 2 ? EndReason::M02 : EndReason::M30;
        if (m == 30) mem_.parts3901 += 1;  // part count (parameter 6700 counts M30 by default)
        return;
      }
    }
  }
  // A modal call (G66) runs after a block that moved an axis, before M98/M99 of the block.
  if (moved && !modalCalls_.empty() && static_cast<int>(modalCalls_.size()) > f.modalFloor) {
    const ModalCall& mc = modalCalls_.back();
    callMacro(mc.prog, mc.repeats, mc.args, mc.scale, FrameKind::ModalMacro, false);
    return;
  }
  for (int k = 0; k < w.nm; ++k) {
    int m = w.m[static_cast<size_t>(k)];
    if (m == 98) {
      int32_t p = w.has('P') ? integerWord(w, 'P') : -1;
      int repeats = w.has('L') ? integerWord(w, 'L') : 1;
      // M98 Q (0i-F/30i): from sequence number Q of program P, or of this program without P.
      const int32_t q = w.has('Q') ? integerWord(w, 'Q') : -1;
      if (w.has('Q') && (q < 1 || q > 99999999))
        throw AlarmError(AlarmId::SequenceNotFound, fmt::format("M98 Q{}", q));
      if (p < 0 && w.nameIdx < 0 && q < 0)
        throw AlarmError(AlarmId::ProgramNotFound, "M98 without P");
      if (!w.has('L') && p > 9999 && setup_.programNumberDigits == 4) {
        // M98 Pxxxxnnnn: repeat count in front of a four-digit program number (with 8-digit
        // program numbers the repeat count can only be given with L).
        repeats = p / 10000;
        p %= 10000;
      }
      if (repeats < 0 || repeats > 9999) throw AlarmError(AlarmId::IntegerOverflow, "L");
      if (repeats == 0) return;
      callSub(p < 0 && w.nameIdx < 0 ? f.prog : findProgram(p, w.nameIdx), repeats, false, q);
      return;
    }
    if (m == 99) {
      modal_.lastM = 99;
      doReturn(w.has('P') ? integerWord(w, 'P') : -1);
      return;
    }
  }
  if (w.subCallProgram >= 0) {
    callSub(findProgram(w.subCallProgram, -1), 1, true);
  } else if (w.tCall) {
    writeVar(149, Value::num(modal_.tool));
    callSub(findProgram(9000, -1), 1, true);
  }
}

}  // namespace ncvm
