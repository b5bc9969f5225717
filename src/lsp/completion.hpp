#pragma once
// textDocument/completion: G codes of the machine's series (and M codes) after a G or M,
// system variables after a #, with what each one is.
#include <nlohmann/json.hpp>

#include "lsp/documents.hpp"
#include "machine/setup.hpp"

namespace ncvm::lsp {

// A CompletionList (empty when the cursor is after nothing that completes).
nlohmann::json complete(const Setup& setup, const Document& doc, int line, int character);

}  // namespace ncvm::lsp
