#include "lsp/nc_tokens.hpp"

#include <cctype>
#include <charconv>

namespace ncvm::lsp {

namespace {
bool isLetter(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0;
}
bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
char upper(char c) {
  return static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
}
}  // namespace

std::vector<Token> tokenizeLine(std::string_view line) {
  std::vector<Token> out;
  size_t k = 0;
  while (k < line.size()) {
    const char c = line[k];
    Token t;
    t.begin = k;
    if (c == '(') {
      const size_t close = line.find(')', k);
      k = close == std::string_view::npos ? line.size() : close + 1;
      t.kind = Token::Kind::Comment;
    } else if (c == '<') {
      const size_t close = line.find('>', k);
      k = close == std::string_view::npos ? line.size() : close + 1;
      t.kind = Token::Kind::ProgramName;
      const size_t inner = k - t.begin - 1 - (close == std::string_view::npos ? 0 : 1);
      t.value = std::string(line.substr(t.begin + 1, inner));
    } else if (c == '#') {
      ++k;
      while (k < line.size() && isDigit(line[k])) ++k;
      if (k == t.begin + 1) {
        t.kind = Token::Kind::Other;  // #[expression]
      } else {
        t.kind = Token::Kind::Variable;
        t.value = std::string(line.substr(t.begin + 1, k - t.begin - 1));
      }
    } else if (isLetter(c)) {
      size_t run = k;
      while (run < line.size() && isLetter(line[run])) ++run;
      if (run - k >= 2) {  // GOTO, WHILE, SIN, EQ...: a keyword, never an address
        t.kind = Token::Kind::Keyword;
        for (size_t j = k; j < run; ++j) t.value.push_back(upper(line[j]));
        k = run;
        if (t.value == "GOTO") {
          t.end = k;
          out.push_back(t);
          while (k < line.size() && line[k] == ' ') ++k;
          Token target;
          target.kind = Token::Kind::GotoTarget;
          target.begin = k;
          while (k < line.size() && isDigit(line[k])) ++k;
          if (k == target.begin) continue;  // GOTO #1, GOTO [#2+1]: computed
          target.end = k;
          target.value = std::string(line.substr(target.begin, k - target.begin));
          out.push_back(std::move(target));
          continue;
        }
      } else {
        t.kind = Token::Kind::Address;
        t.letter = upper(c);
        ++k;
        const size_t numberStart = k;
        if (k < line.size() && (line[k] == '-' || line[k] == '+')) ++k;
        while (k < line.size() && (isDigit(line[k]) || line[k] == '.')) ++k;
        t.value = std::string(line.substr(numberStart, k - numberStart));
      }
    } else {
      ++k;
      t.kind = Token::Kind::Other;
      if (c == ' ' || c == '\t') continue;
    }
    t.end = k;
    out.push_back(std::move(t));
  }
  return out;
}

std::optional<Token> tokenAt(std::string_view line, size_t col) {
  std::optional<Token> after;
  for (auto& t : tokenizeLine(line)) {
    if (col >= t.begin && col < t.end) return t;
    if (col == t.end && t.kind != Token::Kind::Other) after = t;
  }
  return after;
}

std::optional<long long> integerValue(std::string_view value) {
  if (value.empty() || value.find('.') != std::string_view::npos) return std::nullopt;
  if (value.front() == '+') value.remove_prefix(1);
  long long n = 0;
  auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
  if (ec != std::errc() || ptr != value.data() + value.size()) return std::nullopt;
  return n;
}

}  // namespace ncvm::lsp
