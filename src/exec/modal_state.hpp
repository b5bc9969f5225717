#pragma once
// The control's modal state: the G code of each group and the modal words F, S, T, D, H, E,
// B (issue 27's modal-state component; the Executor owns one and nc_block.cpp changes it).
#include <array>
#include <cstdint>

#include "core/units.hpp"

namespace ncvm {

// The modal groups are indexed by the group number of #4000+g.
constexpr int kGroups = 32;

struct ModalState {
  std::array<int16_t, kGroups> g{};  // G code x10 per group
  double feed = 0;                   // F as programmed
  double speed = 0;                  // S as programmed (rpm or CSS)
  int32_t tool = 0;                  // T
  int32_t dOffset = 0, hOffset = 0;  // D, H
  double e = 0, b = 0;
  int32_t lastM = 0;
  int32_t workP = 0;  // P of G54.1
  InputUnit unit = InputUnit::Mm;
  // Derived from g[] for the hot path.
  int motion = 10;  // 0, 10, 20, 30 (x10)
  int plane = 17;
  bool incremental = false;
  bool feedPerRev = false;
  bool css = false;
};

}  // namespace ncvm
