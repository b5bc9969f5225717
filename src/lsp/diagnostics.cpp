#include "lsp/diagnostics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <tuple>

#include "lsp/positions.hpp"

namespace ncvm::lsp {

namespace {
constexpr int kError = 1, kWarning = 2;

struct Finder {
  explicit Finder(const Document& d) : doc(d), lines(d.lines()), name(documentName(d)) {}
  const Document& doc;
  std::vector<std::string_view> lines;
  std::string name;
  std::set<std::tuple<std::string, uint32_t, uint32_t>> seen;  // code, line, col
  nlohmann::json out = nlohmann::json::array();

  // A finding in another file (a called subprogram's alarm) is shown on the first line,
  // naming where it is.
  void add(int severity, const std::string& code, const std::string& text, const std::string& file,
           uint32_t line, uint32_t col, const char* source) {
    if (!seen.emplace(code, file == name ? line : 0, file == name ? col : 0).second) return;
    nlohmann::json d;
    std::string message = text;
    if (file == name && line >= 1 && line <= lines.size()) {
      d["range"] = wordRange(static_cast<int>(line - 1), lines[line - 1], col);
    } else {
      d["range"] = wordRange(0, lines.empty() ? std::string_view{} : lines[0], 0);
      if (!file.empty()) message = fmt::format("{}:{}:{}: {}", file, line, col, text);
    }
    d["severity"] = severity;
    d["code"] = code;
    d["source"] = source;
    d["message"] = message;
    out.push_back(std::move(d));
  }
};

// Stops of the dry run's own limits say so: they are no fault of the program.
std::string limitText(const Alarm& a, const Setup& setup) {
  if (a.code == alarmCode(AlarmId::BlockLimit))
    return fmt::format(
        "{}: the editor's dry run stops after {} blocks (ncvm lsp --max-blocks); "
        "the program may only be long, or loop for ever",
        a.text, setup.limits.maxBlocks);
  return a.text;
}
// A program that returns with M99 and never ends with M02/M30 is a subprogram or macro:
// run on its own it would restart at M99 for ever (a level-0 M99 rewinds) with vacant
// arguments, so the dry run is left to the programs that call it.
bool isCalledProgram(const Program& p) {
  bool m99 = false, end = false;
  for (const Block& b : p.blocks) {
    if (b.kind != BlockKind::Nc) continue;
    const Word* w = p.words.data() + b.firstWord;
    for (uint32_t k = 0; k < b.nWords; ++k) {
      if (w[k].letter != 'M' || w[k].kind != WordKind::Literal) continue;
      m99 |= w[k].value == 99;
      end |= w[k].value == 30 || w[k].value == 2;
    }
  }
  return m99 && !end;
}
}  // namespace

nlohmann::json diagnose(const Setup& setup, const ServerOptions& options, const DocumentStore& docs,
                        const Document& doc) {
  Setup bounded = setup;
  bounded.limits.maxBlocks = std::min(bounded.limits.maxBlocks, options.dryRunBlocks);
  Finder f(doc);
  auto session = openWorkspace(bounded, options, docs, doc, Reach::Everything);
  const nlohmann::json report = session->check();
  for (const char* kind : {"alarms", "warnings"})
    for (const auto& a : report[kind]) {
      if (a["file"] != f.name) continue;  // another open document's finding
      f.add(std::string_view(kind) == "alarms" ? kError : kWarning, a["code"], a["text"], a["file"],
            a["line"], a["col"], "ncvm check");
    }
  // No program text (yet), or a subprogram: nothing to run on its own.
  if (!session->main() || isCalledProgram(*session->main())) return f.out;
  try {
    session->setTiming(false);  // the cycle time is not shown; the run is the cheaper for it
    const Session::Result r = session->run(nullptr);
    if (r.alarm) {
      const Alarm& a = *r.alarm;
      const bool limit = a.code == alarmCode(AlarmId::BlockLimit);
      f.add(limit ? kWarning : kError, a.code, limitText(a, bounded),
            session->files().name(a.loc.file), a.loc.line, a.loc.col, "ncvm run (dry run)");
    }
    for (const auto& w : r.warnings)
      f.add(kWarning, w.code, w.text, session->files().name(w.loc.file), w.loc.line, w.loc.col,
            "ncvm run (dry run)");
  } catch (const std::exception& e) {
    // A setup the run refuses (SetupError) or a program it cannot start.
    f.add(kError, "setup", e.what(), "", 0, 0, "ncvm run (dry run)");
  }
  return f.out;
}

}  // namespace ncvm::lsp
