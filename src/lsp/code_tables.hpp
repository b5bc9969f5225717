#pragma once
// What the words of a Fanuc program mean, for hover and completion: M codes, address
// letters, and the macro variables (what each system variable holds). The G codes come
// from ncvm's own table (exec/gcode_table.hpp, which `ncvm codes` prints), so the editor
// says what the control does. Each table is built once.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "machine/setup.hpp"

namespace ncvm::lsp {

struct MCodeInfo {
  int code;
  const char* meaning;
};
// The M codes with a meaning the control (or every builder) gives them; other numbers are
// the machine builder's.
const std::vector<MCodeInfo>& mCodeTable();

// What the address letter means in an NC block ("" for none), for a mill or a lathe.
std::string addressMeaning(char letter, MachineKind kind);

// "G01: linear interpolation (feed) · group 01 · supported" for the setup's series, with the
// macro the setup calls for it (parameters 6050-6059); nullopt when the series has no such
// code and no call.
std::optional<std::string> describeGCode(int code10, const Setup& setup);
// "M98: subprogram call", with a setup's code calls (6071-6079, 6080-6089, 6004#... T).
std::string describeMCode(int code, const Setup& setup);

// A Custom Macro B keyword (GOTO, WHILE, EQ, SIN, DPRNT...): what it does; "" if none.
std::string keywordMeaning(const std::string& upperCaseWord);

// A range of macro variables that hold one kind of thing.
struct VariableRange {
  enum class Index : uint8_t {
    None,      // one meaning for the whole range
    Local,     // #1-#33: the G65 argument letter
    Axis,      // the n-th controlled axis (from - 1 + n)
    Row,       // the n-th offset number
    WorkTable  // 20 per table: G54.1 P(table) axis n
  };
  int64_t from, to;
  Index index;
  bool mill, lathe;  // machine kinds that have it
  bool writable;
  const char* holds;  // "machine position", "tool length (H) wear", ...
};
const std::vector<VariableRange>& variableTable();

// "#5021: machine position of axis 1 (X) · read-only"; nullopt when ncvm has no such
// variable on this machine.
std::optional<std::string> describeVariable(int64_t n, const Setup& setup);

}  // namespace ncvm::lsp
