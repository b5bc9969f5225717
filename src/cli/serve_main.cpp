// ncvm-serve: the web viewer's server, started by `ncvm serve` with the same arguments. It is
// a binary of its own so that the HTTP library and what it loads (OpenSSL, brotli) stay out of
// every other ncvm command's start-up. Exit status: 0 normal end, 2 usage or setup error.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/session.hpp"
#include "cli/command_line.hpp"
#include "cli/serve_options.hpp"
#include "server/safe_path.hpp"
#include "server/web_server.hpp"

namespace {

using namespace ncvm;

constexpr int kExitOk = 0;

// A folder beside the executable (../share/ncvm/NAME when installed, ../NAME in a build
// folder), else `fallback` (the source tree), else nothing; $ENV overrides.
std::string folderBesideBinary(const char* env, const std::string& installed,
                               const std::string& build, const std::string& fallback) {
  namespace fs = std::filesystem;
  if (const char* e = std::getenv(env); e && *e) return e;
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec)
    for (const auto& rel : {installed, build}) {
      if (rel.empty()) continue;
      fs::path p = exe.parent_path() / rel;
      if (fs::is_directory(p, ec)) return fs::canonical(p, ec).string();
    }
  if (!fallback.empty() && fs::is_directory(fallback, ec)) return fallback;
  return {};
}

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int serveCommand(const ServeOptions& o) {
  namespace fs = std::filesystem;
  server::ServerConfig c;
  c.bind = o.bind;
  c.port = o.port;
  c.threads = o.threads;
  c.caps.maxBlocks = o.maxBlocks;
  c.caps.maxProgramBytes = o.maxProgramMb << 20;
  c.maxUploadBytes = o.maxUploadMb << 20;
  c.maxBodyBytes = 2 * c.maxUploadBytes + (1u << 20);  // JSON-escaped text and its setup
  c.maxAnswerBytes = o.maxAnswerMb << 20;
  c.worker.memoryBytes = o.maxMemoryMb << 20;
  c.worker.timeout = std::chrono::milliseconds(static_cast<int64_t>(o.timeoutSeconds * 1000));
  c.webDir = folderBesideBinary("NCVM_WEB", "../share/ncvm/web", "../web", "");
  std::string examples =
      folderBesideBinary("NCVM_EXAMPLES", "../share/ncvm/examples", "", NCVM_SOURCE_EXAMPLES);
  if (!examples.empty()) c.catalog.add("examples", examples);
  c.presetsDir =
      folderBesideBinary("NCVM_PRESETS", "../share/ncvm/presets", "", NCVM_SOURCE_PRESETS);
  for (const auto& r : o.roots) {
    std::error_code ec;
    if (!fs::is_directory(r, ec)) throw std::runtime_error("--root " + r + ": not a folder");
    fs::path p = fs::canonical(r);
    c.catalog.add(p.filename().string(), p);
  }
  if (!o.program.empty()) {
    fs::path p = fs::canonical(o.program);
    const server::Root* root = nullptr;
    for (const auto& r : c.catalog.roots())
      if (server::resolveInside(r.path, fs::relative(p, fs::canonical(r.path)).generic_string()) ==
          p)
        root = &r;
    if (!root) {
      c.catalog.add(p.parent_path().filename().string(), p.parent_path());
      root = &c.catalog.roots().back();
    }
    c.startRoot = root->name;
    c.startPath = fs::relative(p, fs::canonical(root->path)).generic_string();
  }
  if (!o.setupPath.empty()) {
    (void)loadSetup(o.setupPath);  // a bad setup stops here, not at the first run
    c.setupText = readText(o.setupPath);
    c.setupName = fs::path(o.setupPath).filename().string();
    c.setupDir = fs::canonical(o.setupPath).parent_path().string();
  }
  // The workers run `ncvm serve-worker`: the ncvm binary beside this one.
  std::error_code ec;
  c.workerExe = (fs::read_symlink("/proc/self/exe", ec).parent_path() / "ncvm").string();
  if (ec) throw std::runtime_error("cannot find the ncvm binary for the workers");
  std::signal(SIGPIPE, SIG_IGN);  // a worker that dies must not take the server with it

  server::WebServer web(std::move(c));
  int port = web.bind();
  std::string host = o.bind.find(':') != std::string::npos ? "[" + o.bind + "]" : o.bind;
  fmt::print("ncvm serve: http://{}:{}/\n", host, port);
  if (web.config().webDir.empty())
    fmt::print(
        stderr,
        "ncvm: warning: the front end was not built (web/README.md): only the API is served\n");
  std::fflush(stdout);
  web.listen();
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{std::string("ncvm serve: ") + kServeDescription};
  app.name("ncvm serve");
  ServeOptions opts;
  addServeOptions(&app, opts);
  if (const auto status = parseCommandLine(app, argc, argv)) return *status;
  try {
    return serveCommand(opts);
  } catch (const std::exception& e) {
    return commandError(e);
  }
}
