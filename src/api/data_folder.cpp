#include "api/data_folder.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>

#ifndef NCVM_SOURCE_DATA
#define NCVM_SOURCE_DATA ""
#endif

namespace ncvm::api {

namespace fs = std::filesystem;

namespace {
// A folder is ncvm's data when it holds the bundled macros.
bool isDataFolder(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir / "macros", ec);
}
}  // namespace

std::string findDataFolder() {
  if (const char* env = std::getenv("NCVM_DATA"); env && *env) return env;
  // The file this function was loaded from: libncvm.so, the Python module, or an executable
  // that links the engine statically.
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&findDataFolder), &info) && info.dli_fname) {
    std::error_code ec;
    fs::path self = fs::weakly_canonical(info.dli_fname, ec);
    // PREFIX/lib/libncvm.so is 2 levels below PREFIX, PREFIX/lib/python3/dist-packages/ncvm/
    // _ncvm.so 5: look a few levels up for share/ncvm.
    fs::path dir = self.parent_path();
    for (int up = 0; up < 6 && !dir.empty(); ++up) {
      if (isDataFolder(dir / "share" / "ncvm")) return (dir / "share" / "ncvm").string();
      if (dir == dir.parent_path()) break;
      dir = dir.parent_path();
    }
  }
  if (isDataFolder(NCVM_SOURCE_DATA)) return NCVM_SOURCE_DATA;
  return {};
}

std::string presetPath(const std::string& name) {
  const std::string data = findDataFolder();
  if (data.empty() || name.empty() || name.find('/') != std::string::npos) return {};
  fs::path p = fs::path(data) / "presets" / (name + ".toml");
  std::error_code ec;
  return fs::is_regular_file(p, ec) ? p.string() : std::string();
}

}  // namespace ncvm::api
