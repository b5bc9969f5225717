#pragma once
// `ncvm serve`: the web viewer's HTTP server (cpp-httplib). It serves the built front end
// (web/), lists and reads programs of its roots, and runs programs, each run in its own
// worker process with the caps of RunCaps and WorkerLimits. Bound to 127.0.0.1 unless told
// otherwise; on a loopback address it also refuses requests whose Host or Origin is not a
// loopback name, so that a web page elsewhere cannot drive it through DNS rebinding.
#include <cstdint>
#include <memory>
#include <string>

#include "server/connection_limits.hpp"
#include "server/file_catalog.hpp"
#include "server/run_job.hpp"
#include "server/worker.hpp"

namespace ncvm::server {

struct ServerConfig {
  std::string bind = "127.0.0.1";
  int port = 8765;        // 0: any free port (see WebServer::bind)
  std::string webDir;     // the built front end: index.html, assets/
  FileCatalog catalog;    // the folders programs are read from
  std::string setupText;  // the default setup (--setup), empty for ncvm's default
  std::string setupName;
  std::string setupDir;              // its folder: the files it names are read there (run_job.hpp)
  std::string presetsDir;            // presets/: setups a run may layer (setup_layers.hpp)
  std::string startRoot, startPath;  // the program the page opens with (PROGRAM)
  std::string workerExe;             // the ncvm binary (for `ncvm serve-worker`)
  RunCaps caps;
  WorkerLimits worker;
  uint64_t maxUploadBytes = 64u << 20;   // a program's text in a request (pasted, dropped)
  uint64_t maxBodyBytes = 129u << 20;    // a request: the text JSON-escaped, and its setup
  uint64_t maxAnswerBytes = 2ull << 30;  // the binary run answer (/api/run.bin)
  int threads = 8;                       // concurrent runs (worker processes)
  // Connections served at once. Far more than the runs: an idle or slow connection holds a
  // connection thread, never a run, so 50 idle and 8 slow ones leave room for the page.
  int connections = 128;
  ConnectionLimits connection;  // timeouts and bounds per connection and per client
};

class WebServer {
 public:
  explicit WebServer(ServerConfig config);
  ~WebServer();
  // Binds the socket; returns the port (the chosen one for port 0). Throws on failure.
  int bind();
  // Serves until stop(); call after bind().
  void listen();
  void stop();
  const ServerConfig& config() const { return config_; }

 private:
  struct Impl;
  ServerConfig config_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ncvm::server
