#pragma once
// `ncvm lsp`: the server on standard input and output. Reads frames as they come, answers
// each message, and publishes a changed document's diagnostics once the editor has been
// quiet for a moment (a dry run per keystroke would be wasted work).
#include "lsp/workspace.hpp"
#include "machine/setup.hpp"

namespace ncvm::lsp {

// Runs until `exit` (or the end of input); returns the process exit status.
// debounceMs: the quiet spell after a change before its diagnostics are computed.
int runStdioServer(int inFd, int outFd, Setup setup, ServerOptions options, int debounceMs = 300);

}  // namespace ncvm::lsp
