#pragma once
// `ncvm run --report FILE.html`: one self-contained HTML page (no external files) with the
// run summary, alarms and warnings, time, the stock pictures inlined and the deviation
// table.
#include <nlohmann/json.hpp>
#include <string>

namespace ncvm {

// state: the state JSON of the run (docs/trace-format.md), with "stock" when the stock was
// simulated; pictureDir: where the analysis' "pictures" files are (the --stock-out folder).
std::string htmlReport(const nlohmann::json& state, const std::string& title,
                       const std::string& pictureDir);

}  // namespace ncvm
