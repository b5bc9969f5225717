#pragma once
// LSP ranges from ncvm's source locations (1-based line and byte column).
#include <nlohmann/json.hpp>
#include <string_view>

namespace ncvm::lsp {

// {line, character} with a UTF-16 character in `lineText` at byte column `byteCol` (0-based).
nlohmann::json position(int line, std::string_view lineText, size_t byteCol);
// From byte column `begin` to `end` of one line.
nlohmann::json range(int line, std::string_view lineText, size_t begin, size_t end);
// The range of the word at 1-based byte column `col` of a line (col 0: the whole line).
nlohmann::json wordRange(int line, std::string_view lineText, uint32_t col);

}  // namespace ncvm::lsp
