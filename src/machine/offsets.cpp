#include "machine/offsets.hpp"

#include <fmt/format.h>

#include <cctype>

namespace ncvm {

bool ToolOffsetRow::empty() const {
  for (int k = 0; k < 4; ++k)
    if (geometry[static_cast<size_t>(k)] || wear[static_cast<size_t>(k)]) return false;
  return tip == 0;
}

std::string workOffsetName(int index) {
  if (index == kWorkExt) return "EXT";
  if (index < kWorkP1) return fmt::format("G{}", 53 + index);
  return fmt::format("G54.1 P{}", index - kWorkP1 + 1);
}

int workOffsetIndex(const std::string& raw) {
  std::string n;
  for (char c : raw)
    if (!std::isspace(static_cast<unsigned char>(c)))
      n += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (n == "EXT" || n == "G54P0" || n == "P0") return kWorkExt;
  if (n.size() == 3 && n[0] == 'G' && n[1] == '5' && n[2] >= '4' && n[2] <= '9')
    return kWorkG54 + (n[2] - '4');
  std::string p;
  if (n.rfind("G54.1P", 0) == 0)
    p = n.substr(6);
  else if (n.rfind("G54P", 0) == 0)
    p = n.substr(4);
  else if (n.rfind("P", 0) == 0)
    p = n.substr(1);
  else
    return -1;
  if (p.empty() || p.size() > 3) return -1;
  for (char c : p)
    if (!std::isdigit(static_cast<unsigned char>(c))) return -1;
  int k = std::stoi(p);
  return (k >= 1 && k <= 300) ? kWorkP1 + k - 1 : -1;
}

}  // namespace ncvm
