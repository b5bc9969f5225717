#pragma once
// Fanuc-style alarms. One table (alarm.cpp) holds every number and message; docs/alarms.md
// is generated from it by `ncvm alarms`, so the two never drift apart.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/source.hpp"

namespace ncvm {

// Alarm numbers follow the 0i-D/0i-F/30i "PS" list; ncvm's own limits use PS9xxx, which no
// Fanuc control uses, so they cannot be mistaken for a control alarm.
enum class AlarmId : uint16_t {
  TooManyDigits = 3,
  NoDataAfterAddress = 5,
  IllegalMinus = 6,
  IllegalDecimalPoint = 7,
  ImproperAddress = 9,
  ImproperGCode = 10,
  FeedZero = 11,
  OverToleranceOfRadius = 20,
  IllegalPlaneSelect = 21,
  NoRadiusOrCenter = 22,
  CircleInRapid = 25,
  IllegalOffsetNumber = 30,
  IllegalPInG10 = 31,
  IllegalOffsetValueInG10 = 32,
  NoIntersectionCrc = 33,
  NoCircInStartupCancel = 34,
  CannotG31InCompensation = 35,
  CannotChangePlaneInCrc = 37,
  InterferenceInCircular = 38,
  ChamferInStartupCancel = 39,
  InterferenceInCrc = 41,
  G45G48InCrc = 42,
  G27to30InCycle = 44,
  QNotFound = 45,
  IllegalReferenceReturn = 46,
  // chamfer and corner rounding (,C ,R)
  MissingMoveAfterChamfer = 51,
  NotG01AfterChamfer = 52,
  ChamferMoveTooShort = 55,
  // lathe direct drawing dimensions (,A)
  NoEndPointAndAngle = 56,
  NoSolutionOfBlockEnd = 57,
  EndPointNotFound = 58,
  // lathe multiple repetitive cycles (G70-G76)
  CycleAddressPQNotFound = 61,
  CycleIllegalCommand = 62,
  CycleSequenceNotFound = 63,
  ShapeNotMonotonous = 64,
  ShapeFirstBlockNotG00G01 = 65,
  CycleUnavailableCommand = 66,
  CycleNotInMemory = 67,
  ShapeLastBlockIllegal = 69,
  ProgramNumberOutOfRange = 74,
  ReferenceCheckError = 92,
  ProgramNotFound = 76,
  TooManySubNesting = 77,
  SequenceNotFound = 78,
  IntegerOverflow = 110,
  FloatOverflow = 111,
  ZeroDivide = 112,
  ImproperCommand = 113,
  IllegalExpressionFormat = 114,
  VariableOutOfRange = 115,
  WriteProtectedVariable = 116,
  TooManyBrackets = 118,
  ArgumentOutOfRange = 119,
  TooManyMacroNesting = 122,
  MissingEnd = 124,
  MacroStatementFormat = 125,
  IllegalLoopNumber = 126,
  DuplicateNcMacro = 127,
  IllegalMacroSequence = 128,
  GAsArgument = 129,
  IllegalScaleRate = 142,
  IllegalPlaneForRotation = 144,
  IllegalSInRigidTap = 200,
  DirectDrawingPlane = 212,
  OvertravelPlus = 500,   // shown as OT0500
  OvertravelMinus = 501,  // shown as OT0501
  // ncvm limits and environment
  BlockLimit = 9001,
  TimeLimit = 9002,
  OutputError = 9003,
  LineTooLong = 9004,
  ProgramTooLarge = 9005,
  TraceLimit = 9006,
  ProgramFileChanged = 9007,
  NoProgramText = 9008,
  SkipNotReceived = 9010,
  SignalNotGiven = 9011,
};

struct AlarmInfo {
  AlarmId id;
  const char* message;  // the control's message text
  const char* meaning;  // one line for docs/alarms.md
};

const std::vector<AlarmInfo>& alarmTable();
const char* alarmMessage(AlarmId id);
std::string alarmCode(AlarmId id);  // "PS0112"

struct Alarm {
  std::string code;  // "PS0112", "MC3001"
  std::string text;  // message shown by the control (plus ncvm's detail, if any)
  SourceLoc loc;
  std::optional<int64_t> n;  // N number of the block, if it had one
  int32_t program = -1;      // O number, -1 if unknown
};

// Thrown inside the control and caught at the run loop; alarms are rare, so exceptions cost
// nothing on the normal path.
class AlarmError : public std::runtime_error {
 public:
  AlarmError(AlarmId id, std::string detail = {});
  AlarmError(std::string code, std::string text);  // macro alarm (#3000)
  const std::string& code() const { return code_; }
  const std::string& text() const { return text_; }
  // Location inside the block (column), 0 = use the block's start.
  uint32_t col = 0;
  // Set when the alarm belongs to another block than the one executing (structural errors
  // found before running, syntax errors stored at compile time).
  bool hasLoc = false;
  SourceLoc loc;
  int64_t n = -1;

 private:
  std::string code_;
  std::string text_;
};

}  // namespace ncvm
