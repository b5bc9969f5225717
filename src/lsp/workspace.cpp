#include "lsp/workspace.hpp"

#include <filesystem>
#include <set>

#include "core/program_files.hpp"

namespace ncvm::lsp {

Setup setupForDocument(const Setup& serverSetup, const ServerOptions& options,
                       const Document& doc) {
  if (!options.setupPaths.empty() || doc.path.empty()) return serverSetup;
  const std::filesystem::path beside = setupFileFor(doc.path);
  if (beside.empty()) return serverSetup;
  Setup s = defaultSetup();
  loadSetupInto(s, beside.string());
  for (const auto& kv : options.sets) applySetting(s, kv);
  return s;
}

std::string documentName(const Document& doc) {
  return doc.path.empty() ? doc.uri : doc.path;
}

namespace {
std::string canonical(const std::string& path) {
  std::error_code ec;
  auto c = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : c.string();
}
}  // namespace

std::unique_ptr<Session> openWorkspace(const Setup& setup, const ServerOptions& options,
                                       const DocumentStore& docs, const Document& doc,
                                       Reach reach) {
  auto session = std::make_unique<Session>(setup);
  session->addProgramText(doc.text, documentName(doc));
  if (reach == Reach::DocumentOnly) return session;
  // The open documents' files are read from the editor, not from the disk.
  std::set<std::string> open;
  for (const auto& [uri, other] : docs.all()) {
    if (!other.path.empty()) open.insert(canonical(other.path));
    if (uri != doc.uri) session->addProgramText(other.text, documentName(other));
  }
  const auto notOpen = [&open](const std::string& file) { return !open.count(canonical(file)); };
  std::vector<std::string> folders;
  if (!doc.path.empty()) folders.push_back(std::filesystem::path(doc.path).parent_path().string());
  folders.insert(folders.end(), options.libs.begin(), options.libs.end());
  if (!options.noMacros) folders.push_back(bundledMacrosFolder());
  for (const auto& dir : folders) {
    if (dir.empty()) continue;
    try {
      session->store().addFolder(dir, {}, notOpen);
    } catch (const std::exception&) {
      // An unreadable folder or file: what it would have held is missing, and the dry run
      // says so where the program calls it.
    }
  }
  return session;
}

}  // namespace ncvm::lsp

namespace ncvm::lsp {
const Program* programAt(Session& session, uint32_t file, uint32_t line) {
  const Program* best = nullptr;
  for (const Program& p : session.store().programs())
    if (p.loc.file == file && p.loc.line <= line && (!best || p.loc.line >= best->loc.line))
      best = &p;
  return best;
}
}  // namespace ncvm::lsp
