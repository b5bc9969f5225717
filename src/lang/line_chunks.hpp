#pragma once
// Program text handed to the compiler in pieces of whole lines, so a large file is never held
// whole: the compiled program keeps nothing of its text (comments are copied, alarms keep
// line and column), and a 25 MB CAM file read into one buffer cost 25 MB of fresh pages for
// the kernel to zero. A reused buffer of a few hundred KB stays in the cache instead.
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string_view>

namespace ncvm {

class LineChunks {
 public:
  virtual ~LineChunks() = default;
  // The next piece of the text: whole lines, each ending in '\n', except that the last piece
  // may end in a line without one. Valid until the next call; empty at the end of the text.
  virtual std::string_view next() = 0;
  // About how many lines the whole text has, to size the program's arrays once (a guess is
  // only a cost: too low, they grow; too high, untouched memory). Asked after the first next().
  virtual size_t lineHint() const = 0;
};

// Text already in memory: one piece.
class TextChunks final : public LineChunks {
 public:
  explicit TextChunks(std::string_view text) : text_(text) {}
  std::string_view next() override;
  size_t lineHint() const override;

 private:
  std::string_view text_;
  bool given_ = false;
};

// A stream read through one buffer of `chunkBytes` that is reused for every piece; it grows
// (doubling) only for a line longer than itself. At most `size` bytes are read (the file's
// size when it was opened: a file that grows meanwhile is read as it was, one that shrinks
// as far as it goes).
class StreamChunks final : public LineChunks {
 public:
  static constexpr size_t kChunkBytes = size_t{256} << 10;
  StreamChunks(std::istream& in, uint64_t size, size_t chunkBytes = kChunkBytes);
  std::string_view next() override;
  size_t lineHint() const override { return hint_; }

 private:
  bool fill();  // reads into the free end of the buffer; false at the end of the input

  std::istream& in_;
  uint64_t size_, left_;
  std::unique_ptr<char[]> buf_;
  size_t cap_ = 0;
  size_t have_ = 0;    // bytes in buf_
  size_t given_ = 0;   // buf_[0, given_) was returned by the last next()
  bool first_ = true;  // the first piece sets hint_
  size_t hint_ = 1;
};

}  // namespace ncvm
