// libFuzzer target, differential: a program run whole and streamed (lang/program_stream.hpp,
// compiled in pieces while it runs) must give the same trace, state and printed output. The
// first two bytes choose the setup as in fuzz_run (mill or lathe, inch, block skip, linear
// rapids) and the piece size (1 to 64 bytes, so pieces cut every kind of line); the rest is
// the program, written to a file (streaming reads files, not text in memory). A program the
// stream scan refuses is compiled whole both times, which must agree too.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>

#include "app/session.hpp"
#include "machine/setup.hpp"
#include "report/trace_writer.hpp"

namespace {

std::string runOnce(const std::string& path, const ncvm::Setup& setup, size_t piece, bool stream,
                    bool& streamed) {
  ncvm::Session session(setup);
  if (stream) session.streamMainProgram({0, piece});
  session.addProgramFile(path);
  streamed = session.main() && session.main()->stream;
  if (!session.main()) return "no program";
  ncvm::TraceWriter trace(session.files(), nullptr, setup.limits.maxTraceBytes,
                          setup.reportedAxes());
  ncvm::Session::Result r = session.run(&trace);
  const auto replace = nlohmann::json::error_handler_t::replace;
  return trace.buffer() + "\n" + r.state.dump(-1, ' ', false, replace) + "\n" + r.printed;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const uint8_t a = data[0], b = data[1];
  ncvm::Setup setup =
      ncvm::defaultSetup(a & 1 ? ncvm::MachineKind::Lathe : ncvm::MachineKind::Mill);
  if (a & 4) setup.initialUnit = ncvm::InputUnit::Inch;
  if (a & 8) setup.blockSkip[1] = true;
  if (a & 16) setup.parameters["1401#1"] = 1;  // linear rapids
  setup.limits.maxBlocks = 2000;
  setup.limits.maxTimeSeconds = 3600;
  setup.limits.maxTraceBytes = 1 << 20;
  setup.limits.maxLineLength = 1024;
  const size_t piece = 1 + (b & 63);

  static const std::string path = [] {
    std::atexit([] {
      std::remove(("/tmp/ncvm_fuzz_stream_" + std::to_string(::getpid()) + ".nc").c_str());
    });
    return "/tmp/ncvm_fuzz_stream_" + std::to_string(::getpid()) + ".nc";
  }();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 2), static_cast<std::streamsize>(size - 2));
  }
  bool unused = false, streamed = false;
  const std::string whole = runOnce(path, setup, piece, false, unused);
  const std::string pieces = runOnce(path, setup, piece, true, streamed);
  if (whole != pieces) {
    std::fprintf(
        stderr,
        "streamed (%s, pieces of %zu) differs from whole:\n--- whole\n%s\n--- streamed\n%s\n",
        streamed ? "streamed" : "not streamed", piece, whole.c_str(), pieces.c_str());
    std::abort();
  }
  return 0;
}
