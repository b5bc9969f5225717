#pragma once
// The options of `ncvm serve`, parsed by ncvm (for its help and checks) and again by
// ncvm-serve, which ncvm starts with the same arguments.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace ncvm {

inline constexpr const char* kServeDescription =
    "serve the web viewer (editor, 3D toolpath, timeline) on this machine";

struct ServeOptions {
  int port = 8765;
  std::string bind = "127.0.0.1";
  std::string setupPath;
  std::vector<std::string> roots;
  std::string program;
  double timeoutSeconds = 10;
  uint64_t maxBlocks = 2'000'000;
  int threads = 8;
};

inline void addServeOptions(CLI::App* serve, ServeOptions& o) {
  serve->add_option("PROGRAM", o.program, "program to open in the page");
  serve->add_option("--port", o.port, "TCP port (0: any free port)")->capture_default_str();
  serve->add_option("--bind", o.bind, "address to listen on (another than 127.0.0.1 only when you mean it)")
      ->capture_default_str();
  serve->add_option("--setup", o.setupPath, "default setup for programs that have none (TOML)");
  serve->add_option("--root", o.roots, "folder of programs the page may open (repeatable)");
  serve->add_option("--timeout", o.timeoutSeconds, "wall-clock limit of one run, seconds")->capture_default_str();
  serve->add_option("--max-blocks", o.maxBlocks, "most blocks one run may execute")->capture_default_str();
  serve->add_option("--threads", o.threads, "runs at once (connections are served beside them)")->capture_default_str();
}

}  // namespace ncvm
