#include "lang/line_chunks.hpp"

#include <algorithm>
#include <cstring>
#include <istream>

#include "lang/count_lines.hpp"

namespace ncvm {

std::string_view TextChunks::next() {
  if (given_) return {};
  given_ = true;
  return text_;
}

size_t TextChunks::lineHint() const {
  return 1 + countNewlines(text_);
}

StreamChunks::StreamChunks(std::istream& in, uint64_t size, size_t chunkBytes)
    : in_(in), size_(size), left_(size) {
  // A small file gets a buffer of its size (plus one byte: the read that finds the end).
  cap_ = static_cast<size_t>(std::min<uint64_t>(std::max<size_t>(chunkBytes, 1), size + 1));
  buf_ = std::make_unique_for_overwrite<char[]>(cap_);
}

bool StreamChunks::fill() {
  if (left_ == 0 || !in_) return false;
  const size_t want = static_cast<size_t>(std::min<uint64_t>(cap_ - have_, left_));
  in_.read(buf_.get() + have_, static_cast<std::streamsize>(want));
  const size_t got = static_cast<size_t>(in_.gcount());
  have_ += got;
  left_ -= got;
  if (got < want) left_ = 0;  // the file shrank: compiled as far as it went
  return got > 0;
}

std::string_view StreamChunks::next() {
  // What the last piece left (the start of a line the buffer cut, no '\n' in it) goes to the
  // front.
  if (given_ > 0) {
    std::memmove(buf_.get(), buf_.get() + given_, have_ - given_);
    have_ -= given_;
    given_ = 0;
  }
  size_t searched = have_;  // buf_[0, searched) holds no '\n'
  while (true) {
    if (have_ < cap_) fill();
    // The last '\n' among the new bytes ends the piece.
    for (size_t k = have_; k > searched; --k)
      if (buf_[k - 1] == '\n') {
        given_ = k;
        break;
      }
    if (given_ > 0) break;
    if (have_ < cap_ || left_ == 0) {
      given_ = have_;  // the end: a last line without '\n', or nothing
      break;
    }
    // One line fills the buffer: make room for more of it.
    searched = have_;
    auto bigger = std::make_unique_for_overwrite<char[]>(cap_ * 2);
    std::memcpy(bigger.get(), buf_.get(), have_);
    buf_ = std::move(bigger);
    cap_ *= 2;
  }
  if (first_) {
    first_ = false;
    // The whole text read: count it; otherwise scale the first piece's lines to the file,
    // with a sixteenth to spare (the lines of a CAM file vary little in length).
    if (left_ == 0) {
      hint_ = 1 + countNewlines(std::string_view(buf_.get(), have_));
    } else {
      const double perByte =
          static_cast<double>(countNewlines(std::string_view(buf_.get(), given_))) /
          static_cast<double>(given_);
      hint_ = static_cast<size_t>(perByte * static_cast<double>(size_) * 17 / 16) + 16;
    }
  }
  return std::string_view(buf_.get(), given_);
}

}  // namespace ncvm
