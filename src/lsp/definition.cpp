#include "lsp/definition.hpp"

#include <cmath>
#include <fstream>

#include "lsp/nc_tokens.hpp"
#include "lsp/positions.hpp"

namespace ncvm::lsp {

int calledProgram(long long callP, bool m98, const Setup& setup) {
  if (m98 && setup.programNumberDigits == 4 && callP > 9999) return static_cast<int>(callP % 10000);
  return static_cast<int>(callP);
}

namespace {
// The text of a line of a file: from the editor when it is open, else from the disk.
std::string lineOf(const DocumentStore& docs, const std::string& file, uint32_t line) {
  for (const auto& [uri, d] : docs.all())
    if (documentName(d) == file) return std::string(d.line(line - 1));
  std::ifstream in(file, std::ios::binary);
  std::string text;
  for (uint32_t k = 0; k < line && std::getline(in, text); ++k) {
  }
  if (!text.empty() && text.back() == '\r') text.pop_back();
  return text;
}

std::string uriOf(const DocumentStore& docs, const std::string& file) {
  for (const auto& [uri, d] : docs.all())
    if (documentName(d) == file) return uri;
  return pathToUri(file);
}

// A location at the first token of `kind` (and letter) on a line, else at its start.
nlohmann::json locationAt(const DocumentStore& docs, const std::string& file, uint32_t line,
                          Token::Kind kind, char letter) {
  const std::string text = lineOf(docs, file, line);
  size_t begin = 0, end = text.size();
  for (const auto& t : tokenizeLine(text))
    if (t.kind == kind && t.letter == letter) {
      begin = t.begin;
      end = t.end;
      break;
    }
  return {{"uri", uriOf(docs, file)},
          {"range", range(static_cast<int>(line - 1), text, begin, end)}};
}

nlohmann::json programLocation(Session& ws, const DocumentStore& docs, const Program* p) {
  if (!p) return nullptr;
  const std::string file = ws.files().name(p->loc.file);
  return p->number >= 0 ? locationAt(docs, file, p->loc.line, Token::Kind::Address, 'O')
                        : locationAt(docs, file, p->loc.line, Token::Kind::ProgramName, 0);
}

struct LineCalls {
  bool m98 = false, g65 = false, g66 = false;
};
LineCalls callsOf(const std::vector<Token>& tokens) {
  LineCalls c;
  for (const auto& t : tokens) {
    if (t.kind != Token::Kind::Address) continue;
    const auto v = integerValue(t.value);
    if (!v) continue;
    c.m98 |= t.letter == 'M' && *v == 98;
    c.g65 |= t.letter == 'G' && *v == 65;
    c.g66 |= t.letter == 'G' && *v == 66;
  }
  return c;
}

// The program number the word calls, -1 if it calls none.
int callTarget(const Token& t, const LineCalls& calls, const Setup& setup) {
  if (t.kind != Token::Kind::Address) return -1;
  const auto v = integerValue(t.value);
  if (t.letter == 'P' && v && (calls.m98 || calls.g65 || calls.g66))
    return calledProgram(*v, calls.m98 && !calls.g65 && !calls.g66, setup);
  if (t.letter == 'G' && !t.value.empty()) {
    const double g = std::atof(t.value.c_str());
    if (g == std::floor(g)) return setup.gCodeCall(static_cast<int>(g));
  }
  if (t.letter == 'M' && v) {
    if (const int sub = setup.mCodeSubCall(static_cast<int>(*v)); sub >= 0) return sub;
    return setup.mCodeMacroCall(static_cast<int>(*v));
  }
  if (t.letter == 'T' && v && setup.tcs()) return 9000;
  return -1;
}
}  // namespace

nlohmann::json definition(const Setup& setup, const ServerOptions& options,
                          const DocumentStore& docs, const Document& doc, int line, int character) {
  const std::string_view text = doc.line(static_cast<size_t>(line));
  const auto tokens = tokenizeLine(text);
  const auto t = tokenAt(text, byteColumn(text, character));
  if (!t) return nullptr;
  if (t->kind == Token::Kind::GotoTarget) {
    const auto n = integerValue(t->value);
    auto ws = openWorkspace(setup, options, docs, doc, Reach::DocumentOnly);
    const Program* p = programAt(*ws, 0, static_cast<uint32_t>(line + 1));
    if (!p || !n) return nullptr;
    // The control searches forward from the GOTO block, then from the start.
    uint32_t from = 0;
    while (from < p->blocks.size() && p->blocks[from].loc.line <= static_cast<uint32_t>(line))
      ++from;
    const int32_t k = p->findLabel(static_cast<int32_t>(*n), from);
    if (k < 0) return nullptr;
    return locationAt(docs, documentName(doc), p->blocks[static_cast<size_t>(k)].loc.line,
                      Token::Kind::Address, 'N');
  }
  const LineCalls calls = callsOf(tokens);
  if (t->kind == Token::Kind::ProgramName && (calls.m98 || calls.g65 || calls.g66)) {
    auto ws = openWorkspace(setup, options, docs, doc, Reach::Everything);
    return programLocation(*ws, docs, ws->store().byName(t->value));
  }
  const int target = callTarget(*t, calls, setup);
  if (target < 0) return nullptr;
  auto ws = openWorkspace(setup, options, docs, doc, Reach::Everything);
  return programLocation(*ws, docs, ws->store().byNumber(target));
}

}  // namespace ncvm::lsp
