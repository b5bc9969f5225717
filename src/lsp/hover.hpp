#pragma once
// textDocument/hover: what the word under the cursor means (G and M codes from the code
// tables, address letters, macro variables and keywords).
#include <nlohmann/json.hpp>

#include "lsp/documents.hpp"
#include "machine/setup.hpp"

namespace ncvm::lsp {

// A Hover object, or null when there is nothing to say. line and character are LSP's.
nlohmann::json hover(const Setup& setup, const Document& doc, int line, int character);

}  // namespace ncvm::lsp
