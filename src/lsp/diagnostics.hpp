#pragma once
// The diagnostics of a document: what `ncvm check` finds (Session::check) and what a dry
// run of its first program raises (Session::run, bounded by ServerOptions::dryRunBlocks),
// each at its line and word. A subprogram (M99 and no M02/M30) is only checked: its run
// belongs to the program that calls it, whose diagnostics name the subprogram's lines.
#include <nlohmann/json.hpp>

#include "lsp/workspace.hpp"

namespace ncvm::lsp {

// An array of LSP Diagnostic objects.
nlohmann::json diagnose(const Setup& setup, const ServerOptions& options, const DocumentStore& docs,
                        const Document& doc);

}  // namespace ncvm::lsp
