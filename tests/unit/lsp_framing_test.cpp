// The LSP base protocol: Content-Length frames, split and joined as a pipe delivers them.
#include <gtest/gtest.h>

#include "lsp/framing.hpp"

using namespace ncvm::lsp;

TEST(LspFraming, EncodesTheLengthInBytes) {
  EXPECT_EQ(encodeFrame("{\"a\":\"\xc3\xa9\"}"), "Content-Length: 10\r\n\r\n{\"a\":\"\xc3\xa9\"}");
}

TEST(LspFraming, DecodesAMessageThatArrivesAByteAtATime) {
  const std::string frame = encodeFrame(R"({"id":1})");
  FrameDecoder d;
  for (size_t k = 0; k + 1 < frame.size(); ++k) {
    d.feed(frame.substr(k, 1));
    EXPECT_FALSE(d.next()) << "after " << k + 1 << " bytes";
  }
  d.feed(frame.substr(frame.size() - 1));
  EXPECT_EQ(d.next(), R"({"id":1})");
  EXPECT_FALSE(d.pending());
}

TEST(LspFraming, SplitsTwoMessagesInOneRead) {
  FrameDecoder d;
  d.feed(encodeFrame("[1]") + encodeFrame("[22]"));
  EXPECT_EQ(d.next(), "[1]");
  EXPECT_EQ(d.next(), "[22]");
  EXPECT_FALSE(d.next());
}

TEST(LspFraming, IgnoresOtherHeadersAndTheCaseOfTheName) {
  FrameDecoder d;
  d.feed("content-type: application/vscode-jsonrpc; charset=utf-8\r\ncontent-length:  2\r\n\r\n{}");
  EXPECT_EQ(d.next(), "{}");
}

TEST(LspFraming, RefusesAHeaderWithoutLengthOrWithABadOne) {
  FrameDecoder a;
  a.feed("Content-Type: x\r\n\r\n{}");
  EXPECT_THROW(a.next(), FramingError);
  FrameDecoder b;
  b.feed("Content-Length: 12x\r\n\r\n{}");
  EXPECT_THROW(b.next(), FramingError);
  FrameDecoder c(100);
  c.feed("Content-Length: 101\r\n\r\n");
  EXPECT_THROW(c.next(), FramingError);
  FrameDecoder e;
  e.feed(std::string(9000, 'x'));  // no end of header in sight
  EXPECT_THROW(e.next(), FramingError);
}
