#pragma once
// One run for the web viewer, as JSON in and JSON out: the program text and its setup go
// through a fresh Session; the answer holds the trace, the per-event steps, the final state
// and the check report. It runs inside a worker process (worker.hpp), so a request never
// shares a control, variables or memory with another.
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace ncvm::server {

// The server's caps. A setup may ask for less, never for more.
struct RunCaps {
  uint64_t maxProgramBytes = 512ull << 20;  // as the command line (limits.max_file_bytes)
  uint64_t maxBlocks = 2'000'000;
  double maxSimSeconds = 360'000.0;  // simulated machine time
  uint64_t maxTraceBytes = 64u << 20;
};

// The request (built by the server, never taken from a client as is):
//   {"program": TEXT, "name": FILE NAME, "setup": TOML TEXT or null, "setup_name": NAME,
//    "libs": [FOLDER...], "roots": [{"name", "path"}] (the roots the libs lie in),
//    "setup_dir": FOLDER (the server's own --setup), "caps":
//    {"max_program_bytes", "max_blocks", "max_sim_seconds", "max_trace_bytes"}}
// Files named by the setup are read only inside "setup_dir", when given, else the "libs"
// folders (relative to them). The programs of a lib folder (M98/G65 calls) are loaded only
// when they lie, every symlink followed, inside its root (the folder itself without
// "roots"), as /api/file reads them; the answer names them ROOT/PATH and the bundled macros
// macros/NAME, never by a path of the server's machine.
// The answer: {"ok": true, "state", "trace" (JSON Lines text), "steps", "check", "printed",
// "machine": {"kind", "axes"}, "stock" (with a [stock] in the setup: the final stock,
// docs/web-viewer.md)} or {"ok": false, "error": MESSAGE} for a setup or load error.
// Instead of "program", a request may name "program_path": a file the server resolved inside
// its folders, read by the worker (a large program never passes through JSON).
nlohmann::json runJob(const nlohmann::json& request);

// The same run as the binary stream of viewer_stream.hpp, each frame to `out` as it is made;
// a failure is an end frame {"ok": false, "error"}.
void runViewerJob(const nlohmann::json& request, const std::function<void(std::string_view)>& out);

// "program too large: N bytes (M MB), the server accepts L bytes (... --max-program-mb ...)".
std::string tooLarge(uint64_t bytes, uint64_t limit);

nlohmann::json capsJson(const RunCaps& caps);

}  // namespace ncvm::server
