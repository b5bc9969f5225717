// libFuzzer target: the lexer and parser (program text -> compiled IR, one file).
// The first byte picks the parse options; the rest is the program text. Every compiled
// program must satisfy the IR invariants (ir_invariants.hpp).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "ir_invariants.hpp"
#include "lang/parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  ncvm::ParseOptions options;
  options.eightDigitO = data[0] & 1;
  // A short line limit exercises the PS9004 path; otherwise the default setup's 4096.
  options.maxLineLength = (data[0] & 2) ? 64 : 4096;
  std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  ncvm::ParsedFile parsed = ncvm::parseProgramText(text, 0, "fuzz", options);
  for (const ncvm::Program& p : parsed.programs) ncvm::fuzz::checkProgram(p);
  return 0;
}
