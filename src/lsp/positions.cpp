#include "lsp/positions.hpp"

#include "lsp/documents.hpp"
#include "lsp/nc_tokens.hpp"

namespace ncvm::lsp {

nlohmann::json position(int line, std::string_view lineText, size_t byteCol) {
  return {{"line", line}, {"character", utf16Column(lineText, byteCol)}};
}

nlohmann::json range(int line, std::string_view lineText, size_t begin, size_t end) {
  return {{"start", position(line, lineText, begin)}, {"end", position(line, lineText, end)}};
}

nlohmann::json wordRange(int line, std::string_view lineText, uint32_t col) {
  if (col == 0 || col > lineText.size()) return range(line, lineText, 0, lineText.size());
  const size_t begin = col - 1;
  if (auto t = tokenAt(lineText, begin); t && t->begin == begin)
    return range(line, lineText, t->begin, t->end);
  return range(line, lineText, begin, begin + 1);
}

}  // namespace ncvm::lsp
