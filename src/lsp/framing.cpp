#include "lsp/framing.hpp"

#include <cctype>
#include <charconv>

namespace ncvm::lsp {

namespace {
bool startsWithNoCase(std::string_view s, std::string_view prefix) {
  if (s.size() < prefix.size()) return false;
  for (size_t k = 0; k < prefix.size(); ++k)
    if (std::tolower(static_cast<unsigned char>(s[k])) !=
        std::tolower(static_cast<unsigned char>(prefix[k])))
      return false;
  return true;
}
}  // namespace

std::optional<std::string> FrameDecoder::next() {
  const size_t end = buffer_.find("\r\n\r\n");
  if (end == std::string::npos) {
    if (buffer_.size() > 8192) throw FramingError("LSP header longer than 8 KiB");
    return std::nullopt;
  }
  std::string_view header(buffer_.data(), end);
  std::optional<size_t> length;
  while (!header.empty()) {
    const size_t eol = header.find("\r\n");
    std::string_view line = header.substr(0, eol);
    header = eol == std::string_view::npos ? std::string_view{} : header.substr(eol + 2);
    constexpr std::string_view key = "content-length:";
    if (!startsWithNoCase(line, key)) continue;  // Content-Type and others: ignored
    std::string_view value = line.substr(key.size());
    while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
    while (!value.empty() && value.back() == ' ') value.remove_suffix(1);
    size_t n = 0;
    auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (ec != std::errc() || ptr != value.data() + value.size() || value.empty())
      throw FramingError("bad Content-Length: " + std::string(value));
    length = n;
  }
  if (!length) throw FramingError("LSP header without Content-Length");
  if (*length > maxBody_) throw FramingError("LSP message larger than the limit");
  const size_t start = end + 4;
  if (buffer_.size() - start < *length) return std::nullopt;
  std::string body = buffer_.substr(start, *length);
  buffer_.erase(0, start + *length);
  return body;
}

std::string encodeFrame(std::string_view body) {
  std::string out = "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n";
  out.append(body);
  return out;
}

}  // namespace ncvm::lsp
