#pragma once
// The keys of the [timing] section of the setup (docs/setup-format.md): each sets a field of
// TimingSetup (machine/timing_params.hpp), the data the cycle-time model reads.
#include <string>
#include <variant>
#include <vector>

#include "machine/timing_params.hpp"

namespace ncvm {

// A [timing] value from the setup file or --set.
using TimingValue = std::variant<bool, double, std::string, std::vector<double>>;
// Applies timing.<key>; throws std::invalid_argument with the reason when the key or value
// is wrong.
void applyTimingKey(TimingSetup& t, const std::string& key, const TimingValue& v);

}  // namespace ncvm
