#include "server/setup_layers.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "server/safe_path.hpp"
#include "server/web_server.hpp"

namespace ncvm::server {

namespace fs = std::filesystem;

namespace {

std::optional<std::string> readSmallFile(const fs::path& p, uint64_t maxBytes) {
  std::error_code ec;
  if (!fs::is_regular_file(p, ec) || fs::file_size(p, ec) > maxBytes || ec) return std::nullopt;
  std::ifstream in(p, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) return std::nullopt;
  return text.str();
}

// The folder a layer's root names: the presets, or one of the catalog's folders.
std::optional<fs::path> layerRoot(const std::string& root, const ServerConfig& cf) {
  if (root == "presets") {
    if (cf.presetsDir.empty()) return std::nullopt;
    return fs::path(cf.presetsDir);
  }
  if (const Root* r = cf.catalog.find(root)) return r->path;
  return std::nullopt;
}

std::vector<std::string> tomlFiles(const fs::path& root) {
  std::vector<std::string> out;
  std::error_code ec;
  fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec), end;
  for (; !ec && it != end && out.size() < 1000; it.increment(ec)) {
    if (it.depth() > 5) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->path().extension() != ".toml") continue;
    const std::string rel = fs::relative(it->path(), root, ec).generic_string();
    if (ec || !isPlainRelative(rel)) continue;
    if (auto inside = resolveInside(root, rel); inside && fs::is_regular_file(*inside, ec))
      out.push_back(rel);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// A private folder for one layer's text, removed with it.
struct TempSetupFile {
  fs::path dir, file;
  explicit TempSetupFile(const std::string& text) {
    std::string tmpl = (fs::temp_directory_path() / "ncvm-setup-XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) throw std::runtime_error("cannot make a temporary folder");
    dir = tmpl;
    file = dir / "setup.toml";
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out.flush()) throw std::runtime_error("cannot write a temporary setup file");
  }
  ~TempSetupFile() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); !from.empty() && at != std::string::npos;
       at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace

std::optional<std::string> addSetupLayers(const nlohmann::json& in, const ServerConfig& cf,
                                          nlohmann::json& job) {
  auto it = in.find("setups");
  if (it == in.end()) return std::nullopt;
  if (!it->is_array() || it->size() > 16) return "\"setups\" must be a list of at most 16 layers";
  nlohmann::json layers = nlohmann::json::array();
  bool tab = false;
  auto addTab = [&] {
    tab = true;
    if (job.contains("setup"))
      layers.push_back({{"text", job["setup"]}, {"name", job.value("setup_name", "setup.toml")}});
  };
  for (const auto& layer : *it) {
    if (!layer.is_object()) return "a setup layer must be an object";
    if (layer.value("tab", false)) {
      if (!tab) addTab();
      continue;
    }
    const std::string root = layer.value("root", ""), path = layer.value("path", "");
    auto folder = layerRoot(root, cf);
    std::optional<fs::path> file;
    if (folder && isPlainRelative(path) && fs::path(path).extension() == ".toml")
      file = resolveInside(*folder, path);
    std::optional<std::string> text;
    if (file) text = readSmallFile(*file, cf.maxBodyBytes);
    if (!text) return "no such setup file in the server's folders: " + root + "/" + path;
    layers.push_back({{"text", *text}, {"name", root + "/" + path}});
  }
  if (!tab) addTab();
  job.erase("setup");
  job.erase("setup_name");
  job["setup_layers"] = std::move(layers);
  return std::nullopt;
}

nlohmann::json setupFiles(const ServerConfig& cf) {
  nlohmann::json out = {{"presets", nlohmann::json::array()}, {"roots", nlohmann::json::array()}};
  if (!cf.presetsDir.empty()) out["presets"] = tomlFiles(cf.presetsDir);
  for (const auto& r : cf.catalog.roots())
    out["roots"].push_back({{"name", r.name}, {"files", tomlFiles(r.path)}});
  return out;
}

Setup layeredSetup(const nlohmann::json& layers) {
  Setup s = defaultSetup();
  for (const auto& layer : layers) {
    const std::string name = layer.value("name", "setup.toml");
    TempSetupFile tmp(layer.value("text", ""));
    const std::string tmpPath = tmp.file.string();
    try {
      loadSetupInto(s, tmpPath);
    } catch (SetupError& e) {
      SetupError named(replaceAll(e.what(), tmpPath, name), e.key, e.line);
      named.col = e.col;
      named.file = name;
      throw named;
    }
    // loadSetupInto places relative file names beside the setup file, here the temporary
    // folder: they go back to relative (also those of earlier layers, placed again).
    const std::string prefix = tmp.dir.string() + "/";
    for (std::string* f : {&s.target.polyline, &s.target.heightMap})
      if (f->rfind(prefix, 0) == 0) *f = f->substr(prefix.size());
  }
  return s;
}

}  // namespace ncvm::server
