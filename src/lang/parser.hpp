#pragma once
// Fanuc program text -> compiled programs (ir.hpp), one pass per file.
//
// A block the compiler rejects becomes an Error block: the alarm is raised when execution
// reaches it, as on the control, and `ncvm check` lists it. Loop and label errors
// (Program::structural) are found after the whole program is read, before anything runs.
#include <array>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "lang/ir.hpp"

namespace ncvm {

struct ParseOptions {
  uint32_t maxLineLength = 0;  // 0 = no limit; longer blocks become PS9004 Error blocks
  bool eightDigitO = false;    // O numbers up to 99999999 (0i-F/30i option)
  // A lathe with a C axis: H is the incremental C address, a dimension that takes a decimal
  // point and a sign (`G28 H0.0`, `H-5.`).
  bool hIsAxis = false;
  // Plain lines through the one-pass fast path (fast_block.hpp). Tests turn it off to check
  // that both ways compile every line to the same Program.
  bool fastLines = true;
  // Compiled one piece at a time with its blocks dropped in between (a streamed program,
  // program_stream.hpp): the arrays are sized for a piece, not for the file.
  bool piecewise = false;
  // The optional block skip switches ([1]..[9], Setup::blockSkip). A '/' after the head of an
  // NC block ("G43 H6 Z.25 /M8", as CAM posts write it) skips the rest of the block when its
  // switch is on, which the compiler decides: the switches are fixed for a run.
  std::array<bool, 10> blockSkip{};
  // G and M codes that call a macro (parameters 6050-6059 and 6080-6089; 0 = none): their
  // blocks are macro calls like G65, so D H M S T there are signed arguments that take a
  // point (`G100 D-2.`), which the compiler must know when it checks signs and points.
  std::array<int, 10> callG{};
  std::array<int, 10> callM{};
};

struct ParsedFile {
  std::vector<Program> programs;
  uint32_t fastLines = 0;  // lines the fast path compiled (blank ones included)
  // Text after the closing '%' is not read (the tape ends there): the first line of it that
  // holds more than spaces and filler bytes (NUL, DOS EOF 0x1A, DEL), 0 when none does.
  uint32_t unreadLine = 0;
};

// `stem` names the anonymous program of a file that has no O header.
ParsedFile parseProgramText(std::string_view text, uint32_t fileId, std::string_view stem,
                            const ParseOptions& options = {});

// The same for text given in pieces of whole lines (a file read through a reused buffer):
// the result is parseProgramText's on the whole text.
class LineChunks;
ParsedFile parseProgramChunks(LineChunks& chunks, uint32_t fileId, std::string_view stem,
                              const ParseOptions& options = {});

// The same compiler driven one piece at a time (a streamed program): after the first pieces
// the caller may move the program out of parsed() and have later pieces compiled into it.
class PieceCompiler {
 public:
  PieceCompiler(LineChunks& chunks, uint32_t fileId, std::string_view stem,
                const ParseOptions& options);
  ~PieceCompiler();
  bool next();  // compiles the next piece; false at the end of the text
  ParsedFile& parsed();
  void continueInto(Program& p);
  bool hasControlFlow() const;  // the open program has a WHILE, END, GOTO or IF block
  // The open program has no header and nothing but comments yet: an O header that follows
  // replaces it (a title comment before the O number is not a program of its own).
  bool onlyComments() const;
  uint32_t line() const;  // lines compiled so far

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Resolves WHILE/DO/END pairs and literal GOTO targets; fills Program::structural.
void resolveStructure(Program& program);

}  // namespace ncvm
