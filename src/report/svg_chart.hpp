#pragma once
// Small SVG pieces of the HTML report (html_report.hpp): bar charts with a labelled axis and
// colour-scale legends. Each returns one self-contained <svg> element.
#include <array>
#include <functional>
#include <string>
#include <vector>

namespace ncvm {

// Text made safe inside XML (and HTML) elements and attributes.
std::string escapeXml(const std::string& s);

// A round tick spacing (1, 2 or 5 times a power of ten) giving about `ticks` ticks on span.
double niceStep(double span, int ticks);

// A tick label: as few decimals as the step needs.
std::string tickLabel(double value, double step);

struct Bar {
  std::string label;
  double value = 0;
  std::string colour = "#3b6fb6";
};

// Horizontal bars on one axis from 0 with ticks, `unit` after the axis title and each value
// printed at the end of its bar (`valueText` formats it).
std::string barChartSvg(const std::vector<Bar>& bars, const std::string& axisTitle,
                        const std::function<std::string(double)>& valueText);

// A horizontal colour bar from `from` to `to` (low left) with ticks and the axis title.
// colour(u) gives the RGB of u in [0, 1].
std::string colourScaleSvg(double from, double to, const std::string& axisTitle,
                           const std::function<std::array<double, 3>(double)>& colour);

// The deviation map's legend: gouge (blue) from -10 tolerances to -tol, green within
// +-tol, excess (red) from +tol to +10 tolerances, log scale outside the band, ticks at
// +-10 tol, +-tol and 0 with their values. colour(dev) as the map's.
std::string deviationScaleSvg(double tol, const std::string& axisTitle,
                              const std::function<std::array<double, 3>(double)>& colour);

}  // namespace ncvm
