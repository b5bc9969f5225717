#pragma once
// `ncvm run --report FILE.html`: one self-contained HTML page (no external files): the run
// summary with units, alarms and warnings, where the time goes (bar charts, labelled
// modelled or length / feed), a picture of the tool path, the probe results (every G31 and
// the offsets the program wrote), and the stock: its pictures inlined with their extent and
// colour scales, the deviation table and the collisions, or why there is no stock part.
#include <nlohmann/json.hpp>
#include <string>

#include "core/source.hpp"
#include "machine/setup.hpp"
#include "report/report_recorder.hpp"

namespace ncvm {

// What the page shows beside the state JSON; each may be missing (its part says so).
struct ReportInputs {
  const ReportRecorder* recorder = nullptr;  // the tool path, G31 moves and offset writes
  const Setup* setup = nullptr;
  const SourceFiles* files = nullptr;  // names the files of the recorder's blocks
  // Why the page has no stock part when the state has no "stock" (no [stock] in the setup).
  std::string noStock = "No stock in the setup (no [stock] section): no stock was simulated.";
};

// state: the state JSON of the run (docs/trace-format.md), with "stock" when the stock was
// simulated; pictureDir: where the analysis' "pictures" files are (the --stock-out folder).
std::string htmlReport(const nlohmann::json& state, const std::string& title,
                       const std::string& pictureDir, const ReportInputs& in = {});

}  // namespace ncvm
