#include "server/safe_path.hpp"

namespace ncvm::server {

namespace fs = std::filesystem;

bool isPlainRelative(std::string_view relative) {
  if (relative.size() > 1024) return false;
  if (!relative.empty() && relative.front() == '/') return false;
  if (relative.find('\0') != std::string_view::npos ||
      relative.find('\\') != std::string_view::npos)
    return false;
  size_t start = 0;
  while (start <= relative.size()) {
    size_t end = relative.find('/', start);
    if (end == std::string_view::npos) end = relative.size();
    if (relative.substr(start, end - start) == "..") return false;
    start = end + 1;
  }
  return true;
}

namespace {
// Both canonical: the components of `base` begin those of `full`.
bool startsWith(const fs::path& full, const fs::path& base) {
  auto b = base.begin(), f = full.begin();
  for (; b != base.end(); ++b, ++f)
    if (f == full.end() || *f != *b) return false;
  return true;
}
}  // namespace

bool isInside(const fs::path& root, const fs::path& path) {
  std::error_code ec;
  fs::path base = fs::canonical(root, ec);
  if (ec) return false;
  fs::path full = fs::canonical(path, ec);
  return !ec && startsWith(full, base);
}

std::optional<fs::path> resolveInside(const fs::path& root, std::string_view relative) {
  if (!isPlainRelative(relative)) return std::nullopt;
  std::error_code ec;
  fs::path base = fs::canonical(root, ec);
  if (ec) return std::nullopt;
  // canonical() follows every symlink, so the prefix test below sees where the file really is.
  fs::path full = fs::canonical(base / fs::path(std::string(relative)), ec);
  if (ec || !startsWith(full, base)) return std::nullopt;
  return full;
}

}  // namespace ncvm::server
