#pragma once
// The documents the editor has open (full text sync), file URIs, and LSP positions.
// LSP counts columns in UTF-16 code units; ncvm's alarms count bytes from 1.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ncvm::lsp {

struct Document {
  std::string uri;
  std::string path;  // the file the URI names ("" for a URI that is no file:)
  std::string text;
  int version = 0;
  // Lines without their end (CR LF or LF), as views into text.
  std::vector<std::string_view> lines() const;
  std::string_view line(size_t index) const;  // "" past the end
};

class DocumentStore {
 public:
  Document& open(const std::string& uri, std::string text, int version);
  // Full sync: the new text replaces the old. nullptr if the document is not open.
  Document* change(const std::string& uri, std::string text, int version);
  void close(const std::string& uri) { docs_.erase(uri); }
  Document* find(const std::string& uri);
  const std::map<std::string, Document>& all() const { return docs_; }

 private:
  std::map<std::string, Document> docs_;
};

// file:///a/b%20c.nc <-> /a/b c.nc ("" when the URI is no file: URI).
std::string uriToPath(std::string_view uri);
std::string pathToUri(std::string_view path);

// A byte column (0-based) in a line as a UTF-16 column, and back.
int utf16Column(std::string_view line, size_t byteColumn);
size_t byteColumn(std::string_view line, int utf16Column);

}  // namespace ncvm::lsp
