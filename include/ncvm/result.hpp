#pragma once
// What a run or a check of ncvm reports: how the program ended, the alarm that stopped it,
// the warnings, the run's totals and the end state (the --state JSON of docs/trace-format.md).
// Plain values: they stay valid after the Job that made them is gone.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncvm/export.hpp"

namespace ncvm::api {

// A place in a program file: 1-based line and column, as the alarm lines print them.
struct Location {
  std::string file;  // the file name as loaded (<text> or the name given for program text)
  int line = 0;
  int column = 0;
};

// A Fanuc-style alarm: code "PS0112", "MC3001" (#3000), "OT0500"; the control's message.
struct Alarm {
  std::string code;
  std::string message;
  Location where;
  std::optional<int64_t> n;  // the N number of the block, when it had one
};

// A warning: ncvm's W codes (W001 decimal point, W002 word twice, ...), or the code of an
// alarm that `check` can only say may happen. The code is empty for what loading the
// programs found (a duplicate program, text after the closing %), which has no place.
struct Warning {
  std::string code;
  std::string message;
  Location where;
};

enum class EndReason { M30, M02, M99, Alarm, EndOfFile, Limit };
// The name ncvm prints after "ended:" (M30, M02, M99, alarm, end of file, limit).
NCVM_API std::string endReasonName(EndReason reason);

struct RunStats {
  uint64_t blocks = 0;
  uint64_t moves = 0;
  double rapidLength = 0;  // program units
  double feedLength = 0;   // program units
  double simpleTime = 0;   // seconds: length / feed, rapids at the rapid rates
  // seconds, the cycle-time model (setup [timing] dynamic = true); empty when it was off
  std::optional<double> modelledTime;
};

struct RunResult {
  EndReason end = EndReason::EndOfFile;
  std::optional<Alarm> alarm;     // set exactly when end == EndReason::Alarm
  std::vector<Warning> warnings;  // found while running
  RunStats stats;
  std::string stateJson;  // the end state, as `ncvm run --state` writes it
  std::string printed;    // DPRNT/BPRNT output
};

struct CheckResult {
  std::vector<Alarm> alarms;      // what will stop the program (syntax, labels, ...)
  std::vector<Warning> warnings;  // what may be wrong
  std::string json;               // as `ncvm check --json` prints it
  bool ok() const { return alarms.empty(); }
};

}  // namespace ncvm::api
