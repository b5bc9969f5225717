#include "lang/parser.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>

#include "lang/address_letters.hpp"
#include "lang/count_lines.hpp"
#include "lang/decimal_scan.hpp"
#include "lang/fast_block.hpp"
#include "lang/huge_pages.hpp"
#include "lang/line_chunks.hpp"

namespace ncvm {
namespace {

constexpr int kMaxBracketNesting = 5;  // fanuc-reference B.3: five levels, functions included

enum class Type : uint8_t { Num, Bool };

bool isUpper(char c) {
  return c >= 'A' && c <= 'Z';
}
bool isLower(char c) {
  return c >= 'a' && c <= 'z';
}
bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
// What may follow the closing '%' without being program text: spaces, and the bytes tape
// readers and DOS tools add (NUL feed, DEL, SUB = the DOS end-of-file mark 0x1A).
bool isFiller(char c) {
  return isSpace(c) || c == '\0' || c == '\x1a' || c == '\x7f';
}
bool onlyFiller(std::string_view s) {
  return std::all_of(s.begin(), s.end(), isFiller);
}
// A UTF-8 byte-order mark, which editors put at the start of a file: not program text.
constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
// A program made of comment blocks only (a title before the O number).
bool commentsOnly(const Program& p) {
  return p.errors.empty() && std::all_of(p.blocks.begin(), p.blocks.end(), [](const Block& b) {
           return b.kind == BlockKind::Empty && b.n < 0 && b.skipLevel == 0;
         });
}

using letters::forbidsMinus;
using letters::forbidsPoint;
using letters::isDimension;
using letters::plainWord;

// Exact powers of ten: every one up to 10^22 is a double without rounding.
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

struct FnName {
  const char* name;
  Fn fn;
};
constexpr FnName kFunctions[] = {
    {"SIN", Fn::Sin},     {"COS", Fn::Cos},   {"TAN", Fn::Tan},  {"ASIN", Fn::Asin},
    {"ACOS", Fn::Acos},   {"ATAN", Fn::Atan}, {"ATN", Fn::Atan}, {"SQRT", Fn::Sqrt},
    {"SQR", Fn::Sqrt},    {"ABS", Fn::Abs},   {"BIN", Fn::Bin},  {"BCD", Fn::Bcd},
    {"ROUND", Fn::Round}, {"RND", Fn::Round}, {"FIX", Fn::Fix},  {"FUP", Fn::Fup},
    {"LN", Fn::Ln},       {"EXP", Fn::Exp},   {"POW", Fn::Pow},  {"ADP", Fn::Adp},
};

class Compiler {
 public:
  Compiler(LineChunks& chunks, uint32_t file, std::string_view stem, const ParseOptions& opt)
      : chunks_(chunks), file_(file), stem_(stem), opt_(opt) {}

  ParsedFile run();
  bool onlyComments() const { return prog_ && headerless_ && commentsOnly(*prog_); }
  // Piece by piece (PieceCompiler): compiles the next piece; false at the end of the text.
  bool nextPiece() {
    s_ = chunks_.next();
    if (s_.empty()) return false;
    compilePiece();
    return true;
  }
  ParsedFile& parsed() { return out_; }
  void continueInto(Program& p) { prog_ = &p; }
  bool hasControlFlow() const { return hasControlFlow_; }
  uint32_t line() const { return line_; }

 private:
  // ---- text position -------------------------------------------------------------------
  LineChunks& chunks_;
  std::string_view s_;  // the piece of whole lines being compiled; positions index it
  uint32_t file_;
  std::string_view stem_;
  ParseOptions opt_;
  // The address rules of letters.hpp for this machine: these members hide the namespace
  // functions in every check of the compiler (a lathe's H with a C axis is a dimension).
  bool forbidsPoint(char letter) const {
    return letters::forbidsPoint(letter) && !(opt_.hIsAxis && letter == 'H');
  }
  bool forbidsMinus(char letter) const {
    return letters::forbidsMinus(letter) && !(opt_.hIsAxis && letter == 'H');
  }
  size_t i_ = 0, end_ = 0, lineStart_ = 0;
  uint32_t line_ = 0;

  ParsedFile out_;
  Program* prog_ = nullptr;
  Block blk_;
  MacroOps ops_;               // the macro operands of blk_ (stored only for macro blocks)
  int depth_ = 0;              // bracket nesting inside the current expression
  bool sawStatement_ = false;  // a macro statement is in this block
  bool inWhile_ = false;       // the block's WHILE is being compiled
  uint16_t ncWords_ = 0;
  bool sawHeaderComment_ = false;
  bool hasControlFlow_ = false;  // the open program has a WHILE, END, GOTO or IF block
  bool headerless_ = false;      // the open program was opened by a block, not by a header
  bool firstPiece_ = true;
  // Tape format (F16TB-MC, F30i-DS in docs/fanuc-decisions.md): "%", leader, programs, "%".
  // The text before the first '%' is leader; the closing '%' ends the text. A text whose only
  // '%' has nothing after it was the program and its tape end (a file without the leading
  // '%'): what was compiled before that '%' is kept aside until the end shows which it was.
  enum class Tape : uint8_t { Before, Inside, Done };
  Tape tape_ = Tape::Before;
  ParsedFile leader_;
  bool leaderOnlyComments_ = false;  // leader_ is one header-less program of comments
  uint32_t firstMarkLine_ = 0;

  uint32_t col() const { return static_cast<uint32_t>(i_ - lineStart_ + 1); }
  char peek(size_t k = 0) const { return i_ + k < end_ ? s_[i_ + k] : '\0'; }
  bool atEnd() const { return i_ >= end_; }
  void skipSpaces() {
    while (i_ < end_ && isSpace(s_[i_])) ++i_;
  }
  [[noreturn]] void fail(AlarmId id, std::string detail = {}, uint32_t at = 0) const {
    AlarmError e(id, std::move(detail));
    e.col = at ? at : col();
    throw e;
  }

  // ---- programs and blocks --------------------------------------------------------------
  Program& ensureProgram() {
    if (!prog_) {
      startProgram(-1, std::string(stem_), SourceLoc{file_, line_, 1});
      headerless_ = true;
    }
    return *prog_;
  }
  // Loops and literal GOTOs are resolved once a program is complete; a program without any
  // (a CAM program) has nothing to resolve: no block has a loop parent (loopParents empty).
  void finishProgram() {
    if (prog_ && hasControlFlow_) resolveStructure(*prog_);
    hasControlFlow_ = false;
  }
  void startProgram(int32_t number, std::string name, SourceLoc loc) {
    // Comments before the first header ("%", "(PART NAME)", "O0001") are leader, not a
    // header-less program that would run instead of O0001.
    if (onlyComments() && !out_.programs.empty() && prog_ == &out_.programs.back()) {
      out_.programs.pop_back();
      prog_ = nullptr;
    }
    headerless_ = false;
    finishProgram();
    out_.programs.emplace_back();
    prog_ = &out_.programs.back();
    if (out_.programs.size() == 1 && opt_.piecewise) {
      // A streamed program holds one piece's blocks at a time.
      const size_t lines = countNewlines(s_) + 1;
      prog_->blocks.reserve(lines);
      prog_->words.reserve(lines * 3);
    } else if (out_.programs.size() == 1) {
      // Most files hold one program: size its arrays from the text once, so a large CAM
      // file is never copied while its arrays grow.
      const size_t lines = chunks_.lineHint();
      prog_->blocks.reserve(lines);
      prog_->words.reserve(lines * 3);
      adviseHugePages(prog_->blocks.data(), prog_->blocks.capacity() * sizeof(Block));
      adviseHugePages(prog_->words.data(), prog_->words.capacity() * sizeof(Word));
    }
    prog_->number = number;
    prog_->name = std::move(name);
    prog_->loc = loc;
    sawHeaderComment_ = false;
  }
  void compilePiece();
  void finish();
  void skipUnread(size_t pos);
  size_t tapeMark(size_t after, size_t e);
  void addNoProgram();
  void parseLine(size_t b, size_t e);
  void parseBlock(size_t b, size_t e);
  bool parseHeader();
  void parseStatements();
  void parseComment();
  void parseWord();
  void parseCommaWord();
  void parseAssign(bool asThen);
  void parseIf();
  void parseGotoTarget();
  void parseWhile();
  void parseDo(int32_t cond);
  void parseEnd();
  void parsePrint(PrintKind kind);
  void beginStatement(uint32_t at);
  void commitBlock();

  // ---- expressions ----------------------------------------------------------------------
  int32_t compileExpr(Type want, uint32_t at);  // full expression -> index into exprs
  Type parseRel();
  Type parseSum();
  Type parseTerm();
  Type parseUnary();
  Type parsePrimary();
  Op typedOp(Op op, Type a, Type b, uint32_t at) const;
  Type parseBracket();
  void parseVarRef();  // after '#'
  bool peekKeyword(const char* kw) const;
  // Offset of the letter of a ",C"/",R" word at the ',' here: spaces may follow the comma
  // ("G01 X50., R5.").
  size_t commaLetter() const {
    size_t k = 1;
    while (isSpace(peek(k))) ++k;
    return k;
  }
  size_t letterRun() const {
    size_t k = 0;
    while (isUpper(peek(k))) ++k;
    return k;
  }
  void emit(Op op, uint32_t at, int32_t arg = 0, Fn fn = Fn::Sin) {
    prog_->code.push_back(Instr{op, fn, static_cast<uint16_t>(at > 0xffff ? 0xffff : at), arg});
  }
  int32_t addConst(double v) {
    prog_->consts.push_back(v);
    return static_cast<int32_t>(prog_->consts.size() - 1);
  }
  double parseNumberText(bool& hasPoint, int& intDigits);
  double parseNumberSlow(bool& hasPoint, int& intDigits);
  // The last number read has more digits than a double can hold (1 and 309 zeros, or 400
  // fraction digits): its caller raises PS0003 where it raises its other digit alarms.
  bool numberTooLong_ = false;
  bool operatorAt(const char* kw) const;
};

ParsedFile Compiler::run() {
  for (s_ = chunks_.next(); !s_.empty(); s_ = chunks_.next()) compilePiece();
  finish();
  return std::move(out_);
}

void Compiler::finish() {
  finishProgram();
  const bool onlyCommentsOpen = out_.programs.size() == 1 && onlyComments();
  if (tape_ != Tape::Before && !leader_.programs.empty() &&
      (out_.programs.empty() || onlyCommentsOpen)) {
    // The only '%' had nothing after it: it was the tape end of the program before it.
    const uint32_t unread = out_.unreadLine;
    out_ = std::move(leader_);
    out_.unreadLine = unread;
    prog_ = nullptr;
    if (leaderOnlyComments_) out_.programs.clear();
  } else if (onlyCommentsOpen) {
    out_.programs.clear();  // nothing but comments is no program either
  }
  if (out_.programs.empty()) addNoProgram();
}

// A text without a program (empty, "%" alone, only leader) is one program whose only block
// raises PS9008 where the text is: a run of it stops with an alarm, `ncvm check` lists it.
void Compiler::addNoProgram() {
  const SourceLoc loc{file_, std::max<uint32_t>(firstMarkLine_, 1), 1};
  out_.programs.emplace_back();
  Program& p = out_.programs.back();
  p.name = std::string(stem_);
  p.loc = loc;
  p.errors.push_back(Alarm{alarmCode(AlarmId::NoProgramText),
                           std::string(alarmMessage(AlarmId::NoProgramText)), loc, std::nullopt,
                           -1});
  p.macroOps.push_back(MacroOps{});
  p.macroOps.back().error = 0;
  Block b;
  b.kind = BlockKind::Error;
  b.loc = loc;
  b.ops = 0;
  p.blocks.push_back(b);
}

void Compiler::compilePiece() {
  size_t pos = 0;
  if (firstPiece_) {
    firstPiece_ = false;
    if (s_.starts_with(kUtf8Bom)) pos = kUtf8Bom.size();  // columns count from after it
  }
  const char* const text = s_.data();
  // Once a program is open, a plain line (nearly every line of a CAM program) is compiled in
  // one pass, if a '\n' ends it (the scan stops there); a line with a '%' is never plain.
  const size_t lastNewline = s_.rfind('\n');
  const size_t fastBefore =
      !opt_.fastLines || lastNewline == std::string_view::npos ? 0 : lastNewline + 1;
  while (pos < s_.size()) {
    if (tape_ == Tape::Done) return skipUnread(pos);
    if (prog_ && pos < fastBefore) {
      pos = static_cast<size_t>(compileFastLines(text + pos, text + fastBefore, file_, line_,
                                                 opt_.maxLineLength, *prog_, out_.fastLines) -
                                text);
      if (pos >= s_.size()) break;
    }
    ++line_;
    size_t nl = s_.find('\n', pos);
    size_t e = nl == std::string_view::npos ? s_.size() : nl;
    lineStart_ = pos;
    parseLine(pos, e);
    pos = e + 1;
  }
}

// The lines after the closing '%' are not read; they still count, and the first one holding
// something is noted (the store warns about it).
void Compiler::skipUnread(size_t pos) {
  while (pos < s_.size()) {
    ++line_;
    size_t nl = s_.find('\n', pos);
    size_t e = nl == std::string_view::npos ? s_.size() : nl;
    if (!out_.unreadLine && !onlyFiller(s_.substr(pos, e - pos))) out_.unreadLine = line_;
    pos = e + 1;
  }
}

// A '%' outside a comment at after - 1. Returns where the line goes on being compiled.
size_t Compiler::tapeMark(size_t after, size_t e) {
  if (tape_ == Tape::Inside) {
    tape_ = Tape::Done;  // the tape end: nothing after it is read
    if (!onlyFiller(s_.substr(after, e - after))) out_.unreadLine = line_;
    return e;
  }
  if (tape_ == Tape::Done) return e;
  // The first '%': what was compiled before it is leader (kept aside: finish()).
  finishProgram();
  leaderOnlyComments_ = out_.programs.size() == 1 && onlyComments();
  leader_ = std::move(out_);
  out_ = ParsedFile{};
  prog_ = nullptr;
  headerless_ = false;
  sawHeaderComment_ = false;
  tape_ = Tape::Inside;
  firstMarkLine_ = line_;
  // The rest of its line is a title ("% TITLE", F30i-DS), unless a program header starts
  // there ("%O1200(TITLE)").
  size_t k = after;
  while (k < e && isSpace(s_[k])) ++k;
  const bool header =
      k < e &&
      (s_[k] == '<' || ((s_[k] == 'O' || s_[k] == ':') && k + 1 < e && isDigit(s_[k + 1])));
  return header ? k : e;
}

void Compiler::parseLine(size_t b, size_t e) {
  // Most lines hold none of '(', ';' and '%': three memchr calls find that out quickly.
  const void* line = s_.data() + b;
  if (!std::memchr(line, '(', e - b) && !std::memchr(line, ';', e - b) &&
      !std::memchr(line, '%', e - b)) {
    parseBlock(b, e);
    return;
  }
  // Split at ';' (the EOB of printed listings) and '%' outside comments.
  size_t start = b;
  bool inComment = false;
  for (size_t k = b; k < e; ++k) {
    char c = s_[k];
    if (inComment) {
      if (c == ')') inComment = false;
      continue;
    }
    if (c == '(') {
      inComment = true;
    } else if (c == ';') {
      parseBlock(start, k);
      start = k + 1;
    } else if (c == '%') {
      parseBlock(start, k);
      start = tapeMark(k + 1, e);
      if (tape_ == Tape::Done) return;
      k = start - 1;
    }
  }
  parseBlock(start, e);
}

void Compiler::parseBlock(size_t b, size_t e) {
  i_ = b;
  end_ = e;
  skipSpaces();
  if (atEnd()) return;
  // After the leading '%', before any program: filler bytes (a DOS end-of-file mark after a
  // file's only '%', which is then its tape end) are not a block.
  if (!prog_ && tape_ == Tape::Inside && onlyFiller(s_.substr(i_, e - i_))) return;
  blk_ = Block{};
  ops_ = MacroOps{};
  blk_.loc = SourceLoc{file_, line_, col()};
  sawStatement_ = false;
  inWhile_ = false;
  ncWords_ = 0;
  size_t wordsBefore = prog_ ? prog_->words.size() : 0;
  try {
    if (opt_.maxLineLength && e - b > opt_.maxLineLength)
      fail(AlarmId::LineTooLong, "block longer than " + std::to_string(opt_.maxLineLength));
    if (parseHeader()) return;
    Program& p = ensureProgram();
    blk_.firstWord = static_cast<uint32_t>(p.words.size());
    if (peek() == '/') {
      ++i_;
      blk_.skipLevel = 1;
      if (peek() >= '1' && peek() <= '9') blk_.skipLevel = static_cast<uint8_t>(peek() - '0'), ++i_;
      skipSpaces();
    }
    if (peek() == 'N' && isDigit(peek(1))) {
      ++i_;
      uint32_t at = col();
      int64_t n = 0;
      int digits = 0;
      // The value saturates: more than 8 digits is an alarm anyway.
      while (isDigit(peek()))
        n = std::min<int64_t>(n * 10 + (peek() - '0'), 999999999), ++i_, ++digits;
      if (peek() == '.') fail(AlarmId::IllegalDecimalPoint, "in N", at);
      if (digits > 8) fail(AlarmId::TooManyDigits, "N", at);
      blk_.n = static_cast<int32_t>(n);
    }
    parseStatements();
    commitBlock();
  } catch (const AlarmError& err) {
    Program& p = ensureProgram();
    p.words.resize(std::max(wordsBefore, static_cast<size_t>(blk_.firstWord)));
    Alarm a{err.code(), err.text(), SourceLoc{file_, line_, err.col ? err.col : blk_.loc.col},
            blk_.n >= 0 ? std::optional<int64_t>(blk_.n) : std::nullopt, p.number};
    p.errors.push_back(std::move(a));
    if (inWhile_ && blk_.skipLevel == 0)
      p.lostLoops.push_back(static_cast<int32_t>(p.errors.size() - 1));
    Block bad = blk_;
    bad.kind = BlockKind::Error;
    bad.nWords = 0;
    bad.flags = 0;
    MacroOps badOps;
    badOps.error = static_cast<int32_t>(p.errors.size() - 1);
    p.macroOps.push_back(badOps);
    bad.ops = static_cast<int32_t>(p.macroOps.size() - 1);
    if (bad.n >= 0) p.labels.emplace_back(bad.n, static_cast<uint32_t>(p.blocks.size()));
    p.blocks.push_back(bad);
  }
}

// "Onnnn", ":nnnn" or "<name>" at the head of a block starts a program.
bool Compiler::parseHeader() {
  char c = peek();
  bool numbered = (c == 'O' || c == ':') && isDigit(peek(1));
  if (!numbered && c != '<') return false;
  SourceLoc loc{file_, line_, col()};
  if (numbered) {
    ++i_;
    int64_t n = 0;
    size_t first = i_;
    int64_t max = opt_.eightDigitO ? 99999999 : 9999;
    // Past the limit the value no longer matters (and would overflow): it stays max + 1.
    while (isDigit(peek())) n = std::min(n * 10 + (peek() - '0'), max + 1), ++i_;
    // Four digits is the classic limit; leading zeros do not count.
    if (n == 0 || n > max) {
      startProgram(-1, std::string(stem_), loc);
      std::string digits(s_.substr(first, std::min<size_t>(i_ - first, 20)));
      fail(AlarmId::ProgramNumberOutOfRange, "O" + digits + (i_ - first > 20 ? "..." : ""),
           loc.col);
    }
    startProgram(static_cast<int32_t>(n), {}, loc);
  } else {
    size_t close = s_.find('>', i_);
    if (close == std::string_view::npos || close >= end_) return false;
    std::string name(s_.substr(i_ + 1, close - i_ - 1));
    i_ = close + 1;
    startProgram(-1, name, loc);
  }
  // The rest of a header line is its title comment.
  skipSpaces();
  while (!atEnd()) {
    if (peek() == '(') {
      parseComment();
    } else {
      // Anything else after a program number is an ordinary block on the same line.
      blk_ = Block{};
      ops_ = MacroOps{};
      blk_.loc = SourceLoc{file_, line_, col()};
      blk_.firstWord = static_cast<uint32_t>(prog_->words.size());
      parseStatements();
      commitBlock();
      return true;
    }
    skipSpaces();
  }
  return true;
}

void Compiler::parseComment() {
  size_t close = s_.find(')', i_);
  size_t stop = (close == std::string_view::npos || close >= end_) ? end_ : close;
  if (blk_.comment < 0 && prog_) {
    prog_->strings.emplace_back(s_.substr(i_ + 1, stop - i_ - 1));
    blk_.comment = static_cast<int32_t>(prog_->strings.size() - 1);
  }
  i_ = stop < end_ ? stop + 1 : end_;
}

void Compiler::beginStatement(uint32_t at) {
  if (sawStatement_ || ncWords_ > 0) fail(AlarmId::DuplicateNcMacro, {}, at);
  sawStatement_ = true;
}

void Compiler::parseStatements() {
  while (true) {
    skipSpaces();
    if (atEnd()) return;
    char c = peek();
    uint32_t at = col();
    if (c == '(') {
      parseComment();
    } else if (c == '#') {
      beginStatement(at);
      parseAssign(false);
    } else if (isUpper(c) && isUpper(peek(1))) {
      size_t n = letterRun();
      std::string_view kw = s_.substr(i_, n);
      if (kw == "IF") {
        beginStatement(at), i_ += 2, parseIf();
      } else if (kw == "GOTO") {
        beginStatement(at), i_ += 4, blk_.kind = BlockKind::Goto, parseGotoTarget();
      } else if (kw == "WHILE") {
        beginStatement(at), i_ += 5, parseWhile();
      } else if (kw.substr(0, 2) == "DO" && (n == 2)) {
        beginStatement(at), i_ += 2, parseDo(-1);
      } else if (kw == "END") {
        beginStatement(at), i_ += 3, parseEnd();
      } else if (kw == "DPRNT") {
        beginStatement(at), i_ += 5, parsePrint(PrintKind::Dprnt);
      } else if (kw == "BPRNT") {
        beginStatement(at), i_ += 5, parsePrint(PrintKind::Bprnt);
      } else if (kw == "POPEN") {
        beginStatement(at), i_ += 5, blk_.kind = BlockKind::Popen;
      } else if (kw == "PCLOS") {
        beginStatement(at), i_ += 5, blk_.kind = BlockKind::Pclos;
      } else {
        fail(AlarmId::ImproperAddress, "unknown word '" + std::string(kw) + "'", at);
      }
    } else if (isUpper(c)) {
      if (sawStatement_) fail(AlarmId::DuplicateNcMacro, {}, at);
      parseWord();
    } else if (c == ',' && (peek(commaLetter()) == 'C' || peek(commaLetter()) == 'R' ||
                            peek(commaLetter()) == 'A')) {
      if (sawStatement_) fail(AlarmId::DuplicateNcMacro, {}, at);
      parseCommaWord();
    } else if (c == '/' && !sawStatement_) {
      // A slash after the head of an NC block (outside brackets, where it would divide): with
      // its switch on, the information from it up to the end of the block is ignored; with the
      // switch off it is read over (16i/0i "position of a slash", docs/fanuc-decisions.md §9).
      ++i_;
      size_t level = 1;
      if (peek() >= '1' && peek() <= '9') level = static_cast<size_t>(peek() - '0'), ++i_;
      if (opt_.blockSkip[level]) i_ = end_;
    } else if (c == '<') {
      // <name> as the program of M98/G65/G66 (30i): stored as word '<' naming a string.
      size_t close = s_.find('>', i_);
      if (close == std::string_view::npos || close >= end_)
        fail(AlarmId::ImproperAddress, "'<' without '>'", at);
      prog_->strings.emplace_back(s_.substr(i_ + 1, close - i_ - 1));
      Word w;
      w.letter = '<';
      w.col = static_cast<uint16_t>(at);
      w.a = static_cast<int32_t>(prog_->strings.size() - 1);
      prog_->words.push_back(w);
      ++ncWords_;
      i_ = close + 1;
    } else if (isLower(c)) {
      fail(AlarmId::ImproperAddress, std::string("lower-case '") + c + "'", at);
    } else {
      // A byte that is not printable ASCII is named by its code: the alarm text must stay
      // readable (and valid UTF-8 in the JSON reports).
      bool printable = c > ' ' && c < 0x7f;
      fail(AlarmId::ImproperAddress,
           printable ? std::string("unexpected '") + c + "'"
                     : fmt::format("unexpected byte 0x{:02X}", static_cast<unsigned char>(c)),
           at);
    }
  }
}

// A G or M word whose code a parameter (6050-6059, 6080-6089) makes a macro call.
static bool callsMacro(const std::array<int, 10>& codes, const Word& w) {
  if (w.value != std::floor(w.value) || w.value <= 0) return false;
  return std::find(codes.begin(), codes.end(), static_cast<int>(w.value)) != codes.end();
}

void Compiler::commitBlock() {
  Program& p = *prog_;
  uint32_t nWords = static_cast<uint32_t>(p.words.size() - blk_.firstWord);
  // One pass: G65/G66 (their words are arguments, which take a point), decimal points where
  // an address forbids them (checked again below, rare), and the plain-block test.
  bool macroCall = false, forbiddenPoint = false, forbiddenMinus = false, plain = nWords > 0;
  uint32_t seen = 0;  // plain: each letter once
  for (uint32_t k = blk_.firstWord; k < p.words.size(); ++k) {
    const Word& w = p.words[k];
    if (w.letter == 'G' && w.kind == WordKind::Literal)
      macroCall |= w.value == 65 || w.value == 66 || w.value == 66.1 || callsMacro(opt_.callG, w);
    if (w.letter == 'M' && w.kind == WordKind::Literal) macroCall |= callsMacro(opt_.callM, w);
    forbiddenPoint |= (w.flags & kHasPoint) && forbidsPoint(w.letter);
    forbiddenMinus |= (w.flags & kHasMinus) != 0;
    if (plain) {
      plain = plainWord(w) && !(seen & (1u << (w.letter - 'A')));
      if (plain) seen |= 1u << (w.letter - 'A');
    }
  }
  // In a macro call (G65, G66, G66.1, or a G/M code a parameter makes one) every letter but
  // P, L (and G, which is no argument) is an argument: a signed value that becomes #7, #11,
  // #13, #19, #20 ... (H-2.).
  for (uint32_t k = blk_.firstWord; forbiddenMinus && k < p.words.size(); ++k) {
    const Word& w = p.words[k];
    bool argument = macroCall && w.letter != 'P' && w.letter != 'L' && w.letter != 'G';
    if ((w.flags & kHasMinus) && !argument)
      fail(AlarmId::IllegalMinus, std::string(1, w.letter), w.col);
  }
  for (uint32_t k = blk_.firstWord; forbiddenPoint && k < p.words.size(); ++k) {
    const Word& w = p.words[k];
    bool argument = macroCall && w.letter != 'P' && w.letter != 'L';
    if ((w.flags & kHasPoint) && forbidsPoint(w.letter) && !argument)
      fail(AlarmId::IllegalDecimalPoint, std::string(1, w.letter), w.col);
  }
  blk_.nWords = static_cast<uint16_t>(nWords);
  if (nWords > 0 && blk_.kind == BlockKind::Empty) {
    blk_.kind = BlockKind::Nc;
    if (plain) blk_.flags |= kPlainBlock;
  }
  if (blk_.kind == BlockKind::Empty && blk_.n < 0 && blk_.skipLevel == 0 && blk_.comment < 0)
    return;  // nothing to keep
  if (blk_.n >= 0) p.labels.emplace_back(blk_.n, static_cast<uint32_t>(p.blocks.size()));
  if (blk_.kind == BlockKind::While || blk_.kind == BlockKind::End ||
      blk_.kind == BlockKind::Goto || blk_.kind == BlockKind::If)
    hasControlFlow_ = true;
  if (blk_.kind != BlockKind::Nc && blk_.kind != BlockKind::Empty) {
    p.macroOps.push_back(ops_);
    blk_.ops = static_cast<int32_t>(p.macroOps.size() - 1);
  }
  p.blocks.push_back(blk_);
}

double Compiler::parseNumberText(bool& hasPoint, int& intDigits) {
  // The common number (CAM output, at most 19 digits) in one scan (decimal_scan.hpp);
  // anything else is scanned again by parseNumberSlow.
  const char* text = s_.data();
  DecimalText d;
  numberTooLong_ = false;
  if (!scanDecimal(text + i_, text + end_, d)) return parseNumberSlow(hasPoint, intDigits);
  hasPoint = d.hasPoint;
  intDigits = d.intDigits;
  i_ = static_cast<size_t>(d.end - text);
  return d.value;
}

double Compiler::parseNumberSlow(bool& hasPoint, int& intDigits) {
  // Numbers of more than 19 digits, and two decimal points (an alarm at the second one).
  const char* text = s_.data();
  size_t start = i_, i = i_, end = end_;
  hasPoint = false;
  intDigits = 0;
  bool leading = true, neg = false, anyDigit = false;
  uint64_t mantissa = 0;
  int significant = 0, frac = 0;
  if (i < end && (text[i] == '+' || text[i] == '-')) neg = text[i] == '-', ++i;
  for (; i < end; ++i) {
    char c = text[i];
    if (isDigit(c)) {
      anyDigit = true;
      if (!hasPoint) {
        if (c != '0' || !leading) ++intDigits, leading = false;
      } else {
        ++frac;
      }
      if (mantissa != 0 || c != '0') ++significant;
      if (significant <= 19) mantissa = mantissa * 10 + static_cast<uint64_t>(c - '0');
    } else if (c == '.') {
      if (hasPoint) {
        i_ = i;
        fail(AlarmId::IllegalDecimalPoint, "two decimal points");
      }
      hasPoint = true;
    } else {
      break;
    }
  }
  i_ = i;
  if (!anyDigit) return 0.0;  // "X." reads as zero
  if (significant <= 19 && mantissa <= (uint64_t{1} << 53) && frac <= 22) {
    double v = static_cast<double>(mantissa) / kPow10[frac];
    return neg ? -v : v;
  }
  std::string_view num = s_.substr(start, i_ - start);
  if (num[0] == '+') num.remove_prefix(1);
  double v = 0;
  std::string buf;
  if (num.back() == '.') {
    buf = std::string(num) + "0";
    num = buf;
  }
  // Out of a double's range only with 309 digits or more: too many digits, which the caller
  // raises as PS0003 at the word or constant (one alarm, one place, whatever the length).
  auto res = std::from_chars(num.data(), num.data() + num.size(), v);
  if (res.ec != std::errc()) numberTooLong_ = true;
  return v;
}

void Compiler::parseWord() {
  char letter = peek();
  uint32_t at = col();
  if (letter == 'O' || letter == 'N')
    fail(AlarmId::ImproperAddress, std::string(1, letter) + " inside a block", at);
  ++i_;
  skipSpaces();
  Word w;
  w.letter = letter;
  w.col = static_cast<uint16_t>(at > 0xffff ? 0xffff : at);
  // The sign may stand apart from its value (Z - [#26], Z- 5.): the control skips spaces
  // there as anywhere between a letter and its value.
  char c = peek();
  const bool neg = c == '-', sign = c == '-' || c == '+';
  if (sign) {
    ++i_;
    skipSpaces();
    c = peek();
  }
  // A minus on P, M, S, T, H, D... is checked at the end of the block: in a G65/G66 block
  // those letters are arguments and take one (H-2.).
  if (neg && forbidsMinus(letter)) w.flags |= kHasMinus;
  if (c == '#') {
    if (isDigit(peek(1))) {
      ++i_;
      int64_t n = 0;
      while (isDigit(peek())) {
        n = n * 10 + (peek() - '0'), ++i_;
        if (n > 99999999) fail(AlarmId::VariableOutOfRange, {}, at);
      }
      w.kind = neg ? WordKind::NegVar : WordKind::Var;
      w.a = static_cast<int32_t>(n);
    } else {
      // X#[expr] or X-#[expr]: compile the variable read (and the sign) as an expression.
      uint32_t begin = static_cast<uint32_t>(prog_->code.size());
      depth_ = 0;
      ++i_;
      parseVarRef();
      if (neg) emit(Op::Neg, at);
      prog_->exprs.push_back(ExprRange{begin, static_cast<uint32_t>(prog_->code.size())});
      w.kind = WordKind::Expr;
      w.a = static_cast<int32_t>(prog_->exprs.size() - 1);
    }
  } else if (c == '[') {
    uint32_t begin = static_cast<uint32_t>(prog_->code.size());
    depth_ = 0;
    Type t = parseBracket();
    if (t != Type::Num) fail(AlarmId::IllegalExpressionFormat, "condition used as a value", at);
    if (neg) emit(Op::Neg, at);
    prog_->exprs.push_back(ExprRange{begin, static_cast<uint32_t>(prog_->code.size())});
    w.kind = WordKind::Expr;
    w.a = static_cast<int32_t>(prog_->exprs.size() - 1);
  } else if (isDigit(c) || c == '.') {
    bool hasPoint = false;
    int intDigits = 0;
    const size_t numStart = i_;
    const double v = parseNumberText(hasPoint, intDigits);
    // "X-." has no digit: it reads as zero, as "X." does.
    const bool noDigit = c == '.' && i_ == numStart + 1;
    w.value = neg && !noDigit ? -v : v;
    // Decimal points on P, M, S, T, H, D... are checked at the end of the block: in a
    // G65/G66 block those letters are arguments and take a point (D5.0).
    if (intDigits > 9 || numberTooLong_) fail(AlarmId::TooManyDigits, std::string(1, letter), at);
    if (hasPoint) w.flags |= kHasPoint;
    // 999.99999 is the smallest value that can exceed 99999999 increments (IS-C inch, 10^5 per
    // inch); smaller ones are never checked again.
    if (std::fabs(w.value) >= letters::kLongNumberFrom && isDimension(letter))
      w.flags |= kLongNumber;
  } else {
    fail(AlarmId::NoDataAfterAddress, std::string(1, letter), at);
  }
  prog_->words.push_back(w);
  ++ncWords_;
}

void Compiler::parseCommaWord() {
  uint32_t at = col();
  const size_t k = commaLetter();
  char letter = peek(k) == 'C' ? 'c' : peek(k) == 'A' ? 'a' : 'r';
  i_ += k + 1;
  skipSpaces();
  Word w;
  w.letter = letter;
  w.col = static_cast<uint16_t>(at);
  if (peek() == '#' || peek() == '[') {
    uint32_t begin = static_cast<uint32_t>(prog_->code.size());
    depth_ = 0;
    Type t = parsePrimary();
    if (t != Type::Num) fail(AlarmId::IllegalExpressionFormat, {}, at);
    prog_->exprs.push_back(ExprRange{begin, static_cast<uint32_t>(prog_->code.size())});
    w.kind = WordKind::Expr;
    w.a = static_cast<int32_t>(prog_->exprs.size() - 1);
  } else {
    bool hasPoint = false;
    int intDigits = 0;
    size_t numStart = i_;
    char first = peek();
    w.value = parseNumberText(hasPoint, intDigits);
    if (i_ == numStart || (i_ == numStart + 1 && (first == '-' || first == '+')))
      fail(AlarmId::NoDataAfterAddress, letter == 'c' ? ",C" : letter == 'a' ? ",A" : ",R", at);
    if (intDigits > 9 || numberTooLong_)
      fail(AlarmId::TooManyDigits, letter == 'c' ? ",C" : letter == 'a' ? ",A" : ",R", at);
    if (hasPoint) w.flags |= kHasPoint;
  }
  prog_->words.push_back(w);
  ++ncWords_;
}

void Compiler::parseAssign(bool asThen) {
  uint32_t at = col();
  if (peek() != '#') fail(AlarmId::MacroStatementFormat, "assignment expected", at);
  ++i_;
  skipSpaces();
  if (isDigit(peek())) {
    int64_t n = 0;
    while (isDigit(peek())) {
      n = n * 10 + (peek() - '0'), ++i_;
      if (n > 99999999) fail(AlarmId::VariableOutOfRange, {}, at);
    }
    ops_.lhsVar = static_cast<int32_t>(n);
  } else if (peek() == '[') {
    depth_ = 0;
    uint32_t begin = static_cast<uint32_t>(prog_->code.size());
    if (parseBracket() != Type::Num) fail(AlarmId::IllegalExpressionFormat, {}, at);
    prog_->exprs.push_back(ExprRange{begin, static_cast<uint32_t>(prog_->code.size())});
    ops_.lhsExpr = static_cast<int32_t>(prog_->exprs.size() - 1);
  } else {
    fail(AlarmId::IllegalExpressionFormat, "'#' without a variable number", at);
  }
  skipSpaces();
  if (peek() != '=') fail(AlarmId::MacroStatementFormat, "'=' expected", col());
  ++i_;
  ops_.rhs = compileExpr(Type::Num, col());
  if (!asThen) blk_.kind = BlockKind::Assign;
}

void Compiler::parseIf() {
  skipSpaces();
  uint32_t at = col();
  if (peek() != '[') fail(AlarmId::MacroStatementFormat, "IF needs [condition]", at);
  blk_.kind = BlockKind::If;
  depth_ = 0;
  uint32_t begin = static_cast<uint32_t>(prog_->code.size());
  if (parseBracket() != Type::Bool)
    fail(AlarmId::IllegalExpressionFormat, "IF needs a condition (EQ NE GT GE LT LE)", at);
  prog_->exprs.push_back(ExprRange{begin, static_cast<uint32_t>(prog_->code.size())});
  ops_.cond = static_cast<int32_t>(prog_->exprs.size() - 1);
  skipSpaces();
  if (peekKeyword("GOTO")) {
    i_ += 4;
    parseGotoTarget();
  } else if (peekKeyword("THEN")) {
    i_ += 4;
    skipSpaces();
    ops_.thenAssign = true;
    parseAssign(true);
  } else {
    fail(AlarmId::MacroStatementFormat, "IF without GOTO or THEN", col());
  }
}

void Compiler::parseGotoTarget() {
  skipSpaces();
  uint32_t at = col();
  if (isDigit(peek())) {
    int64_t n = 0;
    while (isDigit(peek())) {
      n = n * 10 + (peek() - '0'), ++i_;
      if (n > 99999999) break;
    }
    if (n < 1 || n > 99999999) fail(AlarmId::IllegalMacroSequence, std::to_string(n), at);
    ops_.gotoLabel = static_cast<int32_t>(n);
  } else if (peek() == '#' || peek() == '[') {
    depth_ = 0;
    uint32_t begin = static_cast<uint32_t>(prog_->code.size());
    if (parsePrimary() != Type::Num) fail(AlarmId::IllegalExpressionFormat, {}, at);
    prog_->exprs.push_back(ExprRange{begin, static_cast<uint32_t>(prog_->code.size())});
    ops_.gotoExpr = static_cast<int32_t>(prog_->exprs.size() - 1);
  } else {
    fail(AlarmId::MacroStatementFormat, "GOTO needs a sequence number", at);
  }
}

void Compiler::parseWhile() {
  inWhile_ = true;
  skipSpaces();
  uint32_t at = col();
  if (peek() != '[') fail(AlarmId::MacroStatementFormat, "WHILE needs [condition]", at);
  depth_ = 0;
  uint32_t begin = static_cast<uint32_t>(prog_->code.size());
  if (parseBracket() != Type::Bool)
    fail(AlarmId::IllegalExpressionFormat, "WHILE needs a condition", at);
  prog_->exprs.push_back(ExprRange{begin, static_cast<uint32_t>(prog_->code.size())});
  int32_t cond = static_cast<int32_t>(prog_->exprs.size() - 1);
  skipSpaces();
  if (!peekKeyword("DO")) fail(AlarmId::MacroStatementFormat, "WHILE without DO", col());
  i_ += 2;
  parseDo(cond);
}

void Compiler::parseDo(int32_t cond) {
  skipSpaces();
  uint32_t at = col();
  if (!isDigit(peek())) fail(AlarmId::IllegalLoopNumber, "DO without a number", at);
  int n = 0;
  while (isDigit(peek())) n = std::min(n * 10 + (peek() - '0'), 1000), ++i_;
  blk_.kind = BlockKind::While;
  ops_.cond = cond;
  blk_.loopId = static_cast<uint8_t>(std::min(n, 255));
}

void Compiler::parseEnd() {
  skipSpaces();
  uint32_t at = col();
  if (!isDigit(peek())) fail(AlarmId::IllegalLoopNumber, "END without a number", at);
  int n = 0;
  while (isDigit(peek())) n = std::min(n * 10 + (peek() - '0'), 1000), ++i_;
  blk_.kind = BlockKind::End;
  blk_.loopId = static_cast<uint8_t>(std::min(n, 255));
}

void Compiler::parsePrint(PrintKind kind) {
  skipSpaces();
  uint32_t at = col();
  if (peek() != '[') fail(AlarmId::MacroStatementFormat, "DPRNT needs [...]", at);
  ++i_;
  blk_.kind = BlockKind::Print;
  ops_.printKind = kind;
  ops_.firstPrint = static_cast<uint32_t>(prog_->prints.size());
  PrintItem text;
  auto flushText = [&] {
    if (!text.text.empty()) prog_->prints.push_back(text), text.text.clear();
  };
  while (true) {
    if (atEnd()) fail(AlarmId::MacroStatementFormat, "DPRNT without ']'", at);
    char c = peek();
    if (c == ']') {
      ++i_;
      break;
    }
    if (isSpace(c)) {
      ++i_;  // spaces are not part of a program; '*' prints a space
      continue;
    }
    if (c == '#') {
      flushText();
      PrintItem item;
      item.isVar = true;
      uint32_t begin = static_cast<uint32_t>(prog_->code.size());
      depth_ = 0;
      ++i_;
      parseVarRef();
      prog_->exprs.push_back(ExprRange{begin, static_cast<uint32_t>(prog_->code.size())});
      item.expr = static_cast<int32_t>(prog_->exprs.size() - 1);
      skipSpaces();
      if (peek() != '[')
        fail(AlarmId::MacroStatementFormat, "variable needs a [digits] format", col());
      ++i_;
      std::string digits;
      while (isDigit(peek())) digits += peek(), ++i_;
      if (peek() != ']') fail(AlarmId::MacroStatementFormat, "bad format", col());
      ++i_;
      if (kind == PrintKind::Dprnt) {
        if (digits.size() != 2) fail(AlarmId::MacroStatementFormat, "format is [ab]", col());
        item.intDigits = static_cast<uint8_t>(digits[0] - '0');
        item.fracDigits = static_cast<uint8_t>(digits[1] - '0');
        if (item.intDigits + item.fracDigits > 8 || item.intDigits == 0)
          fail(AlarmId::MacroStatementFormat, "a+b must be 1..8", col());
      } else {
        if (digits.size() != 1) fail(AlarmId::MacroStatementFormat, "format is [b]", col());
        item.fracDigits = static_cast<uint8_t>(digits[0] - '0');
      }
      prog_->prints.push_back(item);
      continue;
    }
    if (c == '[' || c == '(') fail(AlarmId::MacroStatementFormat, "unexpected bracket", col());
    text.text += c == '*' ? ' ' : c;
    ++i_;
  }
  flushText();
  ops_.nPrint = static_cast<uint32_t>(prog_->prints.size()) - ops_.firstPrint;
}

// ---- expressions ----------------------------------------------------------------------------

bool Compiler::peekKeyword(const char* kw) const {
  size_t n = std::strlen(kw);
  for (size_t k = 0; k < n; ++k)
    if (peek(k) != kw[k]) return false;
  return true;
}

// The operator kw here: alone in its run of letters, or run together with the function name
// after it (IF[ABS[#10]LEABS[#11]], #12=#10ANDABS[#11]): vendors' macros for Fanuc controls
// are written both ways.
bool Compiler::operatorAt(const char* kw) const {
  const size_t n = std::strlen(kw), run = letterRun();
  if (run < n || !peekKeyword(kw)) return false;
  if (run == n) return true;
  const std::string_view rest = s_.substr(i_ + n, run - n);
  return std::any_of(std::begin(kFunctions), std::end(kFunctions),
                     [&](const FnName& f) { return rest == f.name; });
}

int32_t Compiler::compileExpr(Type want, uint32_t at) {
  depth_ = 0;
  uint32_t begin = static_cast<uint32_t>(prog_->code.size());
  Type t = parseRel();
  if (t != want)
    fail(AlarmId::IllegalExpressionFormat,
         want == Type::Num ? "condition used as a value" : "value used as a condition", at);
  skipSpaces();
  prog_->exprs.push_back(ExprRange{begin, static_cast<uint32_t>(prog_->code.size())});
  return static_cast<int32_t>(prog_->exprs.size() - 1);
}

Type Compiler::parseRel() {
  Type a = parseSum();
  skipSpaces();
  static constexpr struct {
    const char* kw;
    Op op;
  } rel[] = {{"EQ", Op::Eq}, {"NE", Op::Ne}, {"GT", Op::Gt},
             {"GE", Op::Ge}, {"LT", Op::Lt}, {"LE", Op::Le}};
  for (const auto& r : rel) {
    if (operatorAt(r.kw)) {
      uint32_t at = col();
      i_ += 2;
      Type b = parseSum();
      if (a != Type::Num || b != Type::Num)
        fail(AlarmId::IllegalExpressionFormat, "comparison of conditions", at);
      emit(r.op, at);
      return Type::Bool;
    }
  }
  return a;
}

Type Compiler::parseSum() {
  Type a = parseTerm();
  while (true) {
    skipSpaces();
    uint32_t at = col();
    char c = peek();
    Op op;
    size_t len = 1;
    if (c == '+')
      op = Op::Add;
    else if (c == '-')
      op = Op::Sub;
    else if (operatorAt("OR"))
      op = Op::Or, len = 2;
    else if (operatorAt("XOR"))
      op = Op::Xor, len = 3;
    else
      return a;
    i_ += len;
    emit(typedOp(op, a, parseTerm(), at), at);
  }
}

// AND/OR/XOR are bitwise on values and logical on conditions (30i [[a]AND[b]]); every
// other operator needs values.
Op Compiler::typedOp(Op op, Type a, Type b, uint32_t at) const {
  bool logical = op == Op::And || op == Op::Or || op == Op::Xor;
  if (!logical) {
    if (a != Type::Num || b != Type::Num)
      fail(AlarmId::IllegalExpressionFormat, "arithmetic on a condition", at);
    return op;
  }
  if (a != b) fail(AlarmId::IllegalExpressionFormat, "mixing a condition and a value", at);
  if (a == Type::Num) return op;
  return op == Op::And ? Op::LAnd : op == Op::Or ? Op::LOr : Op::LXor;
}

Type Compiler::parseTerm() {
  Type a = parseUnary();
  while (true) {
    skipSpaces();
    uint32_t at = col();
    char c = peek();
    Op op;
    size_t len = 1;
    if (c == '*')
      op = Op::Mul;
    else if (c == '/')
      op = Op::Div;
    else if (operatorAt("AND"))
      op = Op::And, len = 3;
    else if (operatorAt("MOD"))
      op = Op::Mod, len = 3;
    else
      return a;
    i_ += len;
    emit(typedOp(op, a, parseUnary(), at), at);
  }
}

Type Compiler::parseUnary() {
  skipSpaces();
  uint32_t at = col();
  if (peek() == '-') {
    ++i_;
    if (parseUnary() != Type::Num) fail(AlarmId::IllegalExpressionFormat, {}, at);
    emit(Op::Neg, at);
    return Type::Num;
  }
  if (peek() == '+') {
    ++i_;
    return parseUnary();
  }
  return parsePrimary();
}

Type Compiler::parseBracket() {
  uint32_t at = col();
  ++i_;  // '['
  if (++depth_ > kMaxBracketNesting) fail(AlarmId::TooManyBrackets, {}, at);
  Type t = parseRel();
  skipSpaces();
  if (peek() != ']') fail(AlarmId::IllegalExpressionFormat, "']' expected", col());
  ++i_;
  --depth_;
  return t;
}

void Compiler::parseVarRef() {
  // After '#': digits, or [expr] for an indirect reference. '##1' is not allowed.
  skipSpaces();
  uint32_t at = col();
  if (isDigit(peek())) {
    int64_t n = 0;
    while (isDigit(peek())) {
      n = n * 10 + (peek() - '0'), ++i_;
      if (n > 99999999) fail(AlarmId::VariableOutOfRange, {}, at);
    }
    emit(Op::Var, at, static_cast<int32_t>(n));
  } else if (peek() == '[') {
    if (parseBracket() != Type::Num) fail(AlarmId::IllegalExpressionFormat, {}, at);
    emit(Op::VarInd, at);
  } else {
    fail(AlarmId::IllegalExpressionFormat, "'#' without a variable number", at);
  }
}

Type Compiler::parsePrimary() {
  skipSpaces();
  uint32_t at = col();
  char c = peek();
  if (c == '[') return parseBracket();
  if (c == '#') {
    ++i_;
    parseVarRef();
    return Type::Num;
  }
  if (isDigit(c) || c == '.') {
    bool hasPoint = false;
    int intDigits = 0;
    double v = parseNumberText(hasPoint, intDigits);
    // A constant longer than a double holds exactly (1 and 300 zeros) is no real program's:
    // the control stops at its digit limit; ncvm allows 15 integer digits.
    if (intDigits > 15 || numberTooLong_)
      fail(AlarmId::TooManyDigits,
           intDigits > 15 ? "constant with more than 15 digits" : "constant with too many digits",
           at);
    emit(Op::Const, at, addConst(v));
    return Type::Num;
  }
  if (isUpper(c)) {
    size_t n = letterRun();
    std::string_view name = s_.substr(i_, n);
    for (const auto& f : kFunctions) {
      if (name != f.name) continue;
      i_ += n;
      skipSpaces();
      if (peek() != '[')
        fail(AlarmId::IllegalExpressionFormat, std::string(name) + " needs [", col());
      uint32_t open = col();
      ++i_;
      if (++depth_ > kMaxBracketNesting) fail(AlarmId::TooManyBrackets, {}, open);
      size_t firstInstr = prog_->code.size();
      if (parseRel() != Type::Num) fail(AlarmId::IllegalExpressionFormat, {}, open);
      skipSpaces();
      bool two = false;
      if (peek() == ',' && (f.fn == Fn::Atan || f.fn == Fn::Pow)) {
        ++i_;
        if (parseRel() != Type::Num) fail(AlarmId::IllegalExpressionFormat, {}, open);
        skipSpaces();
        two = true;
      }
      if (peek() != ']') fail(AlarmId::IllegalExpressionFormat, "']' expected", col());
      ++i_;
      --depth_;
      if (f.fn == Fn::Atan && !two) {
        // ATAN[a]/[b]: the Fanuc two-argument form.
        size_t save = i_;
        skipSpaces();
        if (peek() == '/') {
          ++i_;
          skipSpaces();
          if (peek() == '[') {
            if (parseBracket() != Type::Num) fail(AlarmId::IllegalExpressionFormat, {}, at);
            two = true;
          } else {
            i_ = save;
          }
        } else {
          i_ = save;
        }
      }
      if (f.fn == Fn::Pow && !two) fail(AlarmId::IllegalExpressionFormat, "POW[a,b]", at);
      if (f.fn == Fn::Adp) {
        // ADP works on a local variable passed as an argument: it needs the variable itself.
        const Instr& only = prog_->code[firstInstr];
        if (prog_->code.size() != firstInstr + 1 || only.op != Op::Var)
          fail(AlarmId::IllegalExpressionFormat, "ADP needs a variable: ADP[#n]", at);
        emit(Op::Fn1, at, only.arg, Fn::Adp);
        return Type::Num;
      }
      if (two)
        emit(Op::Fn2, at, 0, f.fn == Fn::Atan ? Fn::Atan2 : Fn::Pow);
      else
        emit(Op::Fn1, at, 0, f.fn);
      return Type::Num;
    }
    fail(AlarmId::IllegalExpressionFormat, "unknown word '" + std::string(name) + "'", at);
  }
  if (c == '\0') fail(AlarmId::IllegalExpressionFormat, "expression ends early", at);
  fail(AlarmId::IllegalExpressionFormat, std::string("unexpected '") + c + "'", at);
}

}  // namespace

ParsedFile parseProgramText(std::string_view text, uint32_t fileId, std::string_view stem,
                            const ParseOptions& options) {
  TextChunks chunks(text);
  return Compiler(chunks, fileId, stem, options).run();
}

ParsedFile parseProgramChunks(LineChunks& chunks, uint32_t fileId, std::string_view stem,
                              const ParseOptions& options) {
  return Compiler(chunks, fileId, stem, options).run();
}

struct PieceCompiler::Impl {
  Compiler compiler;
};

PieceCompiler::PieceCompiler(LineChunks& chunks, uint32_t fileId, std::string_view stem,
                             const ParseOptions& options)
    : impl_(std::make_unique<Impl>(Impl{Compiler(chunks, fileId, stem, options)})) {}
PieceCompiler::~PieceCompiler() = default;
bool PieceCompiler::next() {
  return impl_->compiler.nextPiece();
}
ParsedFile& PieceCompiler::parsed() {
  return impl_->compiler.parsed();
}
void PieceCompiler::continueInto(Program& p) {
  impl_->compiler.continueInto(p);
}
bool PieceCompiler::hasControlFlow() const {
  return impl_->compiler.hasControlFlow();
}
bool PieceCompiler::onlyComments() const {
  return impl_->compiler.onlyComments();
}
uint32_t PieceCompiler::line() const {
  return impl_->compiler.line();
}

void resolveStructure(Program& p) {
  auto structural = [&](const Block& b, AlarmId id, std::string detail) {
    Alarm a{alarmCode(id),
            std::string(alarmMessage(id)) + (detail.empty() ? "" : " (" + detail + ")"), b.loc,
            b.n >= 0 ? std::optional<int64_t>(b.n) : std::nullopt, p.number};
    p.structural.push_back(std::move(a));
  };
  // DO/END pairing: ids 1..3, properly nested, not crossing.
  std::vector<uint32_t> open;  // While block indices
  p.loopParents.assign(p.blocks.size(), -1);
  for (uint32_t k = 0; k < p.blocks.size(); ++k) {
    Block& b = p.blocks[k];
    p.loopParents[k] = open.empty() ? -1 : static_cast<int32_t>(open.back());
    if (b.kind == BlockKind::While) {
      if (b.loopId < 1 || b.loopId > 3) {
        structural(b, AlarmId::IllegalLoopNumber, "DO " + std::to_string(b.loopId));
        continue;
      }
      for (uint32_t o : open)
        if (p.blocks[o].loopId == b.loopId)
          structural(b, AlarmId::IllegalLoopNumber,
                     "DO " + std::to_string(b.loopId) + " inside DO " + std::to_string(b.loopId));
      open.push_back(k);
    } else if (b.kind == BlockKind::End) {
      if (b.loopId < 1 || b.loopId > 3) {
        structural(b, AlarmId::IllegalLoopNumber, "END " + std::to_string(b.loopId));
        continue;
      }
      if (open.empty() || p.blocks[open.back()].loopId != b.loopId) {
        structural(
            b, AlarmId::IllegalLoopNumber,
            "END " + std::to_string(b.loopId) +
                (open.empty() ? " without DO"
                              : " crosses DO " + std::to_string(p.blocks[open.back()].loopId)));
        continue;
      }
      uint32_t w = open.back();
      open.pop_back();
      p.loopParents[k] = open.empty() ? -1 : static_cast<int32_t>(open.back());
      p.ops(b).target = static_cast<int32_t>(w);
      p.ops(p.blocks[w]).target = static_cast<int32_t>(k + 1);
    }
  }
  for (uint32_t o : open)
    structural(p.blocks[o], AlarmId::MissingEnd, "DO " + std::to_string(p.blocks[o].loopId));

  // Literal GOTO targets: must exist and must not jump into a loop.
  for (uint32_t k = 0; k < p.blocks.size(); ++k) {
    Block& b = p.blocks[k];
    if (b.kind != BlockKind::Goto && b.kind != BlockKind::If) continue;
    MacroOps& o = p.ops(b);
    if ((b.kind == BlockKind::If && o.thenAssign) || o.gotoLabel < 0) continue;
    int32_t t = p.findLabel(o.gotoLabel, k);
    if (t < 0) {
      structural(b, AlarmId::IllegalMacroSequence,
                 "N" + std::to_string(o.gotoLabel) + " not found");
      continue;
    }
    o.target = t;
    // The target's enclosing loops must all enclose the GOTO too.
    for (int32_t l = p.loopParents[t]; l >= 0; l = p.loopParents[l]) {
      bool enclosesSource = false;
      for (int32_t s = p.loopParents[k]; s >= 0; s = p.loopParents[s])
        if (s == l) enclosesSource = true;
      if (static_cast<uint32_t>(t) == static_cast<uint32_t>(l))
        break;  // jumping to the WHILE itself
      if (!enclosesSource) {
        structural(b, AlarmId::IllegalLoopNumber,
                   "GOTO " + std::to_string(o.gotoLabel) + " jumps into a loop");
        break;
      }
    }
  }
}

}  // namespace ncvm
