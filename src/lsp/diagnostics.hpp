#pragma once
// The diagnostics of a document: what `ncvm check` finds (Session::check) and what a dry
// run of its first program raises (Session::run, bounded by ServerOptions::dryRunBlocks),
// each at its line and word.
#include <nlohmann/json.hpp>

#include "lsp/workspace.hpp"

namespace ncvm::lsp {

// An array of LSP Diagnostic objects.
nlohmann::json diagnose(const Setup& setup, const ServerOptions& options, const DocumentStore& docs,
                        const Document& doc);

}  // namespace ncvm::lsp
