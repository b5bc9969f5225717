#pragma once
// textDocument/documentSymbol: the document's programs (O numbers and <names>), each with
// its N labels, as ncvm's parser reads them.
#include <nlohmann/json.hpp>

#include "lsp/workspace.hpp"

namespace ncvm::lsp {

// An array of DocumentSymbol objects.
nlohmann::json documentSymbols(const Setup& setup, const ServerOptions& options,
                               const DocumentStore& docs, const Document& doc);

}  // namespace ncvm::lsp
