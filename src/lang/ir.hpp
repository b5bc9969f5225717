#pragma once
// The compiled form of a Fanuc program. A program is compiled once into flat arrays: blocks,
// words, expression bytecode and constants. WHILE/DO/END and literal GOTO targets are
// resolved at compile time; the executor never looks at program text again.
#include <cstdint>
#include <string>
#include <vector>

#include "core/alarm.hpp"
#include "core/source.hpp"

namespace ncvm {

// Expression bytecode for a small stack machine. Each instruction keeps its column so a
// run-time error (zero divide) points at the operator.
enum class Op : uint8_t {
  Const,   // push consts[arg]
  Var,     // push variable #arg
  VarInd,  // pop n, push variable #n
  Neg,
  Add,
  Sub,
  Mul,
  Div,
  Mod,
  And,
  Or,
  Xor,  // bitwise on integer values
  LAnd,
  LOr,
  LXor,  // logical on conditions (30i [[a]AND[b]])
  Eq,
  Ne,
  Gt,
  Ge,
  Lt,
  Le,
  Fn1,  // one-argument function, fn = Fn id
  Fn2,  // two-argument function (ATAN[a]/[b], ATAN[a,b], POW[a,b])
};

enum class Fn : uint8_t {
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Atan2,
  Sqrt,
  Abs,
  Bin,
  Bcd,
  Round,
  Fix,
  Fup,
  Ln,
  Exp,
  Pow,
  Adp,
};

struct Instr {
  Op op;
  Fn fn = Fn::Sin;
  uint16_t col = 0;
  int32_t arg = 0;
};

struct ExprRange {
  uint32_t begin = 0;  // into Program::code
  uint32_t end = 0;
};

// How an address word gets its value.
enum class WordKind : uint8_t {
  Literal,  // number as written; flag HasPoint says whether it had a decimal point
  Var,      // X#12: variable number in `a` (vacant drops the word)
  NegVar,   // X-#12
  Expr,     // X[...] or X#[...]: expression index in `a`; result counts as "with point"
};

enum WordFlags : uint8_t {
  kHasPoint = 1,  // literal written with a decimal point
  // A literal dimension word (X Y Z U V W A B C I J K R Q) of 999.99999 or more: it may have
  // more than 8 digits in increments (PS0003), which the executor checks once the unit is known.
  kLongNumber = 2,
  // A minus sign on a letter that takes none (P M S T H D L G): PS0006 unless the block is a
  // G65/G66 macro call, where the letter is a signed argument.
  kHasMinus = 4,
};

// Block flags (Block::flags), set by the compiler.
enum BlockFlags : uint8_t {
  // Only literal words, each letter once, of G00/G01/G02/G03 (at most one G) and X Y Z F I J
  // K R, none of them long enough to need the digit-count check: the executor's plain-motion
  // path reads such a block's words directly (it still checks the modal state).
  kPlainBlock = 1,
};

// Letters are 'A'..'Z'; the 30i comma words ,C and ,R are stored as 'c' and 'r' (the lathe's ,A as
// 'a'). 16 bytes: a literal needs only `value`, every other kind only `a`, so they share the
// storage (a 1,000,000-line CAM program holds 3,000,000 words).
struct Word {
  char letter = 0;
  WordKind kind = WordKind::Literal;
  uint8_t flags = 0;
  uint16_t col = 0;
  union {
    double value = 0.0;  // Literal
    int32_t a;           // Var/NegVar: variable number; Expr: expression index; '<': string
  };
};

enum class BlockKind : uint8_t {
  Empty,   // nothing but N, comments, or a program header
  Nc,      // NC words
  Assign,  // #a = expr        (lhsVar >= 0) or #[expr] = expr (lhsExpr >= 0)
  If,      // IF [cond] GOTO target | IF [cond] THEN assignment
  Goto,    // GOTO target
  While,   // WHILE [cond] DO m  (cond < 0: plain DO m)
  End,     // END m
  Print,   // DPRNT / BPRNT
  Popen,
  Pclos,
  Error,  // a block the compiler rejected: executing it raises `error`
};

enum class PrintKind : uint8_t { Dprnt, Bprnt };

struct PrintItem {
  bool isVar = false;
  std::string text;   // literal characters (`*` already turned into a space)
  int32_t expr = -1;  // variable item: expression index
  uint8_t intDigits = 0, fracDigits = 0;
};

// Operands of the macro statements (and the error of an Error block), kept apart from Block
// so the NC blocks that make up nearly all of a CAM program stay small (-1 = unused).
struct MacroOps {
  int32_t cond = -1;        // condition expression (If, While)
  int32_t lhsVar = -1;      // Assign: literal variable number
  int32_t lhsExpr = -1;     // Assign: indirect variable expression
  int32_t rhs = -1;         // Assign: value expression
  int32_t gotoLabel = -1;   // If/Goto: literal sequence number
  int32_t gotoExpr = -1;    // If/Goto: computed target expression
  int32_t target = -1;      // resolved block index (Goto/If literal target; While: after END;
                            // End: its While)
  bool thenAssign = false;  // If: THEN form (uses lhs*/rhs)
  PrintKind printKind = PrintKind::Dprnt;
  uint32_t firstPrint = 0, nPrint = 0;  // into Program::prints
  int32_t error = -1;                   // Error: index into Program::errors
};

struct Block {
  BlockKind kind = BlockKind::Empty;
  uint8_t skipLevel = 0;  // 0 = no '/', 1..9 = '/' or '/n'
  uint8_t loopId = 0;     // While/End: m
  uint8_t flags = 0;      // BlockFlags
  uint16_t nWords = 0;
  uint32_t firstWord = 0;
  SourceLoc loc;         // start of the block
  int32_t n = -1;        // sequence number, -1 = none
  int32_t comment = -1;  // index into Program::strings of the block's first comment
  int32_t ops = -1;      // index into Program::macroOps; -1 for NC and empty blocks
};
// 36 bytes: a 1,000,000-line CAM program holds 1,000,000 blocks (the enclosing loop of each,
// which only programs with loops or GOTOs need, is Program::loopParents).

class ProgramStream;

struct Program {
  int32_t number = -1;  // O number; -1 for a file without O header
  std::string name;     // <name> programs, or the file stem for anonymous ones
  std::string label;    // how traces and alarms name it: "O0100" or the name
  SourceLoc loc;        // header location
  std::vector<Block> blocks;
  std::vector<Word> words;
  std::vector<MacroOps> macroOps;  // the macro and error blocks' operands (Block::ops)
  std::vector<Instr> code;
  std::vector<double> consts;
  std::vector<ExprRange> exprs;
  std::vector<PrintItem> prints;
  std::vector<std::string> strings;  // comments
  std::vector<Alarm> errors;         // block-level syntax errors (raised when reached)
  std::vector<Alarm> structural;     // DO/END and label errors (raised before running)
  // Indices into `errors` of WHILE blocks (not block-skippable) that failed to compile: their
  // DO is lost, so a structural error about its END is a consequence of the WHILE's error.
  std::vector<int32_t> lostLoops;
  // Sequence numbers in program order: (N, block index).
  std::vector<std::pair<int32_t, uint32_t>> labels;
  // Per block, the index of the innermost enclosing While block (-1: none). Filled by
  // resolveStructure, which runs only for a program with a WHILE, END, GOTO or IF block;
  // empty otherwise, when no block has one.
  std::vector<int32_t> loopParents;
  // Set while the program is streamed (program_stream.hpp): the arrays above then hold only
  // the piece that runs, from block stream->base() on. The executor moves it on at the end of
  // a piece and asks for the whole program before it needs any other block.
  ProgramStream* stream = nullptr;

  std::string displayName() const;
  // A block's macro operands; all -1 for a block that has none.
  const MacroOps& ops(const Block& b) const {
    static const MacroOps none;
    return b.ops >= 0 ? macroOps[static_cast<size_t>(b.ops)] : none;
  }
  MacroOps& ops(Block& b) { return macroOps[static_cast<size_t>(b.ops)]; }
  // The innermost While block around block k, -1 if none.
  int32_t loopParent(size_t k) const { return loopParents.empty() ? -1 : loopParents[k]; }
  // Block index of the first block with sequence number n at or after `from`, then from the
  // start (the control's search order); -1 if none.
  int32_t findLabel(int32_t n, uint32_t from = 0) const;
};

}  // namespace ncvm
