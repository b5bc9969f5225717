#include "lang/program_store.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/program_files.hpp"
#include "lang/line_chunks.hpp"

namespace ncvm {

std::vector<const Program*> ProgramStore::addText(std::string_view text, const std::string& name) {
  TextChunks chunks(text);
  return addChunks(chunks, name, files_.add(name));
}

std::vector<const Program*> ProgramStore::addChunks(LineChunks& chunks, const std::string& name,
                                                    uint32_t id) {
  std::string stem = std::filesystem::path(name).stem().string();
  ParsedFile parsed = parseProgramChunks(chunks, id, stem, options_);
  if (parsed.unreadLine)
    warnings_.push_back(
        fmt::format("{}:{}: text after the closing '%' is not read (the tape ends there)", name,
                    parsed.unreadLine));
  std::vector<const Program*> added;
  for (auto& p : parsed.programs) {
    p.label = p.displayName();
    programs_.push_back(std::move(p));
    const Program* prog = &programs_.back();
    added.push_back(prog);
    registerProgram(prog, name);
  }
  return added;
}

void ProgramStore::registerProgram(const Program* prog, const std::string& name) {
  if (prog->number >= 0) {
    auto [it, fresh] = byNumber_.emplace(prog->number, prog);
    if (!fresh)
      warnings_.push_back(fmt::format("{}:{}: {} is also in {}; the first one is used", name,
                                      prog->loc.line, prog->displayName(),
                                      files_.name(it->second->loc.file)));
  }
  if (!prog->name.empty()) byName_.emplace(prog->name, prog);
}

void ProgramStore::rewindStreams() {
  for (auto& s : streams_) s->rewind();
}

std::vector<const Program*> ProgramStore::addFile(const std::string& path) {
  return addFile(path, nullptr);
}

std::vector<const Program*> ProgramStore::addFile(const std::string& path,
                                                  const StreamOptions* stream) {
  std::error_code ec;
  // The same file named twice (on the command line and inside a --lib folder) loads once.
  std::string canonical = std::filesystem::weakly_canonical(path, ec).string();
  if (!ec && !loadedFiles_.insert(canonical).second) return {};
  ec.clear();
  auto size = std::filesystem::file_size(path, ec);
  if (ec) throw std::runtime_error(fmt::format("{}: cannot read: {}", path, ec.message()));
  if (size > maxFileBytes_) return addTooLarge(path, size);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot open", path));
  const uint32_t id = files_.add(path);
  uint32_t lines = 0;
  if (stream && size >= stream->minBytes &&
      ProgramStream::scan(path, size, stream->pieceBytes, lines)) {
    // Compiled while it runs, a piece at a time (program_stream.hpp).
    programs_.emplace_back();
    Program& p = programs_.back();
    auto s = std::make_unique<ProgramStream>(path, id, std::filesystem::path(path).stem().string(),
                                             options_, stream->pieceBytes, lines, p);
    if (s->usable()) {
      p.label = p.displayName();
      streams_.push_back(std::move(s));
      registerProgram(&p, path);
      return {&p};
    }
    programs_.pop_back();
  }
  // Compiled as it is read, through one reused buffer (line_chunks.hpp): the text is never
  // held whole. Not mmap: a file truncated while it is compiled must not kill the process
  // with SIGBUS. A file that shrank since file_size is compiled as far as it was read.
  StreamChunks chunks(in, size);
  return addChunks(chunks, path, id);
}

// A file over limits.max_file_bytes is not read: like a control whose memory is full, it
// becomes one program whose only block raises PS9005 when it runs (or is checked).
std::vector<const Program*> ProgramStore::addTooLarge(const std::string& path, uintmax_t size) {
  Program p;
  p.name = std::filesystem::path(path).stem().string();
  p.loc = SourceLoc{files_.add(path), 1, 1};
  p.label = p.displayName();
  p.errors.push_back(Alarm{alarmCode(AlarmId::ProgramTooLarge),
                           fmt::format("{} ({} bytes; limits.max_file_bytes = {})",
                                       alarmMessage(AlarmId::ProgramTooLarge), size, maxFileBytes_),
                           p.loc, std::nullopt, -1});
  Block b;
  b.kind = BlockKind::Error;
  b.loc = p.loc;
  p.macroOps.push_back(MacroOps{});
  p.macroOps.back().error = 0;
  b.ops = 0;
  p.blocks.push_back(b);
  programs_.push_back(std::move(p));
  return {&programs_.back()};
}

void ProgramStore::addFolder(const std::string& dir, std::string_view except,
                             const std::function<bool(const std::string&)>& accept) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw std::runtime_error(dir + ": not a folder");
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (!e.is_regular_file() || (!except.empty() && e.path().filename() == except)) continue;
    if (isProgramFileName(e.path())) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files)
    if (!accept || accept(f.string())) addFile(f.string());
}

const Program* ProgramStore::byNumber(int32_t number) const {
  auto it = byNumber_.find(number);
  return it == byNumber_.end() ? nullptr : it->second;
}

const Program* ProgramStore::byName(std::string_view name) const {
  auto it = byName_.find(std::string(name));
  return it == byName_.end() ? nullptr : it->second;
}

}  // namespace ncvm
