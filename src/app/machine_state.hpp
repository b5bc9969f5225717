#pragma once
// The machine-state file (--machine-state): what a Fanuc control keeps through power-off,
// as JSON in machine units (mm; lathe X as a diameter). Loaded before a run, saved after
// it, atomically, whatever way the run ended.
#include <nlohmann/json.hpp>

#include "machine/offsets.hpp"
#include "machine/setup.hpp"

namespace ncvm {

nlohmann::json memoryToJson(const MachineMemory& mem, const Setup& setup);
// Throws std::runtime_error naming the bad entry.
void memoryFromJson(const nlohmann::json& j, const Setup& setup, MachineMemory& mem);

// The offsets part of the state report.
nlohmann::json workOffsetsJson(const MachineMemory& mem, const Setup& setup, bool all);
nlohmann::json toolOffsetsJson(const MachineMemory& mem, const Setup& setup);

}  // namespace ncvm
