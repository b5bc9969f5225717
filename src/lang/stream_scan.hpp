#pragma once
// Decides, before a file is compiled, whether its program may be compiled while it runs
// (program_stream.hpp): one quick look at every byte, far cheaper than compiling.
//
// A streamed program is compiled one piece at a time and each piece's blocks are dropped once
// they have run, so nothing may need the program as a whole before or while it runs. The
// scan accepts only text in which every block is address words (a letter and a number), N
// numbers, spaces and comments, with one program header at the start: no macro statement
// (#, [, keywords such as IF, GOTO, WHILE, END, DO, DPRNT: two letters in a row), no second
// program (O, <name>), no ';' or '/', no ',C'/',R' corner word (the control keeps a pointer to
// that block until the next move), and no '%' after the first piece when the first piece had
// none (the text before a file's first '%' is leader, which the compiler drops). What the scan
// accepts can still jump back (M99, a lathe cycle's P/Q, M99 P from a subprogram): the
// executor then compiles the program whole and goes on there (ProgramStream::materialize).
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace ncvm {

class StreamScan {
 public:
  // The pieces of the text in order, exactly as the compiler will get them (StreamChunks).
  void piece(std::string_view text);
  // Every piece so far can be streamed.
  bool streamable() const { return ok_; }
  // The '\n' seen so far.
  uint64_t lines() const { return lines_; }

 private:
  void scalar(const char* p, size_t n);

  uint64_t lines_ = 0;
  bool ok_ = true;
  bool first_ = true;          // the piece being scanned is the first
  bool percentFirst_ = false;  // the first piece holds a '%'
  bool header_ = false;        // the one O header was seen
  bool comment_ = false;       // inside ( ... ), which ends at ')' or the end of the line
  bool letter_ = false;        // the last byte outside a comment was a letter
  bool lineStart_ = true;      // only spaces since the start of the line
};

}  // namespace ncvm
