#include "core/program_files.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>

namespace ncvm {

namespace fs = std::filesystem;

namespace {
std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool isProgramName(std::string_view name) {
  if (name.size() < 2 || (name[0] != 'O' && name[0] != 'o')) return false;
  return std::all_of(name.begin() + 1, name.end(),
                     [](unsigned char c) { return std::isdigit(c) != 0; });
}
}  // namespace

bool isProgramFileName(const fs::path& file) {
  static constexpr std::array<std::string_view, 9> kExtensions{
      ".nc", ".tap", ".txt", ".min", ".cnc", ".ptp", ".eia", ".iso", ".anc"};
  // A CMake project file beside the examples (examples/embed) is .txt but never a program.
  if (lower(file.filename().string()) == "cmakelists.txt") return false;
  const std::string ext = lower(file.extension().string());
  if (ext.empty()) return isProgramName(file.filename().string());
  return std::find(kExtensions.begin(), kExtensions.end(), ext) != kExtensions.end();
}

std::vector<std::string> setupCandidates(const fs::path& program) {
  std::vector<std::string> names;
  std::string stem = program.filename().string();
  if (program.has_extension()) stem = program.stem().string();
  while (!stem.empty()) {
    names.push_back(stem + ".toml");
    const auto dash = stem.rfind('-');
    if (dash == std::string::npos || dash == 0) break;
    stem.resize(dash);
  }
  if (std::find(names.begin(), names.end(), "setup.toml") == names.end())
    names.push_back("setup.toml");
  return names;
}

fs::path setupFileFor(const fs::path& program) {
  std::error_code ec;
  for (const auto& name : setupCandidates(program)) {
    fs::path candidate = program.parent_path() / name;
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  return {};
}

std::vector<fs::path> programFilesUnder(const fs::path& dir, int depth) {
  std::vector<fs::path> files;
  std::error_code ec;
  fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    if (it.depth() >= depth) it.disable_recursion_pending();
    std::error_code fileEc;
    if (isProgramFileName(it->path()) && it->is_regular_file(fileEc)) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace ncvm
