#pragma once
// The report's picture of the tool path (html_report.hpp): a mill's plan view (X right,
// Y up) or a lathe's half-section (Z right, X as a radius up), at one scale on both axes,
// with a grid, ticks and axis titles in the program's units, rapids dashed, feeds solid, G31
// moves and their touch points marked, and a legend. Lines closer than half a pixel are
// merged, so the SVG stays small for long programs.
#include <string>

#include "machine/setup.hpp"
#include "report/report_recorder.hpp"

namespace ncvm {

std::string toolpathSvg(const ReportRecorder& rec, const Setup& setup, const std::string& units);

}  // namespace ncvm
