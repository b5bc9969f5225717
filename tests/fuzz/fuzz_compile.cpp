// libFuzzer target: the compiler as a session sees it. The input is split at NUL bytes
// into up to three files that go through the program store (program numbers, names and
// duplicates across files), WHILE/DO/END and GOTO resolution, label search, and
// `ncvm check` (loop and label errors, decimal-point and duplicate-word warnings).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "app/session.hpp"
#include "ir_invariants.hpp"
#include "machine/setup.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  uint8_t mode = data[0];
  ncvm::Setup setup =
      ncvm::defaultSetup(mode & 1 ? ncvm::MachineKind::Lathe : ncvm::MachineKind::Mill);
  if (mode & 2) setup.parameters["3401#0"] = 1;  // calculator-type decimal input
  if (mode & 4) setup.programNumberDigits = 8;
  ncvm::Session session(setup);
  std::string_view rest(reinterpret_cast<const char*>(data + 1), size - 1);
  for (int file = 0; file < 3 && (file == 0 || !rest.empty()); ++file) {
    size_t cut = file == 2 ? std::string_view::npos : rest.find('\0');
    std::string_view text = rest.substr(0, cut);
    rest = cut == std::string_view::npos ? std::string_view{} : rest.substr(cut + 1);
    session.addProgramText(text, "fuzz" + std::to_string(file) + ".nc");
  }
  for (const ncvm::Program& p : session.store().programs()) {
    ncvm::fuzz::checkProgram(p);
    // Every label is found from every block, and the search lands on that label.
    for (const auto& [n, index] : p.labels) {
      int32_t t = p.findLabel(n, index);
      if (t < 0 || p.blocks[static_cast<size_t>(t)].n != n)
        ncvm::fuzz::violated("findLabel", index);
    }
    if (p.number >= 0 && !session.store().byNumber(p.number)) ncvm::fuzz::violated("byNumber", 0);
  }
  (void)session.check().dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return 0;
}
