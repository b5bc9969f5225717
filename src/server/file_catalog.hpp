#pragma once
// The folders the server may read programs from (the bundled examples, --root folders, the
// folder of the PROGRAM given on the command line): listing them, and reading one program
// with its setup, always through safe_path.hpp.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ncvm::server {

struct Root {
  std::string name;  // how the API names it: "examples", or the folder's name
  std::filesystem::path path;
};

class FileCatalog {
 public:
  // Names are made unique ("parts", "parts-2").
  void add(const std::string& name, const std::filesystem::path& path);
  const std::vector<Root>& roots() const { return roots_; }
  const Root* find(const std::string& name) const;

  // {"roots": [{"name", "files": [{"path", "setup"}]}]}: the program files of each root
  // (core/program_files.hpp) (at most
  // 1000 per root, 6 folders deep), with the setup each one runs with.
  nlohmann::json list() const;

  // A program and its setup: {"root", "path", "text", "setup", "setup_path", "dir"}; nullopt
  // when the path is not a readable file inside the root or is larger than maxBytes.
  std::optional<nlohmann::json> read(const std::string& root, const std::string& path,
                                     uint64_t maxBytes) const;

  // The setup file programPath runs with (setupFor) and its text: {path, text}, if any.
  std::optional<std::pair<std::string, std::string>> setupOf(const std::string& root,
                                                             const std::string& programPath,
                                                             uint64_t maxBytes) const;
  // The folder `dir` of a root as a canonical path (for M98/G65 calls), if it is one.
  std::optional<std::filesystem::path> folder(const std::string& root,
                                              const std::string& dir) const;

 private:
  std::vector<Root> roots_;
};

// The setup a program runs with, by the rule of core/program_files.hpp that `make demo` uses
// too (a path relative to the root, or empty).
std::string setupFor(const Root& root, const std::string& programPath);

}  // namespace ncvm::server
