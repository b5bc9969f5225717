#pragma once
// Deviation statistics shared by the stock models: signed distances between the simulated
// stock and the target, summarised in bands of the user tolerance.
#include <nlohmann/json.hpp>
#include <string>
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
//  "bands": [{"from", "to", "share"}], "measured"}; from/to null for the open ends, shares of
// the total weight. No samples: not measured (markNotMeasured), never a clean 100 %.
nlohmann::json deviationJson(const std::vector<DeviationSample>& samples, double tolerance);

// Turns a deviation (or uncut) object into "not measured": "measured" false, "not_measured"
// the reason, every statistic and band share null, so that no report shows a pass or a zero
// for what was not measured.
void markNotMeasured(nlohmann::json& summary, const std::string& why);

// What a summary line shows for an analysis object: "not measured (WHY)" when it is one,
// else empty.
std::string notMeasuredText(const nlohmann::json& summary);

// Colour (#rrggbb) of a deviation for the pictures: green within the tolerance, red
// shades for excess, blue shades for gouge, saturated at 5 tolerances.
const char* deviationColour(double d, double tolerance);

}  // namespace ncvm
