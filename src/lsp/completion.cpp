#include "lsp/completion.hpp"

#include <fmt/format.h>

#include <cctype>

#include "exec/gcode_table.hpp"
#include "lsp/code_tables.hpp"
#include "lsp/positions.hpp"

namespace ncvm::lsp {

namespace {
constexpr int kItemFunction = 3, kItemVariable = 6;

nlohmann::json item(const std::string& label, const std::string& detail, int kind,
                    const nlohmann::json& replace) {
  return {{"label", label},
          {"kind", kind},
          {"detail", detail},
          {"filterText", label},
          {"textEdit", {{"range", replace}, {"newText", label}}}};
}

// "G01: linear..." -> "linear..." (the label already says G01).
std::string afterColon(const std::string& s) {
  const size_t k = s.find(": ");
  return k == std::string::npos ? s : s.substr(k + 2);
}
}  // namespace

nlohmann::json complete(const Setup& setup, const Document& doc, int line, int character) {
  const std::string_view text = doc.line(static_cast<size_t>(line));
  const size_t cursor = byteColumn(text, character);
  size_t start = cursor;
  while (start > 0 &&
         (std::isdigit(static_cast<unsigned char>(text[start - 1])) || text[start - 1] == '.'))
    --start;
  nlohmann::json items = nlohmann::json::array();
  if (start == 0) return {{"isIncomplete", false}, {"items", items}};
  const char lead = static_cast<char>(std::toupper(static_cast<unsigned char>(text[start - 1])));
  // The G or M must be an address, not the last letter of a keyword.
  const bool word = start < 2 || !std::isalpha(static_cast<unsigned char>(text[start - 2]));
  const nlohmann::json replace = range(line, text, start - 1, cursor);
  if (lead == 'G' && word) {
    for (const auto& g : gcodeTable()) {
      if (!(g.seriesMask & seriesBit(setup.series()))) continue;
      std::string label = fmt::format("G{:02d}", g.code10 / 10);
      if (g.code10 % 10) label += fmt::format(".{}", g.code10 % 10);
      items.push_back(item(label, afterColon(describeGCode(g.code10, setup).value_or("")),
                           kItemFunction, replace));
    }
  } else if (lead == 'M' && word) {
    for (const auto& m : mCodeTable())
      items.push_back(item(fmt::format("M{:02d}", m.code), afterColon(describeMCode(m.code, setup)),
                           kItemFunction, replace));
  } else if (lead == '#') {
    const bool lathe = setup.kind == MachineKind::Lathe;
    for (const auto& r : variableTable()) {
      if (r.from < 1000 || (lathe ? !r.lathe : !r.mill)) continue;
      // One entry per axis the machine has, else the first number of the range.
      int64_t last = r.from;
      if (r.index == VariableRange::Index::Axis) {
        int axes = 0;
        for (const auto& a : setup.axes) axes += a.present ? 1 : 0;
        last = r.from + axes - 1;
      }
      for (int64_t n = r.from; n <= last; ++n)
        items.push_back(item(fmt::format("#{}", n),
                             afterColon(describeVariable(n, setup).value_or("")), kItemVariable,
                             replace));
    }
  }
  return {{"isIncomplete", false}, {"items", items}};
}

}  // namespace ncvm::lsp
