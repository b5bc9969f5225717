#pragma once
// Deviation statistics shared by the stock models: signed distances between the simulated
// stock and the target, summarised in bands of the user tolerance.
#include <nlohmann/json.hpp>
#include <vector>

namespace ncvm {

// One measurement: d > 0 is material left outside the target (excess), d < 0 material
// removed inside it (gouge). weight is what the sample stands for (contour length, area).
struct DeviationSample {
  double d = 0;
  double weight = 1;
};

// Band edges at +-1, 2, 3 and 5 tolerances. The JSON (docs/stock-analysis.md):
// {"tolerance", "samples", "max", "mean", "max_excess", "max_gouge", "in_tolerance",
//  "bands": [{"from", "to", "share"}]}; from/to null for the open ends, shares of the total weight.
nlohmann::json deviationJson(const std::vector<DeviationSample>& samples, double tolerance);

// Colour (#rrggbb) of a deviation for the pictures: green within the tolerance, red
// shades for excess, blue shades for gouge, saturated at 5 tolerances.
const char* deviationColour(double d, double tolerance);

}  // namespace ncvm
