// libFuzzer target: the web server's request handling (src/server) without a socket or a
// worker process. The input is three lines and a body:
//   line 1: the Host header, line 2: the Origin header,
//   line 3: a client path (the `path` of /api/file, a file of the page, a library folder),
//   the rest: a /api/run body (JSON: program, setup TOML, name, root, dir).
// What must hold (abort otherwise):
// - Host/Origin: a request passes only when both name this machine: "localhost", "::1" or
//   an IPv4 literal 127.a.b.c (an oracle written apart from request_checks.cpp).
// - Paths: resolveInside, FileCatalog::read and FileCatalog::folder answer only with files
//   inside the root (a tree built once in a temporary folder, with symlinks to a secret
//   beside it), and never with the secret's text.
// - /api/run: the body is refused with 400/413, or becomes a job whose program is within the
//   cap, whose name is a plain file name and whose library folders are inside the root. The
//   job then crosses the process boundary as the server sends it (JSON text), and the
//   worker's code (workerAnswer: runJob in this process, under small caps) answers with one
//   JSON object holding "ok".
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "server/request_checks.hpp"
#include "server/safe_path.hpp"
#include "server/worker.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

[[noreturn]] void fail(const char* what, std::string_view detail) {
  std::fprintf(stderr, "fuzz_server: %s: %.*s\n", what, static_cast<int>(detail.size()),
               detail.data());
  std::abort();
}

bool isNumber255(std::string_view s) {
  if (s.empty() || s.size() > 3) return false;
  int v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + (c - '0');
  }
  return v <= 255;
}

// The oracle: the host part (without port or brackets) of a name that means this machine.
bool meansThisMachine(std::string_view host) {
  if (host == "localhost" || host == "::1") return true;
  std::string_view parts[4];
  for (int k = 0; k < 4; ++k) {
    size_t dot = k == 3 ? std::string_view::npos : host.find('.');
    if (k < 3 && dot == std::string_view::npos) return false;
    parts[k] = host.substr(0, dot);
    host = dot == std::string_view::npos ? std::string_view{} : host.substr(dot + 1);
  }
  for (auto p : parts)
    if (!isNumber255(p)) return false;
  return parts[0] == "127";
}

struct Fixture {
  fs::path top, root, outside;
  std::string rootText;  // canonical root, as resolveInside answers
  ncvm::server::ServerConfig config;

  Fixture() {
    std::string t = (fs::temp_directory_path() / "ncvm-fuzz-server-XXXXXX").string();
    if (!::mkdtemp(t.data())) fail("mkdtemp", t);
    top = fs::canonical(t);
    root = top / "root";
    outside = top / "root-outside";  // shares the root's name as a prefix
    write(root / "parts" / "p1.nc", "O0001\nG00 X1.\nM98 P2000\nM30\n");
    write(root / "parts" / "p1.toml", "[machine]\nkind = \"mill\"\n");
    write(root / "parts" / "O2000.nc", "O2000\nG00 Y2.\nM99\n");
    write(root / "index.html", "<title>ncvm</title>");
    write(outside / "secret.nc", "O9999 (SECRET)\n");
    write(outside / "setup.toml", "# SECRET\n");
    fs::create_symlink(outside / "secret.nc", root / "parts" / "link.nc");
    fs::create_symlink(outside, root / "dirlink");
    fs::create_symlink(top, root / "up");
    rootText = root.string();
    config.catalog.add("root", root);
    config.maxBodyBytes = 256 * 1024;
    config.caps.maxProgramBytes = 64 * 1024;
    config.caps.maxBlocks = 2000;
    config.caps.maxSimSeconds = 3600;
    config.caps.maxTraceBytes = 1 << 20;
  }
  ~Fixture() {
    std::error_code ec;
    fs::remove_all(top, ec);
  }
  static void write(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
  }
  bool inside(const fs::path& p) const {
    const std::string& s = p.native();
    return s == rootText ||
           (s.size() > rootText.size() && s.compare(0, rootText.size(), rootText) == 0 &&
            s[rootText.size()] == '/');
  }
};

const Fixture& fixture() {
  static Fixture f;
  return f;
}

std::string_view line(std::string_view& rest) {
  size_t nl = rest.find('\n');
  std::string_view l = rest.substr(0, nl);
  rest = nl == std::string_view::npos ? std::string_view{} : rest.substr(nl + 1);
  return l;
}

void checkHeaders(std::string_view host, std::string_view origin) {
  using namespace ncvm::server;
  constexpr int kPort = 8765;
  auto refusal = foreignHostOrOrigin(std::string(host), std::string(origin), kPort);
  if (refusal) return;
  if (!host.empty() && !meansThisMachine(hostPart(std::string(host))))
    fail("a foreign Host passed", host);
  std::string o(origin);
  if (!o.empty() && o.rfind("http://", 0) != 0) fail("an Origin of another scheme passed", origin);
  if (!o.empty()) o = o.substr(7);
  if (!o.empty() && !meansThisMachine(hostPart(o))) fail("a foreign Origin passed", origin);
  if (!o.empty() && portPart(o) != kPort) fail("an Origin of another port passed", origin);
}

void checkPath(const Fixture& fx, std::string_view path) {
  using namespace ncvm::server;
  auto full = resolveInside(fx.root, path);
  if (full && (!isPlainRelative(path) || !fx.inside(*full)))
    fail("resolveInside left the root", full->native());
  if (auto f = fx.config.catalog.read("root", std::string(path), 1 << 16)) {
    std::string text = f->dump(-1, ' ', false, json::error_handler_t::replace);
    if (text.find("SECRET") != std::string::npos) fail("read a file outside the root", path);
  }
  if (auto dir = fx.config.catalog.folder("root", std::string(path)); dir && !fx.inside(*dir))
    fail("a library folder outside the root", dir->native());
}

void checkRun(const Fixture& fx, std::string_view body) {
  using namespace ncvm::server;
  RunRequest r = runRequestFromBody(std::string(body), fx.config);
  if (r.status != 200) {
    if ((r.status != 400 && r.status != 413) || r.error.empty()) fail("odd refusal", r.error);
    return;
  }
  const json& job = r.job;
  if (!job["program"].is_string() ||
      job["program"].get_ref<const std::string&>().size() > fx.config.caps.maxProgramBytes)
    fail("a program over the cap", job.dump(-1, ' ', false, json::error_handler_t::replace));
  for (const char* key : {"name", "setup_name"}) {
    if (!job.contains(key)) continue;
    const std::string& n = job[key].get_ref<const std::string&>();
    if (n.empty() || n.size() > 128 || n == "." || n == ".." ||
        n.find_first_of("/\\") != std::string::npos)
      fail("not a plain file name", n);
  }
  for (const auto& lib : job["libs"])
    if (!fx.inside(lib.get<std::string>())) fail("a library outside the root", lib.dump());
  // As runWorker sends it, and as the worker answers it.
  std::string answer = workerAnswer(job.dump(-1, ' ', false, json::error_handler_t::replace));
  json a = json::parse(answer, nullptr, false);
  if (a.is_discarded() || !a.is_object() || !a.contains("ok") || !a["ok"].is_boolean())
    fail("the worker's answer is not {\"ok\": ...}", answer.substr(0, 200));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const Fixture& fx = fixture();
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  std::string_view host = line(rest), origin = line(rest), path = line(rest);
  checkHeaders(host, origin);
  checkPath(fx, path);
  checkRun(fx, rest);
  return 0;
}
