#include "report/toolpath_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "report/svg_chart.hpp"

namespace ncvm {

namespace {

struct Style {
  const char* colour;
  const char* dash;
  double width;
  const char* name;
};

Style styleOf(PathKind k) {
  switch (k) {
    case PathKind::Rapid:
      return {"#d9822b", "5 4", 1.0, "rapid (G00)"};
    case PathKind::Probe:
      return {"#1e9e4a", "", 1.6, "G31 measuring move"};
    case PathKind::Feed:
      break;
  }
  return {"#1f5fbf", "", 1.3, "feed (G01-G03)"};
}

}  // namespace

std::string toolpathSvg(const ReportRecorder& rec, const Setup& setup, const std::string& units) {
  const bool lathe = setup.kind == MachineKind::Lathe;
  const bool diameterX = lathe && setup.axes[0].diameter;
  // (u, v): the picture's right and up.
  auto uv = [&](const std::array<float, 3>& p) -> std::array<double, 2> {
    if (lathe) return {p[2], diameterX ? p[0] / 2.0 : p[0]};
    return {p[0], p[1]};
  };
  const auto& path = rec.path();
  double ulo = std::numeric_limits<double>::infinity(), uhi = -ulo, vlo = ulo, vhi = -ulo;
  auto grow = [&](const std::array<double, 2>& q) {
    ulo = std::min(ulo, q[0]), uhi = std::max(uhi, q[0]);
    vlo = std::min(vlo, q[1]), vhi = std::max(vhi, q[1]);
  };
  for (const auto& v : path) grow(uv(v.p));
  for (const auto& pr : rec.probes()) grow(uv(pr.drawn));
  if (lathe && !path.empty()) grow({ulo, 0.0});  // the axis of rotation is always in view
  if (path.empty()) return "";
  // A path along one line still gets an area around it.
  const double span = std::max({uhi - ulo, vhi - vlo, 1e-3});
  if (uhi - ulo < span * 0.05) ulo -= span * 0.025, uhi += span * 0.025;
  if (vhi - vlo < span * 0.05) vlo -= span * 0.025, vhi += span * 0.025;
  const double step = niceStep(span, 10);
  // A margin of 4 % around the path; grid lines at the multiples of the step inside.
  const double pad = span * 0.04;
  const double gulo = ulo - pad, guhi = uhi + pad, gvlo = vlo - pad, gvhi = vhi + pad;

  const double maxW = 820, maxH = 620, left = 64, right = 16, top = 12, bottom = 52;
  const double scale = std::min(maxW / (guhi - gulo), maxH / (gvhi - gvlo));
  const double pw = (guhi - gulo) * scale, ph = (gvhi - gvlo) * scale;
  const double legendH = 26;
  const double W = left + pw + right, H = top + ph + bottom + legendH;
  auto X = [&](double u) { return left + (u - gulo) * scale; };
  auto Y = [&](double v) { return top + (gvhi - v) * scale; };

  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"toolpath\" width=\"{0:.0f}\" "
      "height=\"{1:.0f}\" viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"sans-serif\" "
      "font-size=\"12\">\n<rect x=\"{2:.1f}\" y=\"{3:.1f}\" width=\"{4:.1f}\" height=\"{5:.1f}\" "
      "fill=\"#fbfbfb\" stroke=\"#888\"/>\n",
      W, H, left, top, pw, ph);
  // Grid and ticks, one label every grid line (at least ~40 px apart by the step choice).
  const int labelEvery = step * scale < 40 ? static_cast<int>(std::ceil(40 / (step * scale))) : 1;
  int k = 0;
  for (double u = std::ceil(gulo / step) * step; u <= guhi; u += step, ++k) {
    s += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#e2e2e2\"/>\n",
        X(u), top, top + ph);
    if (k % labelEvery == 0)
      s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n", X(u),
                       top + ph + 16, tickLabel(u, step));
  }
  k = 0;
  for (double v = std::ceil(gvlo / step) * step; v <= gvhi; v += step, ++k) {
    s += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#e2e2e2\"/>\n",
        left, Y(v), left + pw);
    if (k % labelEvery == 0)
      s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{}</text>\n", left - 5,
                       Y(v) + 4, tickLabel(v, step));
  }
  const std::string uName = lathe ? "Z" : "X";
  const std::string vName = lathe ? (diameterX ? "X radius (diameter / 2)" : "X") : "Y";
  s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{} ({})</text>\n",
                   left + pw / 2, top + ph + 34, uName, units);
  s += fmt::format(
      "<text transform=\"translate({:.1f} {:.1f}) rotate(-90)\" text-anchor=\"middle\">{} "
      "({})</text>\n",
      14.0, top + ph / 2, escapeXml(vName), units);
  // Work zero (and on a lathe the spindle axis, dash-dotted).
  if (lathe) {
    s += fmt::format(
        "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#555\" "
        "stroke-dasharray=\"14 3 2 3\"/>\n",
        left, Y(0), left + pw, Y(0));
  } else if (0 >= gulo && 0 <= guhi && 0 >= gvlo && 0 <= gvhi) {
    s += fmt::format(
        "<path d=\"M{0:.1f} {1:.1f}h16M{0:.1f} {1:.1f}v-16\" stroke=\"#555\" "
        "stroke-width=\"1.5\" fill=\"none\"/>\n",
        X(0), Y(0));
  }

  // The path: one <path> per run of one kind; points closer than half a pixel merged.
  std::string d;
  PathKind runKind = PathKind::Feed;
  double lastX = 0, lastY = 0;
  bool open = false;
  auto flush = [&] {
    if (!open) return;
    Style st = styleOf(runKind);
    s += fmt::format("<path class=\"{}\" d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"",
                     runKind == PathKind::Rapid   ? "rapid"
                     : runKind == PathKind::Probe ? "probe"
                                                  : "feed",
                     d, st.colour, st.width);
    if (*st.dash) s += fmt::format(" stroke-dasharray=\"{}\"", st.dash);
    s += "/>\n";
    d.clear();
    open = false;
  };
  for (size_t i = 0; i < path.size(); ++i) {
    const auto q = uv(path[i].p);
    const double x = X(q[0]), y = Y(q[1]);
    if (path[i].start) {  // a new piece: the pen goes up and down again here
      if (open) d += fmt::format("M{:.1f} {:.1f}", x, y);
      lastX = x, lastY = y;
      continue;
    }
    if (!open || path[i].kind != runKind) {
      flush();
      runKind = path[i].kind;
      d = fmt::format("M{:.1f} {:.1f}", lastX, lastY);
      open = true;
    } else if (std::abs(x - lastX) < 0.5 && std::abs(y - lastY) < 0.5 && i + 1 < path.size() &&
               !path[i + 1].start && path[i + 1].kind == runKind) {
      continue;
    }
    d += fmt::format("L{:.1f} {:.1f}", x, y);
    lastX = x, lastY = y;
    if (d.size() > 60000) {  // keeps each element of a reasonable size
      flush();
      open = false;
    }
  }
  flush();
  // G31 end points: a filled ring where the signal came, a hollow one where it never did.
  for (const auto& pr : rec.probes()) {
    const auto q = uv(pr.drawn);
    s += fmt::format(
        "<circle class=\"{}\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4\" fill=\"{}\" stroke=\"#b00\" "
        "stroke-width=\"1.5\"/>\n",
        pr.hit ? "probe-hit" : "probe-miss", X(q[0]), Y(q[1]), pr.hit ? "#e33" : "none");
  }
  // The first point of the path.
  {
    const auto q = uv(path.front().p);
    s += fmt::format("<path class=\"start\" d=\"M{:.1f} {:.1f}l-5 -9h10z\" fill=\"#222\"/>\n",
                     X(q[0]), Y(q[1]));
  }
  // Legend.
  double lx = left, ly = top + ph + bottom + 8;
  auto legendLine = [&](PathKind kind) {
    Style st = styleOf(kind);
    s += fmt::format(
        "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" "
        "stroke-width=\"{}\"{}/><text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n",
        lx, ly, lx + 26, ly, st.colour, st.width + 0.7,
        *st.dash ? fmt::format(" stroke-dasharray=\"{}\"", st.dash) : std::string(), lx + 31,
        ly + 4, st.name);
    lx += 46 + 7.0 * static_cast<double>(std::string(st.name).size());
  };
  legendLine(PathKind::Feed);
  legendLine(PathKind::Rapid);
  if (!rec.probes().empty()) {
    legendLine(PathKind::Probe);
    s += fmt::format(
        "<circle cx=\"{0:.1f}\" cy=\"{1:.1f}\" r=\"4\" fill=\"#e33\" stroke=\"#b00\"/>"
        "<text x=\"{2:.1f}\" y=\"{3:.1f}\">touch</text>"
        "<circle cx=\"{4:.1f}\" cy=\"{1:.1f}\" r=\"4\" fill=\"none\" stroke=\"#b00\"/>"
        "<text x=\"{5:.1f}\" y=\"{3:.1f}\">no touch</text>\n",
        lx + 4, ly, lx + 12, ly + 4, lx + 62, lx + 70);
    lx += 140;
  }
  s += fmt::format(
      "<path d=\"M{:.1f} {:.1f}l-5 -9h10z\" fill=\"#222\"/><text x=\"{:.1f}\" y=\"{:.1f}\">start"
      "</text>\n",
      lx + 5, ly + 5, lx + 14, ly + 4);
  lx += 60;
  s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">grid {} {}</text>\n", lx, ly + 4,
                   tickLabel(step, step), units);
  s += "</svg>\n";
  return s;
}

}  // namespace ncvm
