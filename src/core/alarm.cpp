#include "core/alarm.hpp"

#include <fmt/format.h>

namespace ncvm {

const std::vector<AlarmInfo>& alarmTable() {
  static const std::vector<AlarmInfo> table = {
      {AlarmId::TooManyDigits, "TOO MANY DIGIT", "A word has more digits than the address allows."},
      {AlarmId::NoDataAfterAddress, "NO DATA AFTER ADDRESS",
       "An address letter is not followed by a number, a variable or a bracket."},
      {AlarmId::IllegalMinus, "ILLEGAL USE OF MINUS SIGN",
       "A minus sign on an address that takes no sign (N, O, G, M, ...)."},
      {AlarmId::IllegalDecimalPoint, "ILLEGAL USE OF DECIMAL POINT",
       "A decimal point on an address that forbids it (P, M, S, T, H, D, L, N, O), or two points."},
      {AlarmId::ImproperAddress, "IMPROPER NC-ADDRESS",
       "A character that is not an address of this control (lower case, unknown letter, an axis "
       "the "
       "machine lacks)."},
      {AlarmId::ImproperGCode, "IMPROPER G-CODE",
       "A G code the control does not have, or one ncvm does not support yet (the text says "
       "which)."},
      {AlarmId::FeedZero, "FEED ZERO (COMMAND)", "A cutting move with F = 0 or no F ever given."},
      {AlarmId::OverToleranceOfRadius, "OVER TOLERANCE OF RADIUS",
       "Arc end point radius differs from the start radius by more than parameter 3410."},
      {AlarmId::IllegalPlaneSelect, "ILLEGAL PLANE SELECT",
       "An arc with an axis that is not in the selected plane."},
      {AlarmId::NoRadiusOrCenter, "R OR I,J,K COMMAND NOT FOUND", "An arc without R or I/J/K."},
      {AlarmId::CircleInRapid, "CIRCLE CUT IN RAPID (F0)", "An arc in rapid or with F0."},
      {AlarmId::IllegalOffsetNumber, "ILLEGAL OFFSET NUMBER",
       "An H, D or T offset number out of range."},
      {AlarmId::IllegalPInG10, "ILLEGAL P COMMAND IN G10",
       "G10 with an L or P it does not accept."},
      {AlarmId::IllegalOffsetValueInG10, "ILLEGAL OFFSET VALUE IN G10",
       "G10 with a value out of range."},
      {AlarmId::NoIntersectionCrc, "NO INTERSECTION AT CUTTER COMPENSATION",
       "Cutter compensation C cannot place a corner: the offset paths do not meet, or the cutter "
       "radius is larger than an inner arc."},
      {AlarmId::NoCircInStartupCancel, "NO CIRC ALLOWED IN STUP/EXT BLK",
       "G02/G03 in the block that starts (G41/G42) or cancels (G40, D0) cutter compensation."},
      {AlarmId::CannotG31InCompensation, "CAN NOT COMMANDED G31",
       "G31 while cutter compensation is on."},
      {AlarmId::CannotChangePlaneInCrc, "CAN NOT CHANGE PLANE IN G41/G42",
       "G17/G18/G19 while cutter compensation vectors are in effect."},
      {AlarmId::InterferenceInCircular, "INTERFERENCE IN CIRCULAR BLOCK",
       "Cutter compensation moves an arc's start or end point onto its centre."},
      {AlarmId::InterferenceInCrc, "INTERFERENCE IN CUTTER COMPENSATION",
       "A compensated block would run against its programmed direction (a step or groove "
       "smaller than the cutter radius): the tool would overcut."},
      {AlarmId::ChamferInStartupCancel, "CHF/CNR NOT ALLOWED IN G41,G42",
       "Chamfer or corner rounding (,C ,R) in the block that starts or cancels cutter "
       "compensation."},
      {AlarmId::G45G48InCrc, "G45/G48 NOT ALLOWED IN CRC",
       "G45-G48 (tool position offset) while cutter compensation is on."},
      {AlarmId::G27to30InCycle, "G27-G30 NOT ALLOWED IN FIXED CYC",
       "G27-G30 in canned-cycle mode."},
      {AlarmId::QNotFound, "ADDRESS Q NOT FOUND (G73/G83)",
       "G73 or G83 without a peck depth Q (or Q0)."},
      {AlarmId::IllegalReferenceReturn, "ILLEGAL REFERENCE RETURN COMMAND",
       "G30 with P other than 2-4."},
      {AlarmId::MissingMoveAfterChamfer, "MISSING MOVE AFTER CNR/CHF",
       "The block after a ,C or ,R block does not move in the same plane (no move, another "
       "plane, a non-moving block, the end of the program)."},
      {AlarmId::NotG01AfterChamfer, "CODE IS NOT G01 AFTER CHF/CNR",
       "The block after a ,C or ,R block (or the ,C/,R block itself) is not G01, G02 or G03."},
      {AlarmId::ChamferMoveTooShort, "MISSING MOVE VALUE IN CHF/CNR",
       "The chamfer or corner R does not fit on one of its two blocks (larger than the block)."},
      {AlarmId::NoEndPointAndAngle, "NO END POINT & ANGLE IN CHF/CNR",
       "Direct drawing dimensions (lathe ,A): the block after an angle-only block lacks its "
       "absolute X and Z or its angle, or X, Z and ,A come without an angle-only block before."},
      {AlarmId::NoSolutionOfBlockEnd, "NO SOLUTION OF BLOCK END",
       "Direct drawing dimensions (lathe ,A): the end point cannot be computed (the angle runs "
       "along the given coordinate, or the two lines of an angle-only block are parallel)."},
      {AlarmId::EndPointNotFound, "END POINT NOT FOUND",
       "Direct drawing dimensions (lathe ,A): an angle-only block with no NC block after it "
       "(a macro statement, the end of the program or of the G70-G73 shape)."},
      {AlarmId::CycleAddressPQNotFound, "ADDRESS P/Q NOT FOUND IN G70-G73",
       "G70-G73 without the P or Q that names the shape program."},
      {AlarmId::CycleIllegalCommand, "ILLEGAL COMMAND IN G71-G76",
       "A bad value in G71-G76: depth of cut 0 or less, G73 divisions below 1, a G74/G75 "
       "shift of 0, a G76 height, depth, angle or count out of range."},
      {AlarmId::CycleSequenceNotFound, "SEQUENCE NUMBER NOT FOUND",
       "The ns or nf block of G70-G73 is not in the program."},
      {AlarmId::ShapeNotMonotonous, "SHAPE PROGRAM NOT MONOTONOUSLY",
       "The G71/G72 shape is not monotonic: type I in both axes, type II along the cut."},
      {AlarmId::ShapeFirstBlockNotG00G01, "G00/G01 IS NOT IN THE FIRST SHAPE PROGRAM",
       "The ns block of G70-G73 is not G00 or G01."},
      {AlarmId::CycleUnavailableCommand, "UNAVAILABLE COMMAND IS IN G71-G76",
       "A command the shape program may not contain (M98, G codes of other groups, ...)."},
      {AlarmId::ReferenceCheckError, "ZERO RETURN CHECK (G27) ERROR",
       "G27: an axis did not reach its reference position at the commanded point."},
      {AlarmId::CycleNotInMemory, "G70-G73 NOT IN MEMORY",
       "G70-G73 run from MDI or DNC, where the shape blocks cannot be read back."},
      {AlarmId::ShapeLastBlockIllegal, "LAST BLOCK OF SHAPE PROGRAM IS AN ILLEGAL COMMAND",
       "The nf block ends in a chamfer or corner R that has nothing to join."},
      {AlarmId::ProgramNumberOutOfRange, "ILLEGAL PROGRAM NUMBER",
       "A program number outside 1-9999 (1-99999999 with 8-digit O numbers), or O0."},
      {AlarmId::ProgramNotFound, "PROGRAM NOT FOUND",
       "M98, G65, G66 or a code-triggered call names a program that is in no loaded file or "
       "library."},
      {AlarmId::TooManySubNesting, "TOO MANY SUB,MACRO NESTING",
       "More nested subprogram calls than the control allows."},
      {AlarmId::SequenceNotFound, "SEQUENCE NUMBER NOT FOUND",
       "M99 P names a sequence number that the "
       "caller lacks, or M98 Q one the called "
       "program lacks."},
      {AlarmId::IntegerOverflow, "OVERFLOW :INTEGER",
       "An integer value out of range (BIN, BCD, AND/OR/XOR, "
       "M/S/T/H/D values)."},
      {AlarmId::FloatOverflow, "OVERFLOW :FLOATING",
       "A result too large (EXP, POW, huge operands, NaN)."},
      {AlarmId::ZeroDivide, "ZERO DIVIDE", "Division by zero (also TAN of 90 degrees)."},
      {AlarmId::ImproperCommand, "IMPROPER COMMAND", "A function that cannot be used here."},
      {AlarmId::IllegalExpressionFormat, "ILLEGAL EXPRESSION FORMAT",
       "Bad expression syntax; a condition used as a value or a value used as a condition."},
      {AlarmId::VariableOutOfRange, "VARIABLE NO. OUT OF RANGE",
       "A variable number the control does not "
       "have."},
      {AlarmId::WriteProtectedVariable, "WRITE PROTECTED VARIABLE",
       "An assignment to #0 or to a read-only system variable."},
      {AlarmId::TooManyBrackets, "TOO MANY BRACKET NESTING",
       "More than five nested brackets, function brackets included."},
      {AlarmId::ArgumentOutOfRange, "ARGUMENT VALUE OUT OF RANGE",
       "A function argument outside its domain (SQRT of a negative, ASIN/ACOS beyond 1, LN of 0 or "
       "less, ...)."},
      {AlarmId::TooManyMacroNesting, "TOO MANY MACRO NESTING",
       "More nested macro calls (G65, G66, code calls) than the control allows."},
      {AlarmId::MissingEnd, "MISSING END STATEMENT",
       "A WHILE/DO without its END (found before running)."},
      {AlarmId::MacroStatementFormat, "MACRO STATEMENT FORMAT ERROR",
       "A macro statement that is not well formed (IF without GOTO/THEN, bad DPRNT, ...)."},
      {AlarmId::IllegalLoopNumber, "ILLEGAL LOOP NUMBER",
       "DO/END number outside 1-3, loops crossing, END without DO, or a jump into a loop."},
      {AlarmId::DuplicateNcMacro, "DUPLICATE NC,MACRO STATEMENT",
       "NC words and a macro statement in one "
       "block."},
      {AlarmId::IllegalMacroSequence, "ILLEGAL MACRO SEQUENCE NUMBER",
       "GOTO to a sequence number that is not in the program or out of 1-99999."},
      {AlarmId::GAsArgument, "USE 'G' AS ARGUMENT", "G used as an argument of G65/G66."},
      {AlarmId::IllegalScaleRate, "ILLEGAL SCALE RATE",
       "G51 scale factor (P, I, J, K or parameters 5411/5421) of 0 or out of range."},
      {AlarmId::IllegalPlaneForRotation, "ILLEGAL PLANE SELECTED",
       "Under G68 an arc, cutter compensation or a drilling cycle in a plane other than the "
       "rotation plane."},
      {AlarmId::IllegalSInRigidTap, "ILLEGAL S CODE COMMAND",
       "Rigid tapping (M29 before G84/G74, lathe G84/G88) with no spindle speed S."},
      {AlarmId::DirectDrawingPlane, "ILLEGAL PLANE SELECT",
       "Direct drawing dimensions (lathe ,A) outside the Z-X plane (G18)."},
      {AlarmId::OvertravelPlus, "+ OVERTRAVEL ( SOFT 1 )",
       "A move would pass an axis' upper stroke limit (axes.<X>.max); it is refused before it "
       "starts."},
      {AlarmId::OvertravelMinus, "- OVERTRAVEL ( SOFT 1 )",
       "A move would pass an axis' lower stroke limit (axes.<X>.min); it is refused before it "
       "starts."},
      {AlarmId::BlockLimit, "BLOCK LIMIT REACHED",
       "ncvm: the run executed more blocks than limits.max_blocks (runaway program)."},
      {AlarmId::TimeLimit, "TIME LIMIT REACHED",
       "ncvm: the simulated machine time passed limits.max_time_s (runaway program)."},
      {AlarmId::OutputError, "OUTPUT FILE ERROR",
       "ncvm: an output file (DPRNT, trace) could not be "
       "written."},
      {AlarmId::LineTooLong, "LINE TOO LONG", "ncvm: a block longer than limits.max_line_length."},
      {AlarmId::ProgramTooLarge, "PROGRAM TOO LARGE",
       "ncvm: a file larger than limits.max_file_bytes."},
      {AlarmId::SkipNotReceived, "SKIP SIGNAL NOT RECEIVED",
       "ncvm: a G31 touched nothing while probe.miss_alarm is set (a real control ends the move "
       "normally; the option makes a missed probe visible)."},
      {AlarmId::SignalNotGiven, "SIGNAL NOT IN SETUP",
       "ncvm: the program read an interface signal input (#1000-#1032) that the setup's [signals] "
       "does not give, while signals.missing = \"alarm\"."},
      {AlarmId::TraceLimit, "TRACE LIMIT REACHED",
       "ncvm: the trace grew past limits.max_trace_bytes."},
      {AlarmId::ProgramFileChanged, "PROGRAM FILE CHANGED",
       "ncvm: a streamed program's file was changed while it ran and ncvm had to read it again."},
      {AlarmId::NoProgramText, "NO PROGRAM IN FILE",
       "ncvm: the file holds no program text (empty, only '%', only leader or comments)."},
  };
  return table;
}

const char* alarmMessage(AlarmId id) {
  for (const auto& a : alarmTable())
    if (a.id == id) return a.message;
  return "ALARM";
}

std::string alarmCode(AlarmId id) {
  int n = static_cast<int>(id);
  return fmt::format("{}{:04d}", n >= 500 && n < 600 ? "OT" : "PS", n);
}

static std::string joinText(AlarmId id, const std::string& detail) {
  std::string t = alarmMessage(id);
  if (!detail.empty()) t += " (" + detail + ")";
  return t;
}

AlarmError::AlarmError(AlarmId id, std::string detail)
    : std::runtime_error(joinText(id, detail)), code_(alarmCode(id)), text_(joinText(id, detail)) {}

AlarmError::AlarmError(std::string code, std::string text)
    : std::runtime_error(text), code_(std::move(code)), text_(std::move(text)) {}

}  // namespace ncvm
