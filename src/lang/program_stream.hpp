#pragma once
// A large file's program compiled while it runs: one piece of text at a time, whose blocks
// replace the last piece's once the executor has run them. A 1,000,000-line CAM program
// otherwise holds about 84 MB of blocks and words that are written once, read once, and whose
// fresh pages the kernel must clear first; streamed, it holds two pieces (a few hundred KB,
// which stay in the cache).
//
// Only a file StreamScan accepts is streamed: its program runs from the first block to the
// last, and nothing needs it whole before it runs. Whatever would still need another block (a
// jump back by M99, a lathe cycle's P/Q blocks, a return to a sequence number, the program
// entered a second time) asks for materialize(), which compiles the file whole into the same
// Program and detaches the stream; the blocks keep their indices (base() + index in the piece).
//
// The Program's compiled arrays hold only the current piece: Block::firstWord and the program's
// labels index that piece (its labels are not used before materialize()). Comments, errors and
// the other side tables grow as in a whole program.
#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "lang/ir.hpp"
#include "lang/line_chunks.hpp"
#include "lang/parser.hpp"

namespace ncvm {

class ProgramStream {
 public:
  // Whether the file (read once through pieces of pieceBytes) can be streamed; `lines` is then
  // its number of lines.
  static bool scan(const std::string& path, uint64_t size, size_t pieceBytes, uint32_t& lines);

  // Compiles the file's first blocks into `program` (its header, number and name as a whole
  // compile would give them) and sets program.stream, if usable(). Throws std::runtime_error
  // when the file cannot be read.
  ProgramStream(const std::string& path, uint32_t fileId, std::string stem,
                const ParseOptions& options, size_t pieceBytes, uint32_t lineBound,
                Program& program);
  ~ProgramStream();
  // False when the first blocks showed that the file cannot be streamed after all (nothing but
  // comments, say); the program is then untouched and the file must be compiled whole.
  bool usable() const { return usable_; }

  // The next piece's blocks in place of the current ones; false (nothing changed) at the end.
  bool advance();
  // Index in the whole program of the current piece's first block.
  uint32_t base() const { return base_; }
  // Compiles the file whole into the program and detaches the stream (program.stream becomes
  // nullptr); returns the old base(). The current and last pieces' arrays stay valid until the
  // stream is destroyed (the executor is in the middle of one of their blocks). Throws
  // AlarmError PS9007 when the file changed since it was opened.
  uint32_t materialize();
  // Back to the first piece for another run; a materialized program stays whole.
  void rewind();

  // Lines of the file (at least the line of its last block), for the time table's size.
  uint32_t lineBound() const { return lineBound_; }
  // Line of the first block.
  uint32_t firstLine() const { return firstLine_; }
  // The sequence number of the block on `line` (-1: none), read again from the file.
  int32_t sequenceAt(uint32_t line);

 private:
  struct Piece {
    uint64_t offset = 0;     // in the file
    uint32_t firstLine = 0;  // line of its first byte
    uint32_t bytes = 0;
  };
  struct Identity {
    uint64_t dev = 0, ino = 0, size = 0;
    int64_t mtimeSec = 0, mtimeNsec = 0;
    bool operator==(const Identity&) const = default;
  };
  static Identity identityOf(const std::string& path);
  void start();
  bool compileNext();           // one more piece into the program; records it
  bool unchanged() const;       // the file is still the one opened (identity_)
  void checkUnchanged() const;  // PS9007 otherwise

  std::string path_;
  uint32_t fileId_;
  std::string stem_;
  ParseOptions options_;
  size_t pieceBytes_;
  Program& prog_;
  Identity identity_;
  std::ifstream in_;
  std::unique_ptr<StreamChunks> chunks_;
  std::unique_ptr<LineChunks> counting_;  // chunks_, recording each piece's size
  std::unique_ptr<PieceCompiler> compiler_;
  uint32_t base_ = 0;
  uint64_t offset_ = 0;  // of the next piece
  uint32_t lineBound_ = 1;
  uint32_t firstLine_ = 1;
  bool materialized_ = false;
  bool advanced_ = false;  // past the first piece (rewind() must start again)
  bool usable_ = false;
  std::vector<Piece> pieces_;
  // The last piece's arrays, swapped in as the next piece's storage: a block of the last piece
  // stays valid while the executor moves to the next one.
  std::vector<Block> spareBlocks_;
  std::vector<Word> spareWords_;
  std::vector<Program> retired_;  // arrays replaced by materialize()
};

}  // namespace ncvm
