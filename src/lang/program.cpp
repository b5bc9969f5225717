#include <fmt/format.h>

#include "lang/ir.hpp"

namespace ncvm {

std::string Program::displayName() const {
  if (number >= 0) return fmt::format("O{:04d}", number);
  return name;
}

int32_t Program::findLabel(int32_t n, uint32_t from) const {
  // Forward from `from` to the end, then from the start: the control's search order, which
  // decides which block wins when a sequence number appears twice.
  for (const auto& [seq, index] : labels)
    if (seq == n && index >= from) return static_cast<int32_t>(index);
  for (const auto& [seq, index] : labels)
    if (seq == n && index < from) return static_cast<int32_t>(index);
  return -1;
}

}  // namespace ncvm
