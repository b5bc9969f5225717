#include "server/request_checks.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>

#include "server/safe_path.hpp"
#include "server/setup_layers.hpp"

namespace ncvm::server {

namespace {

// "127.0.0.1": four decimal numbers 0-255, the first 127.
bool isLoopbackIpv4(const std::string& h) {
  int parts = 0;
  size_t i = 0;
  int first = -1;
  while (i <= h.size()) {
    size_t start = i;
    int value = 0;
    while (i < h.size() && std::isdigit(static_cast<unsigned char>(h[i])) && i - start < 3)
      value = value * 10 + (h[i++] - '0');
    if (i == start || value > 255) return false;
    if (first < 0) first = value;
    ++parts;
    if (i == h.size()) break;
    if (h[i] != '.' || parts == 4) return false;
    ++i;
  }
  return parts == 4 && first == 127;
}

// A string field of a request, or `fallback` when it is missing or not a string.
std::string field(const nlohmann::json& j, const char* key, const std::string& fallback) {
  auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : fallback;
}

RunRequest refuse(int status, std::string message) {
  return {status, std::move(message), {}};
}

}  // namespace

bool isLoopback(const std::string& host) {
  return host == "localhost" || host == "::1" || isLoopbackIpv4(host);
}

std::string hostPart(const std::string& h) {
  if (!h.empty() && h.front() == '[') {
    auto close = h.find(']');
    return close == std::string::npos ? h : h.substr(1, close - 1);
  }
  auto colon = h.rfind(':');
  return colon == std::string::npos ? h : h.substr(0, colon);
}

std::optional<std::string> foreignHostOrOrigin(const std::string& host, const std::string& origin,
                                               int ownPort) {
  if (!host.empty() && !isLoopback(hostPart(host)))
    return "this server answers only to loopback host names";
  if (origin.empty()) return std::nullopt;
  constexpr std::string_view kScheme = "http://";
  if (origin.rfind(kScheme, 0) != 0) return "cross-origin requests are refused";
  const std::string hostPort = origin.substr(kScheme.size());
  if (!isLoopback(hostPart(hostPort)) || portPart(hostPort) != ownPort)
    return "cross-origin requests are refused (only this server's own pages may call it)";
  return std::nullopt;
}

int portPart(const std::string& h) {
  const size_t close = !h.empty() && h.front() == '[' ? h.find(']') : 0;
  if (close == std::string::npos) return -1;
  const size_t colon = h.find(':', close);
  if (colon == std::string::npos) return 80;  // the default port of http://
  int port = 0;
  const char* first = h.data() + colon + 1;
  auto [end, ec] = std::from_chars(first, h.data() + h.size(), port);
  if (ec != std::errc() || end != h.data() + h.size() || first == end || port <= 0 || port > 65535)
    return -1;
  return port;
}

std::string baseName(const std::string& s) {
  size_t slash = s.find_last_of("/\\");
  std::string b = s.substr(slash == std::string::npos ? 0 : slash + 1);
  if (b.empty() || b == "." || b == ".." || b.size() > 128) return "program.nc";
  return b;
}

std::string tooLargeBody(uint64_t bytes, const ServerConfig& cf) {
  auto mb = [](uint64_t b) { return std::to_string((b + (1u << 20) - 1) >> 20); };
  return "request too large: " + std::to_string(bytes) + " bytes (" + mb(bytes) +
         " MB), the server accepts requests of " + std::to_string(cf.maxBodyBytes) +
         " bytes and a pasted or dropped program of " + mb(cf.maxUploadBytes) +
         " MB at most (ncvm serve --max-upload-mb raises it; a program of the server's folders "
         "runs by its path, up to --max-program-mb)";
}

RunRequest runRequestFromBody(const std::string& body, const ServerConfig& cf) {
  if (body.size() > cf.maxBodyBytes) return refuse(413, tooLargeBody(body.size(), cf));
  nlohmann::json in = nlohmann::json::parse(body, nullptr, false);
  if (in.is_discarded() || !in.is_object()) return refuse(400, "the body must be a JSON object");
  const bool byPath = !in.contains("program") && in.contains("root") && in["root"].is_string() &&
                      in.contains("path") && in["path"].is_string();
  if (!byPath && (!in.contains("program") || !in["program"].is_string()))
    return refuse(400, "\"program\" (the program text) is missing");
  if (!byPath) {
    const size_t size = in["program"].get_ref<const std::string&>().size();
    if (size > cf.caps.maxProgramBytes) return refuse(413, tooLarge(size, cf.caps.maxProgramBytes));
    if (size > cf.maxUploadBytes) return refuse(413, tooLargeBody(size, cf));
  }
  // The worker gets only what the server vouches for: the text (or a file inside the
  // roots), a plain name, a setup text and library folders resolved inside the roots.
  RunRequest r;
  nlohmann::json& job = r.job;
  job = {{"name", baseName(field(in, "name", "program.nc"))},
         {"caps", capsJson(cf.caps)},
         {"libs", nlohmann::json::array()}};
  std::string dir = field(in, "dir", "");
  if (byPath) {
    const std::string path = in["path"].get<std::string>();
    const Root* root = cf.catalog.find(in["root"].get<std::string>());
    std::optional<std::filesystem::path> file;
    std::error_code ec;
    if (root && isPlainRelative(path)) file = resolveInside(root->path, path);
    if (!file || !std::filesystem::is_regular_file(*file, ec))
      return refuse(404, "no such program in the server's folders");
    uint64_t size = std::filesystem::file_size(*file, ec);
    if (ec) return refuse(404, "no such program in the server's folders");
    if (size > cf.caps.maxProgramBytes) return refuse(413, tooLarge(size, cf.caps.maxProgramBytes));
    job["program_path"] = file->string();
    job["name"] = baseName(path);
    dir = std::filesystem::path(path).parent_path().generic_string();
  } else {
    job["program"] = in["program"];
  }
  // A program of the server's folders sent without a setup runs with its own, by the rule of
  // `ncvm list` and `make demo` (core/program_files.hpp); the --setup file is for programs
  // that have none.
  std::optional<std::pair<std::string, std::string>> own;
  if (!(in.contains("setup") && in["setup"].is_string()) && in.contains("root") &&
      in["root"].is_string()) {
    const std::string program =
        byPath ? in["path"].get<std::string>()
               : (std::filesystem::path(dir) / job["name"].get<std::string>()).generic_string();
    own = cf.catalog.setupOf(in["root"].get<std::string>(), program, cf.maxBodyBytes);
  }
  if (in.contains("setup") && in["setup"].is_string()) {
    job["setup"] = in["setup"];
    job["setup_name"] = baseName(field(in, "setup_name", "setup.toml"));
  } else if (own) {
    job["setup"] = own->second;
    job["setup_name"] = baseName(own->first);
  } else if (!cf.setupText.empty()) {
    job["setup"] = cf.setupText;
    job["setup_name"] = cf.setupName;
    if (!cf.setupDir.empty()) job["setup_dir"] = cf.setupDir;
  }
  // Layers (setup_layers.hpp): presets and setup files, in order around the setup above.
  if (auto bad = addSetupLayers(in, cf, job)) return refuse(400, *bad);
  // The stock along the timeline (stock_snapshots.hpp): the first interval, in moves.
  if (auto every = in.find("stock_every"); every != in.end() && every->is_number_integer())
    job["stock_every"] = std::clamp<int64_t>(every->get<int64_t>(), 1, int64_t{1} << 30);
  if (in.contains("root") && in["root"].is_string()) {
    auto folder = cf.catalog.folder(in["root"].get<std::string>(), dir);
    if (!folder) return refuse(400, "bad folder: not inside the server's folders");
    job["libs"].push_back(folder->string());
    // The worker confines the folder's programs to their root and names them by it.
    const Root* root = cf.catalog.find(in["root"].get<std::string>());
    std::error_code ec;
    job["roots"] = nlohmann::json::array(
        {{{"name", root->name}, {"path", std::filesystem::canonical(root->path, ec).string()}}});
  }
  return r;
}

}  // namespace ncvm::server
