#pragma once
// Largest offset values the control accepts (PS0032 beyond, in G10 and the offset variables):
// 999.999 mm for tool offsets, 99999.999 mm for work offsets (IS-B), as stored in
// MachineMemory (integer nm, lathe X as a radius); imaginary tip directions 0-9. The
// machine-state file is held to the same limits (app/machine_state.cpp).
#include <cstdint>

namespace ncvm {

constexpr int64_t kMaxToolOffsetNm = 999'999'000;
constexpr int64_t kMaxWorkOffsetNm = 99'999'999'000;
constexpr int kMaxTipDirection = 9;

}  // namespace ncvm
