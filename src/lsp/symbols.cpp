#include "lsp/symbols.hpp"

#include <fmt/format.h>

#include "lsp/nc_tokens.hpp"
#include "lsp/positions.hpp"

namespace ncvm::lsp {

namespace {
constexpr int kSymbolFunction = 12, kSymbolKey = 20;

// The range of the first token of a kind (and letter) on a line, or of the whole line.
nlohmann::json tokenRange(std::string_view text, int line, Token::Kind kind, char letter) {
  for (const auto& t : tokenizeLine(text))
    if (t.kind == kind && t.letter == letter) return range(line, text, t.begin, t.end);
  return range(line, text, 0, text.size());
}
}  // namespace

nlohmann::json documentSymbols(const Setup& setup, const ServerOptions& options,
                               const DocumentStore& docs, const Document& doc) {
  auto ws = openWorkspace(setup, options, docs, doc, Reach::DocumentOnly);
  const auto lines = doc.lines();
  const auto lineText = [&lines](uint32_t line1) {
    return line1 >= 1 && line1 <= lines.size() ? lines[line1 - 1] : std::string_view{};
  };
  nlohmann::json out = nlohmann::json::array();
  for (const Program& p : ws->store().programs()) {
    if (p.loc.file != 0 || p.loc.line == 0) continue;
    const uint32_t first = p.loc.line;
    const uint32_t last = p.blocks.empty() ? first : std::max(first, p.blocks.back().loc.line);
    const int line0 = static_cast<int>(first - 1);
    nlohmann::json sym;
    // O number, <NAME> header, or neither: a file without a header is named by its stem.
    bool named = false;
    for (const auto& t : tokenizeLine(lineText(first))) named |= t.kind == Token::Kind::ProgramName;
    sym["name"] = p.number >= 0 ? p.label : named ? "<" + p.name + ">" : p.label;
    sym["kind"] = kSymbolFunction;
    const std::string_view lastText = lineText(last);
    sym["range"] = {{"start", {{"line", line0}, {"character", 0}}},
                    {"end", position(static_cast<int>(last - 1), lastText, lastText.size())}};
    sym["selectionRange"] = tokenRange(
        lineText(first), line0, p.number >= 0 ? Token::Kind::Address : Token::Kind::ProgramName,
        p.number >= 0 ? 'O' : 0);
    // The program's title: the comment on its header line, as a shop writes it.
    for (const auto& t : tokenizeLine(lineText(first)))
      if (t.kind == Token::Kind::Comment) {
        sym["detail"] = std::string(lineText(first).substr(t.begin, t.end - t.begin));
        break;
      }
    nlohmann::json children = nlohmann::json::array();
    for (const auto& [n, index] : p.labels) {
      const uint32_t l = p.blocks[index].loc.line;
      const std::string_view text = lineText(l);
      const auto r = tokenRange(text, static_cast<int>(l - 1), Token::Kind::Address, 'N');
      children.push_back({{"name", fmt::format("N{}", n)},
                          {"kind", kSymbolKey},
                          {"range", range(static_cast<int>(l - 1), text, 0, text.size())},
                          {"selectionRange", r}});
    }
    sym["children"] = std::move(children);
    out.push_back(std::move(sym));
  }
  return out;
}

}  // namespace ncvm::lsp
