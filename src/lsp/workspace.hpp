#pragma once
// The programs an open document sees, compiled by ncvm's own loader (app/session.hpp): the
// document first (its first program is the one the dry run runs), then the other open
// documents as the editor holds them (unsaved text wins over the file), the document's
// folder, the --lib folders and the bundled macros, in that order (the first program of a
// number is the one a call reaches, as in `ncvm run`).
#include <memory>
#include <string>
#include <vector>

#include "app/session.hpp"
#include "lsp/documents.hpp"

namespace ncvm::lsp {

struct ServerOptions {
  std::vector<std::string> libs;        // --lib DIR
  std::vector<std::string> setupPaths;  // --setup FILE
  std::vector<std::string> sets;        // --set KEY=VALUE
  bool noMacros = false;
  // The dry run stops after this many blocks (PS9001), so that a program that loops for
  // ever cannot hold the server: the setup's limits.max_blocks when that is smaller.
  uint64_t dryRunBlocks = 200'000;
};

// The setup a document is checked with: the server's (--setup, --set) when it was given
// --setup; else the setup file beside the document by the rule of `ncvm list`, `ncvm serve`
// and `make demo` (core/program_files.hpp: NAME.toml, BASE.toml, setup.toml), with the
// --set values; else the server's. Throws SetupError for a setup file that does not load.
Setup setupForDocument(const Setup& serverSetup, const ServerOptions& options, const Document& doc);

// The name the document's programs carry in alarms: its path, or the URI when it is no file.
std::string documentName(const Document& doc);

enum class Reach { DocumentOnly, Everything };

// A session over the document (file id 0) and, with Reach::Everything, all it can call.
// Folders that cannot be read are left out (the run then says which program is missing).
std::unique_ptr<Session> openWorkspace(const Setup& setup, const ServerOptions& options,
                                       const DocumentStore& docs, const Document& doc, Reach reach);

}  // namespace ncvm::lsp

namespace ncvm::lsp {
// The program of file `file` whose text holds 1-based `line` (the last one that starts at or
// before it), nullptr if none.
const Program* programAt(Session& session, uint32_t file, uint32_t line);
}  // namespace ncvm::lsp
