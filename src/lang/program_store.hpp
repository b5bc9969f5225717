#pragma once
// Every program ncvm can run or call: the files named on the command line, then library
// folders (--lib), then the bundled macros/ folder. The first program with a number or
// name wins; later duplicates are reported as warnings.
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/source.hpp"
#include "lang/line_chunks.hpp"
#include "lang/parser.hpp"
#include "lang/program_stream.hpp"

namespace ncvm {

class ProgramStore {
 public:
  ProgramStore(SourceFiles& files, ParseOptions options, uint64_t maxFileBytes)
      : files_(files), options_(options), maxFileBytes_(maxFileBytes) {}

  // Loads and compiles a file. Returns its programs in file order. Throws
  // std::runtime_error when the file cannot be read; a file larger than the limit becomes
  // a program that raises PS9005.
  std::vector<const Program*> addFile(const std::string& path);
  // Streamed loading (program_stream.hpp) for the next addFile(stream = true): files of at
  // least minBytes that StreamScan accepts, read in pieces of pieceBytes.
  struct StreamOptions {
    uint64_t minBytes = uint64_t{4} << 20;
    size_t pieceBytes = size_t{64} << 10;
  };
  std::vector<const Program*> addFile(const std::string& path, const StreamOptions* stream);
  // Every streamed program back at its first block, for another run.
  void rewindStreams();
  // Same for text already in memory (tests, the server).
  std::vector<const Program*> addText(std::string_view text, const std::string& name);
  // Every program file in a folder (not recursive), in name order, but the one named
  // `except` (a file whose text was added already, as the web viewer's editor text).
  // `accept`, when given, decides for each file found (the server confines a folder's
  // files, symlinks followed, to its roots: server/safe_path.hpp).
  void addFolder(const std::string& dir, std::string_view except = {},
                 const std::function<bool(const std::string&)>& accept = {});

  const Program* byNumber(int32_t number) const;
  const Program* byName(std::string_view name) const;
  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::deque<Program>& programs() const { return programs_; }
  SourceFiles& files() { return files_; }

 private:
  std::vector<const Program*> addChunks(LineChunks& chunks, const std::string& name, uint32_t id);
  void registerProgram(const Program* prog, const std::string& name);
  std::vector<const Program*> addTooLarge(const std::string& path, uintmax_t size);

  SourceFiles& files_;
  ParseOptions options_;
  uint64_t maxFileBytes_;
  std::deque<Program> programs_;  // deque: addresses stay valid as files are added
  std::unordered_map<int32_t, const Program*> byNumber_;
  std::unordered_map<std::string, const Program*> byName_;
  std::vector<std::string> warnings_;
  std::unordered_set<std::string> loadedFiles_;
  std::vector<std::unique_ptr<ProgramStream>> streams_;
};

}  // namespace ncvm
