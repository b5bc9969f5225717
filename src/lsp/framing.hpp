#pragma once
// The base protocol of LSP: each JSON-RPC message is a header ("Content-Length: N", CRLF
// lines, a blank line) and N bytes of JSON. The decoder takes bytes as they arrive (one
// read may hold half a header or three messages) and hands out whole bodies.
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ncvm::lsp {

// A header the server cannot read (no Content-Length, a bad number, a body above the limit):
// the stream is out of step and the session ends.
class FramingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class FrameDecoder {
 public:
  // Bodies larger than this are refused (an editor sends a whole document per change).
  explicit FrameDecoder(size_t maxBody = size_t{64} << 20) : maxBody_(maxBody) {}
  void feed(std::string_view bytes) { buffer_.append(bytes); }
  // The next whole body, if one has arrived. Throws FramingError.
  std::optional<std::string> next();
  // Whether bytes wait that next() has not consumed (a part of a message, or more).
  bool pending() const { return !buffer_.empty(); }

 private:
  std::string buffer_;
  size_t maxBody_;
};

// The body with its header, ready to write.
std::string encodeFrame(std::string_view body);

}  // namespace ncvm::lsp
