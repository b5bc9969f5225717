#include "report/svg_chart.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace ncvm {

std::string escapeXml(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

double niceStep(double span, int ticks) {
  if (!(span > 0) || !std::isfinite(span)) return 1;
  const double raw = span / std::max(1, ticks);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / mag;
  return (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * mag;
}

std::string tickLabel(double value, double step) {
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
  if (std::abs(value) < step * 1e-6) value = 0;  // no "-0"
  return fmt::format("{:.{}f}", value, decimals);
}

namespace {
constexpr const char* kFont = "font-family=\"sans-serif\" font-size=\"12\"";
}

std::string barChartSvg(const std::vector<Bar>& bars, const std::string& axisTitle,
                        const std::function<std::string(double)>& valueText) {
  const double labelW = 260, plotW = 520, valueW = 150, rowH = 22, top = 8;
  const double W = labelW + plotW + valueW;
  const double H = top + rowH * static_cast<double>(bars.size()) + 46;
  double vmax = 0;
  for (const auto& b : bars) vmax = std::max(vmax, b.value);
  const double step = niceStep(vmax > 0 ? vmax : 1, 5);
  const double axisMax = std::max(step, std::ceil((vmax > 0 ? vmax : 1) / step - 1e-9) * step);
  auto X = [&](double v) { return labelW + plotW * v / axisMax; };
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"chart\" width=\"{:.0f}\" "
      "height=\"{:.0f}\" viewBox=\"0 0 {:.0f} {:.0f}\" {}>\n",
      W, H, W, H, kFont);
  const double plotBottom = top + rowH * static_cast<double>(bars.size());
  for (double v = 0; v <= axisMax + step * 1e-6; v += step) {
    s += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#ddd\"/>\n"
        "<text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\">{4}</text>\n",
        X(v), top, plotBottom + 4, plotBottom + 18, tickLabel(v, step));
  }
  s += fmt::format(
      "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#333\"/>\n",
      labelW, plotBottom, labelW + plotW);
  s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n",
                   labelW + plotW / 2, plotBottom + 36, escapeXml(axisTitle));
  for (size_t k = 0; k < bars.size(); ++k) {
    const auto& b = bars[k];
    const double y = top + rowH * static_cast<double>(k);
    // About 6.5 px a character at 12 px: longer labels are cut (the full one is the tooltip).
    std::string label = b.label.size() > 36 ? b.label.substr(0, 35) + "\u2026" : b.label;
    s += fmt::format(
        "<g class=\"bar\"><title>{0}</title>"
        "<text x=\"{1:.1f}\" y=\"{2:.1f}\" text-anchor=\"end\">{3}</text>"
        "<rect x=\"{4:.1f}\" y=\"{5:.1f}\" width=\"{6:.2f}\" height=\"{7:.1f}\" fill=\"{8}\"/>"
        "<text x=\"{9:.1f}\" y=\"{2:.1f}\">{10}</text></g>\n",
        escapeXml(b.label + ": " + valueText(b.value)), labelW - 6, y + rowH * 0.68,
        escapeXml(label), labelW, y + 3, std::max(0.0, X(b.value) - labelW), rowH - 6, b.colour,
        X(b.value) + 4, escapeXml(valueText(b.value)));
  }
  s += "</svg>\n";
  return s;
}

namespace {
// A legend's head and its colour bar: n rectangles, each coloured by colourAt(the fraction of
// the bar at its middle), framed; the caller adds the ticks and the title and closes it.
constexpr double kLegendWidth = 560, kLegendLeft = 40, kLegendBarW = 480, kLegendBarH = 18,
                 kLegendTop = 6;
std::string legendBar(int n, const std::function<std::array<double, 3>(double)>& colourAt) {
  const double left = kLegendLeft, barW = kLegendBarW, barH = kLegendBarH, top = kLegendTop;
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"legend\" width=\"{0:.0f}\" "
      "height=\"64\" viewBox=\"0 0 {0:.0f} 64\" {1}>\n",
      kLegendWidth, kFont);
  for (int k = 0; k < n; ++k) {
    auto c = colourAt((k + 0.5) / n);
    s += fmt::format(
        "<rect x=\"{:.2f}\" y=\"{:.0f}\" width=\"{:.2f}\" height=\"{:.0f}\" "
        "fill=\"rgb({},{},{})\"/>\n",
        left + barW * k / n, top, barW / n + 0.3, barH, std::lround(255 * c[0]),
        std::lround(255 * c[1]), std::lround(255 * c[2]));
  }
  s += fmt::format(
      "<rect x=\"{:.0f}\" y=\"{:.0f}\" width=\"{:.0f}\" height=\"{:.0f}\" fill=\"none\" "
      "stroke=\"#333\"/>\n",
      left, top, barW, barH);
  return s;
}
}  // namespace

std::string colourScaleSvg(double from, double to, const std::string& axisTitle,
                           const std::function<std::array<double, 3>(double)>& colour) {
  const double left = kLegendLeft, barW = kLegendBarW, barH = kLegendBarH, top = kLegendTop;
  std::string s = legendBar(64, colour);
  const double span = to - from;
  if (span > 0) {
    const double step = niceStep(span, 6);
    for (double v = std::ceil(from / step - 1e-9) * step; v <= to + step * 1e-6; v += step) {
      const double x = left + barW * (v - from) / span;
      s += fmt::format(
          "<line x1=\"{0:.1f}\" y1=\"{1:.0f}\" x2=\"{0:.1f}\" y2=\"{2:.0f}\" stroke=\"#333\"/>"
          "<text x=\"{0:.1f}\" y=\"{3:.0f}\" text-anchor=\"middle\">{4}</text>\n",
          x, top + barH, top + barH + 4, top + barH + 17, tickLabel(v, step));
    }
  } else {
    s += fmt::format("<text x=\"{:.0f}\" y=\"{:.0f}\">{}</text>\n", left, top + barH + 17,
                     tickLabel(from, 0.001));
  }
  s += fmt::format("<text x=\"{:.0f}\" y=\"{:.0f}\" text-anchor=\"middle\">{}</text>\n",
                   left + barW / 2, top + barH + 36, escapeXml(axisTitle));
  s += "</svg>\n";
  return s;
}

std::string deviationScaleSvg(double tol, const std::string& axisTitle,
                              const std::function<std::array<double, 3>(double)>& colour) {
  const double left = kLegendLeft, barW = kLegendBarW, barH = kLegendBarH, top = kLegendTop;
  const double band = 0.2;
  // Position in [0, 1] of a deviation: the tolerance band in the middle fifth, the rest
  // log10(|dev| / tol) from 0 to 1 on each side.
  auto pos = [&](double d) {
    if (std::abs(d) <= tol) return 0.5 + band / 2 * d / tol;
    const double u = std::clamp(std::log10(std::abs(d) / tol), 0.0, 1.0);
    return d > 0 ? 0.5 + band / 2 + (0.5 - band / 2) * u : 0.5 - band / 2 - (0.5 - band / 2) * u;
  };
  auto dev = [&](double x) {  // the inverse of pos
    if (std::abs(x - 0.5) <= band / 2) return (x - 0.5) / (band / 2) * tol;
    const double u = (std::abs(x - 0.5) - band / 2) / (0.5 - band / 2);
    return (x > 0.5 ? 1 : -1) * tol * std::pow(10.0, u);
  };
  std::string s = legendBar(80, [&](double x) { return colour(dev(x)); });
  const double step = niceStep(tol, 1) / 10;
  for (double d : {-10 * tol, -tol, 0.0, tol, 10 * tol}) {
    const double x = left + barW * pos(d);
    s += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.0f}\" x2=\"{0:.1f}\" y2=\"{2:.0f}\" stroke=\"#333\"/>"
        "<text x=\"{0:.1f}\" y=\"{3:.0f}\" text-anchor=\"middle\">{4}{5}</text>\n",
        x, top + barH, top + barH + 4, top + barH + 17, d > 0 ? "+" : "", tickLabel(d, step));
  }
  s += fmt::format("<text x=\"{:.0f}\" y=\"{:.0f}\" text-anchor=\"middle\">{}</text>\n",
                   left + barW / 2, top + barH + 36, escapeXml(axisTitle));
  s += "</svg>\n";
  return s;
}

}  // namespace ncvm
