#pragma once
// The names of the setup keys (docs/setup-format.md), for "did you mean" in setup errors.
// A key segment written X stands for an axis letter, N for a number.
#include <optional>
#include <string>
#include <vector>

namespace ncvm {

// Every fixed key name that src/machine/setup.cpp reads (tests/unit/setup_test.cpp checks
// that each one is accepted), with X and N placeholders.
const std::vector<std::string>& setupKeyNames();

// The known key nearest to a mistyped one (a few letters off), written with the mistyped
// key's own axis letters and numbers ("axes.Z.rapd" -> "axes.Z.rapid"); nullopt when none is near.
std::optional<std::string> nearestSetupKey(const std::string& key);

}  // namespace ncvm
