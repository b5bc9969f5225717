#include "server/state_diff.hpp"

#include <cstring>

#include "app/machine_state.hpp"
#include "app/session.hpp"

namespace ncvm::server {

namespace {

// System variables shown in the viewer's panel (fanuc-reference: #3901/#3902 part counters,
// #4001-#4022 modal G codes, #4107-#4120 D F H M N O S T of the last block, #5001- block end,
// #5021- machine, #5041- work position, #5061- skip position, #5081- tool offset), per axis
// for the axes the machine reports.
std::vector<int> systemVariables(int axes, bool positionsApart) {
  std::vector<int> v{3901, 3902};
  for (int g = 4001; g <= 4022; ++g) v.push_back(g);
  for (int n : {4107, 4109, 4111, 4113, 4114, 4115, 4119, 4120}) v.push_back(n);
  for (int base : {5000, 5020, 5040, 5060, 5080}) {
    if (positionsApart && base <= 5040) continue;
    for (int k = 1; k <= axes; ++k) v.push_back(base + k);
  }
  return v;
}

// The modal state as the panel shows it is made from these fields only: comparing them
// first spares building its JSON for every event (most events change none of them).
bool sameModal(const ModalState& a, const ModalState& b) {
  return a.g == b.g && a.feed == b.feed && a.speed == b.speed && a.tool == b.tool &&
         a.dOffset == b.dOffset && a.hOffset == b.hOffset && a.e == b.e && a.b == b.b &&
         a.lastM == b.lastM && a.workP == b.workP && a.unit == b.unit;
}

// The modal state's JSON (modalJson) differs only in the G code groups.
bool onlyGroupsDiffer(const ModalState& a, const ModalState& b) {
  return a.feed == b.feed && a.speed == b.speed && a.tool == b.tool && a.dOffset == b.dOffset &&
         a.hOffset == b.hOffset && a.unit == b.unit;
}

}  // namespace

template <size_t N>
void StateDiff::compareAll(nlohmann::json& step, const char* key, int first,
                           const std::array<Value, N>& now, Value* was) {
  // Most events change no variable: one memcmp of the array says so. The copy kept is the
  // control's array byte for byte (padding included), so that an unchanged array compares
  // equal; a difference in padding only finds no change below and is copied over too.
  if (!first_ && std::memcmp(now.data(), was, N * sizeof(Value)) == 0) return;
  for (size_t k = 0; k < N; ++k) {
    const Value& v = now[k];
    if (v.null != was[k].null || (!v.null && v.v != was[k].v) || first_)
      changed(step, key, first + static_cast<int>(k), v, was[k]);
  }
  std::memcpy(was, now.data(), N * sizeof(Value));
}

StateDiff::StateDiff(const Setup& setup, bool positionsApart)
    : setup_(setup),
      positionsApart_(positionsApart),
      system_numbers_(systemVariables(setup.reportedAxes(), positionsApart)),
      system_(system_numbers_.size()),
      systemReadable_(system_numbers_.size(), true) {}

void StateDiff::changed(nlohmann::json& step, const char* key, int number, const Value& now,
                        Value& was) {
  was = now;
  if (first_ && now.null) return;
  step[key]["#" + std::to_string(number)] =
      now.null ? nlohmann::json(nullptr) : nlohmann::json(now.v);
}

nlohmann::json StateDiff::next(bool offsetsChanged) {
  nlohmann::json step;  // null until something changed: most events change nothing
  if (!attached()) return step;
  auto compare = [&](const char* key, int number, const Value& now, Value& was) {
    if (now.null != was.null || (!now.null && now.v != was.v) || first_)
      changed(step, key, number, now, was);
  };
  // Variables are compared with what was last read (a vacant one and 0 differ); only what
  // changed goes into the delta. The arrays are read directly: this runs after every event.
  compareAll(step, "l", 1, exec_->currentLocals(), locals_.data());
  compareAll(step, "c", 100, exec_->common100(), common_.data());
  compareAll(step, "c", 500, exec_->memory().common500, common_.data() + 100);
  // #4001-#4022 are the modal G codes: read only when the modal state changed.
  const ModalState& m = exec_->modal();
  const bool modalChanged = !haveModal_ || !sameModal(m, lastModal_);
  for (size_t k = 0; k < system_numbers_.size(); ++k) {
    const int n = system_numbers_[k];
    if (!systemReadable_[k] || (!modalChanged && n >= 4001 && n <= 4022)) continue;
    Value v;
    try {
      v = exec_->readVar(n);
    } catch (const std::exception&) {
      systemReadable_[k] = false;  // a variable this machine does not have (an axis, a series)
      continue;
    }
    compare("s", n, v, system_[k]);
  }
  if (positionsApart_) {
    const int axes = setup_.reportedAxes();
    positions_.assign(static_cast<size_t>(3 * axes), 0.0);
    for (int g = 0; g < 3; ++g)
      for (int k = 1; k <= axes; ++k) {
        try {
          Value v = exec_->readVar(5000 + 20 * g + k);
          positions_[static_cast<size_t>(g * axes + k - 1)] = v.null ? 0.0 : v.v;
        } catch (const std::exception&) {
        }
      }
  }

  if (modalChanged && haveModal_ && onlyGroupsDiffer(m, lastModal_)) {
    // A move of another kind (G01 after G02), a plane, a canned cycle: only the G code groups
    // changed, and only those go into the delta, without building the modal JSON again
    // (which cost a third of the server's time on a million-line CAM program).
    nlohmann::json delta = nlohmann::json::object();
    for (size_t g = 1; g < static_cast<size_t>(kGroups); ++g) {
      if (m.g[g] == lastModal_.g[g]) continue;
      auto entry = modal_.find(std::to_string(g));
      if (entry == modal_.end()) continue;  // a group this series does not have
      *entry = m.g[g] / 10.0;
      delta[entry.key()] = *entry;
    }
    if (!delta.empty()) step["m"] = std::move(delta);
    lastModal_ = m;
  } else if (modalChanged) {
    // The first time the whole modal state, then only the entries that changed.
    nlohmann::json full = modalJson(m, setup_);
    nlohmann::json delta = nlohmann::json::object();
    for (auto it = full.begin(); it != full.end(); ++it) {
      auto was = modal_.find(it.key());
      if (!haveModal_ || was == modal_.end() || *was != it.value()) delta[it.key()] = it.value();
    }
    if (!delta.empty()) step["m"] = std::move(delta);
    modal_ = std::move(full);
    lastModal_ = m;
    haveModal_ = true;
  }
  if (offsetsChanged || first_)
    step["o"] = {{"work", workOffsetsJson(exec_->memory(), setup_, true)},
                 {"tool", toolOffsetsJson(exec_->memory(), setup_)}};
  first_ = false;
  return step;
}

}  // namespace ncvm::server
