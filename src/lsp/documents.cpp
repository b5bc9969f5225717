#include "lsp/documents.hpp"

#include <fmt/format.h>

namespace ncvm::lsp {

std::vector<std::string_view> Document::lines() const {
  std::vector<std::string_view> out;
  std::string_view rest = text;
  while (true) {
    const size_t eol = rest.find('\n');
    std::string_view line = rest.substr(0, eol);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    out.push_back(line);
    if (eol == std::string_view::npos) break;
    rest.remove_prefix(eol + 1);
  }
  return out;
}

std::string_view Document::line(size_t index) const {
  std::string_view rest = text;
  for (size_t k = 0; k < index; ++k) {
    const size_t eol = rest.find('\n');
    if (eol == std::string_view::npos) return {};
    rest.remove_prefix(eol + 1);
  }
  std::string_view line = rest.substr(0, rest.find('\n'));
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

Document& DocumentStore::open(const std::string& uri, std::string text, int version) {
  Document& d = docs_[uri];
  d.uri = uri;
  d.path = uriToPath(uri);
  d.text = std::move(text);
  d.version = version;
  return d;
}

Document* DocumentStore::change(const std::string& uri, std::string text, int version) {
  Document* d = find(uri);
  if (!d) return nullptr;
  d->text = std::move(text);
  d->version = version;
  return d;
}

Document* DocumentStore::find(const std::string& uri) {
  auto it = docs_.find(uri);
  return it == docs_.end() ? nullptr : &it->second;
}

namespace {
int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}
}  // namespace

std::string uriToPath(std::string_view uri) {
  constexpr std::string_view scheme = "file://";
  if (uri.substr(0, scheme.size()) != scheme) return {};
  uri.remove_prefix(scheme.size());
  // file://host/path: only the local host (empty or localhost) is a file here.
  const size_t slash = uri.find('/');
  if (slash == std::string_view::npos) return {};
  const std::string_view host = uri.substr(0, slash);
  if (!host.empty() && host != "localhost") return {};
  uri.remove_prefix(slash);
  std::string out;
  for (size_t k = 0; k < uri.size(); ++k) {
    if (uri[k] == '%' && k + 2 < uri.size() && hexValue(uri[k + 1]) >= 0 &&
        hexValue(uri[k + 2]) >= 0) {
      out.push_back(static_cast<char>(hexValue(uri[k + 1]) * 16 + hexValue(uri[k + 2])));
      k += 2;
    } else {
      out.push_back(uri[k]);
    }
  }
  return out;
}

std::string pathToUri(std::string_view path) {
  std::string out = "file://";
  for (char c : path) {
    const auto u = static_cast<unsigned char>(c);
    const bool plain = (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || (u >= '0' && u <= '9') ||
                       c == '/' || c == '-' || c == '_' || c == '.' || c == '~';
    if (plain)
      out.push_back(c);
    else
      out += fmt::format("%{:02X}", u);
  }
  return out;
}

// UTF-8 lead bytes start a code point; four-byte ones are two UTF-16 units (a surrogate pair).
int utf16Column(std::string_view line, size_t byteColumn) {
  int units = 0;
  for (size_t k = 0; k < line.size() && k < byteColumn; ++k) {
    const auto u = static_cast<unsigned char>(line[k]);
    if ((u & 0xC0) == 0x80) continue;  // continuation byte
    units += u >= 0xF0 ? 2 : 1;
  }
  if (byteColumn > line.size()) units += static_cast<int>(byteColumn - line.size());
  return units;
}

size_t byteColumn(std::string_view line, int utf16Column) {
  int units = 0;
  size_t k = 0;
  while (k < line.size() && units < utf16Column) {
    const auto u = static_cast<unsigned char>(line[k]);
    units += u >= 0xF0 ? 2 : 1;
    ++k;
    while (k < line.size() && (static_cast<unsigned char>(line[k]) & 0xC0) == 0x80) ++k;
  }
  return k;
}

}  // namespace ncvm::lsp
