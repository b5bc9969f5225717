#pragma once
// Parts of the HTML report (html_report.hpp), each an HTML fragment starting at its <h2>.
#include <nlohmann/json.hpp>
#include <string>

#include "report/html_report.hpp"

namespace ncvm {

// "Time": the cycle time, said to be modelled (the dynamic machine model) or length / feed
// (the simple model, not a modelled time), and bar charts by kind, by tool and by operation.
std::string timeSection(const nlohmann::json& state);

// "Tool path": the plan view (mill) or half-section (lathe), toolpath_svg.hpp.
std::string toolpathSection(const ReportInputs& in, const std::string& units);

// "Probing": every G31 (block, touch or not, the latched position) and every offset the
// program wrote (G10, #5221 and the other system variables, G52, G92).
std::string probingSection(const ReportInputs& in, const std::string& units);

}  // namespace ncvm
