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
  uint64_t maxUploadMb = 64;    // a pasted or dropped program
  uint64_t maxProgramMb = 512;  // a program run by its path (the command line's own limit)
  uint64_t maxAnswerMb = 2048;  // the binary answer of one run
  uint64_t maxMemoryMb = 4096;  // the address space of one run's worker
};

inline void addServeOptions(CLI::App* serve, ServeOptions& o) {
  serve->add_option("PROGRAM", o.program, "program to open in the page");
  serve->add_option("--port", o.port, "TCP port (0: any free port)")->capture_default_str();
  serve
      ->add_option("--bind", o.bind,
                   "address to listen on (another than 127.0.0.1 only when you mean it)")
      ->capture_default_str();
  serve->add_option("--setup", o.setupPath, "default setup for programs that have none (TOML)");
  serve->add_option("--root", o.roots, "folder of programs the page may open (repeatable)");
  serve->add_option("--timeout", o.timeoutSeconds, "wall-clock limit of one run, seconds")
      ->capture_default_str();
  serve->add_option("--max-blocks", o.maxBlocks, "most blocks one run may execute")
      ->capture_default_str();
  serve->add_option("--threads", o.threads, "runs at once (connections are served beside them)")
      ->capture_default_str();
  serve
      ->add_option("--max-upload-mb", o.maxUploadMb,
                   "largest program text a page may send (pasted, dropped), MB")
      ->capture_default_str();
  serve->add_option("--max-program-mb", o.maxProgramMb, "largest program one run may read, MB")
      ->capture_default_str();
  serve->add_option("--max-answer-mb", o.maxAnswerMb, "largest answer of one run, MB")
      ->capture_default_str();
  serve
      ->add_option("--max-memory-mb", o.maxMemoryMb,
                   "address space of one run's worker process, MB")
      ->capture_default_str();
}

}  // namespace ncvm
