#pragma once
// The words of one program line as an editor points at them: which word is under the
// cursor and where it ends. Only where the words are, not what they do: the meaning comes
// from ncvm's parser and code tables.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ncvm::lsp {

struct Token {
  enum class Kind { Address, Variable, Keyword, GotoTarget, Comment, ProgramName, Other };
  Kind kind = Kind::Other;
  size_t begin = 0, end = 0;  // byte columns, 0-based, end exclusive
  char letter = 0;            // Address: the upper-case letter
  std::string value;          // Address: the number as written ("01", "-1.5"; "" for X#1);
                              // Variable, GotoTarget (the literal N of GOTO n): the digits;
                              // Keyword: upper case; ProgramName: the name
};

std::vector<Token> tokenizeLine(std::string_view line);
// The token that holds byte column `col` (or ends at it: the cursor just after a word).
std::optional<Token> tokenAt(std::string_view line, size_t col);
// A literal number of an address word or a GOTO target as an integer ("98", "0100"; not
// "1.5" or "").
std::optional<long long> integerValue(std::string_view value);

}  // namespace ncvm::lsp
