#pragma once
// textDocument/definition: from a call to the program it calls (M98 P, G65 P, G66 P, M98 <name>,
// and the setup's G, M and T code calls) and from GOTO n to its N label.
#include <nlohmann/json.hpp>

#include "lsp/workspace.hpp"

namespace ncvm::lsp {

// A Location, or null when the word under the cursor leads nowhere that is loaded.
nlohmann::json definition(const Setup& setup, const ServerOptions& options,
                          const DocumentStore& docs, const Document& doc, int line, int character);

// The program number a block's call reaches: `callP` is the P of M98/G65/G66 as written.
// M98 P12340100 with 4-digit program numbers repeats O0100 1234 times.
int calledProgram(long long callP, bool m98, const Setup& setup);

}  // namespace ncvm::lsp
