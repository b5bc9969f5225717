#include "server/file_catalog.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/program_files.hpp"
#include "server/safe_path.hpp"

namespace ncvm::server {

namespace fs = std::filesystem;

namespace {
constexpr size_t kMaxListed = 1000;
constexpr int kMaxDepth = 6;

std::optional<std::string> slurp(const fs::path& p, uint64_t maxBytes) {
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) return std::nullopt;
  auto size = fs::file_size(p, ec);
  if (ec || size > maxBytes) return std::nullopt;
  std::ifstream in(p, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

void FileCatalog::add(const std::string& name, const fs::path& path) {
  std::string unique = name.empty() ? "files" : name;
  for (int k = 2; find(unique); ++k) unique = name + "-" + std::to_string(k);
  roots_.push_back({unique, path});
}

const Root* FileCatalog::find(const std::string& name) const {
  for (const auto& r : roots_)
    if (r.name == name) return &r;
  return nullptr;
}

std::string setupFor(const Root& root, const std::string& programPath) {
  const fs::path p(programPath);
  for (const auto& name : setupCandidates(p)) {
    const std::string c = (p.parent_path() / name).generic_string();
    if (auto full = resolveInside(root.path, c); full && fs::is_regular_file(*full)) return c;
  }
  return {};
}

nlohmann::json FileCatalog::list() const {
  nlohmann::json out{{"roots", nlohmann::json::array()}};
  for (const auto& r : roots_) {
    std::vector<std::string> files;
    std::error_code ec;
    auto base = fs::canonical(r.path, ec);
    if (!ec) {
      fs::recursive_directory_iterator it(base, fs::directory_options::skip_permission_denied, ec),
          end;
      for (; !ec && it != end && files.size() < kMaxListed; it.increment(ec)) {
        if (it.depth() >= kMaxDepth) it.disable_recursion_pending();
        if (!isProgramFileName(it->path())) continue;
        std::string rel = fs::relative(it->path(), base, ec).generic_string();
        // Listed only what read() would serve: a symlink out of the root is not.
        if (!ec && resolveInside(base, rel) && fs::is_regular_file(it->path(), ec))
          files.push_back(rel);
      }
    }
    std::sort(files.begin(), files.end());
    nlohmann::json list = nlohmann::json::array();
    for (const auto& f : files) {
      std::string setup = setupFor(r, f);
      list.push_back({{"path", f},
                      {"setup", setup.empty() ? nlohmann::json(nullptr) : nlohmann::json(setup)}});
    }
    out["roots"].push_back({{"name", r.name}, {"files", list}});
  }
  return out;
}

std::optional<nlohmann::json> FileCatalog::read(const std::string& root, const std::string& path,
                                                uint64_t maxBytes) const {
  const Root* r = find(root);
  if (!r || path.empty()) return std::nullopt;
  auto full = resolveInside(r->path, path);
  if (!full) return std::nullopt;
  auto text = slurp(*full, maxBytes);
  if (!text) return std::nullopt;
  nlohmann::json out{
      {"root", root}, {"path", path}, {"text", *text}, {"setup", nullptr}, {"setup_path", nullptr}};
  out["dir"] = fs::path(path).parent_path().generic_string();
  if (auto setup = setupOf(root, path, maxBytes)) {
    out["setup"] = setup->second;
    out["setup_path"] = setup->first;
  }
  return out;
}

std::optional<std::pair<std::string, std::string>> FileCatalog::setupOf(
    const std::string& root, const std::string& programPath, uint64_t maxBytes) const {
  const Root* r = find(root);
  if (!r) return std::nullopt;
  std::string setup = setupFor(*r, programPath);
  if (setup.empty()) return std::nullopt;
  auto full = resolveInside(r->path, setup);
  if (!full) return std::nullopt;
  auto text = slurp(*full, maxBytes);
  if (!text) return std::nullopt;
  return std::pair{setup, *text};
}

std::optional<fs::path> FileCatalog::folder(const std::string& root, const std::string& dir) const {
  const Root* r = find(root);
  if (!r) return std::nullopt;
  auto full = resolveInside(r->path, dir);
  std::error_code ec;
  if (!full || !fs::is_directory(*full, ec)) return std::nullopt;
  return full;
}

}  // namespace ncvm::server
