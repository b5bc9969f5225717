// libFuzzer target: a bounded run of the executor. The first two bytes choose the setup
// (mill or lathe, decimal input, G-code system, inch, block skip, 8-digit O numbers); the
// rest is split at NUL bytes into a main file and up to two files of called programs.
// Small block, time and trace limits keep every run short; the trace is formatted in
// memory, and the state report is built, as `ncvm run --trace --state` would.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "app/session.hpp"
#include "machine/setup.hpp"
#include "report/trace_writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const uint8_t a = data[0], b = data[1];
  ncvm::Setup setup =
      ncvm::defaultSetup(a & 1 ? ncvm::MachineKind::Lathe : ncvm::MachineKind::Mill);
  if (a & 2) setup.parameters["3401#0"] = 1;  // calculator-type decimal input
  if (a & 4) setup.initialUnit = ncvm::InputUnit::Inch;
  if (a & 8) setup.blockSkip[1] = true;
  if (a & 16) setup.programNumberDigits = 8;
  if (a & 1) setup.gcodeSystem = "ABC"[(a >> 5) % 3];
  if (b & 1) setup.parameters["6004#0"] = 1;  // NAT
  if (b & 2) setup.parameters["1401#1"] = 1;  // linear rapids
  if (b & 4) setup.parameters["6001#1"] = 1;  // PRT
  if (b & 8) setup.probe.missAlarm = true;
  setup.limits.maxBlocks = 2000;
  setup.limits.maxTimeSeconds = 3600;
  setup.limits.maxTraceBytes = 1 << 20;
  setup.limits.maxLineLength = 1024;

  ncvm::Session session(setup);
  std::string_view rest(reinterpret_cast<const char*>(data + 2), size - 2);
  for (int file = 0; file < 3 && (file == 0 || !rest.empty()); ++file) {
    size_t cut = file == 2 ? std::string_view::npos : rest.find('\0');
    std::string_view text = rest.substr(0, cut);
    rest = cut == std::string_view::npos ? std::string_view{} : rest.substr(cut + 1);
    session.addProgramText(text, "fuzz" + std::to_string(file) + ".nc");
  }
  if (!session.main()) return 0;
  ncvm::TraceWriter trace(session.files(), nullptr, setup.limits.maxTraceBytes,
                          setup.reportedAxes());
  ncvm::Session::Result r = session.run(&trace);
  // The reports as the command line writes them (invalid UTF-8 replaced), and every trace
  // line must be one valid JSON object.
  const auto replace = nlohmann::json::error_handler_t::replace;
  (void)r.state.dump(-1, ' ', false, replace);
  (void)r.machineState.dump(-1, ' ', false, replace);
  const std::string& t = trace.buffer();
  for (size_t pos = 0; pos < t.size();) {
    size_t nl = t.find('\n', pos);
    if (nl == std::string::npos) nl = t.size();
    if (!nlohmann::json::accept(std::string_view(t).substr(pos, nl - pos))) {
      std::fprintf(stderr, "invalid trace line: %s\n", t.substr(pos, nl - pos).c_str());
      std::abort();
    }
    pos = nl + 1;
  }
  return 0;
}
