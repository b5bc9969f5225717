#include "lsp/hover.hpp"

#include <fmt/format.h>

#include <cmath>

#include "lsp/code_tables.hpp"
#include "lsp/nc_tokens.hpp"
#include "lsp/positions.hpp"

namespace ncvm::lsp {

namespace {
std::string wordText(const Setup& setup, const Token& t) {
  using K = Token::Kind;
  switch (t.kind) {
    case K::Variable: {
      const auto n = integerValue(t.value);
      if (!n) return {};
      if (auto d = describeVariable(*n, setup)) return *d;
      return fmt::format("#{}: no such variable in ncvm on this machine (PS0115 when used)", *n);
    }
    case K::Keyword:
      return keywordMeaning(t.value);
    case K::GotoTarget:
      return fmt::format("GOTO {}: jump to sequence number N{} of this program", t.value, t.value);
    case K::ProgramName:
      return fmt::format("<{}>: program name (M98 <{}> and G65 <{}> call it)", t.value, t.value,
                         t.value);
    case K::Address: {
      if (t.letter == 'G' && !t.value.empty()) {
        const double v = std::atof(t.value.c_str());
        const int code10 = static_cast<int>(std::lround(v * 10));
        if (auto d = describeGCode(code10, setup)) return *d;
        return fmt::format("G{}: not a G code of this machine's series (PS0010)", t.value);
      }
      if (t.letter == 'M')
        if (const auto m = integerValue(t.value)) return describeMCode(static_cast<int>(*m), setup);
      const std::string meaning = addressMeaning(t.letter, setup.kind);
      if (meaning.empty()) return {};
      return fmt::format("{}{}: {}", t.letter, t.value, meaning);
    }
    default:
      return {};
  }
}
}  // namespace

nlohmann::json hover(const Setup& setup, const Document& doc, int line, int character) {
  const std::string_view text = doc.line(static_cast<size_t>(line));
  const auto t = tokenAt(text, byteColumn(text, character));
  if (!t) return nullptr;
  const std::string value = wordText(setup, *t);
  if (value.empty()) return nullptr;
  return {{"contents", {{"kind", "plaintext"}, {"value", value}}},
          {"range", range(line, text, t->begin, t->end)}};
}

}  // namespace ncvm::lsp
