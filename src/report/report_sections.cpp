#include "report/report_sections.hpp"

#include <fmt/format.h>

#include "report/clock_time.hpp"
#include "report/svg_chart.hpp"
#include "report/toolpath_svg.hpp"

namespace ncvm {

namespace {

std::string seconds(double t) {
  return fmt::format("{:.2f} s", t);
}

std::string block(const ReportInputs& in, const RecordedOrigin& at) {
  std::string s =
      fmt::format("{}:{}", in.files ? in.files->name(at.file) : std::string("?"), at.line);
  if (at.n >= 0) s += fmt::format(" N{}", at.n);
  return escapeXml(s);
}

char axisName(const ReportInputs& in, int axis) {
  if (in.setup && axis >= 0 && axis < kMaxAxes)
    return in.setup->axes[static_cast<size_t>(axis)].name;
  return "XYZABC"[axis >= 0 && axis < kMaxAxes ? axis : 0];
}

}  // namespace

std::string timeSection(const nlohmann::json& state) {
  std::string h = "<h2>Time</h2>\n";
  const double t = state.value("cycle_time", 0.0);
  const double simple = state.value("cycle_time_simple", t);
  const auto& timing = state.contains("timing") ? state["timing"] : nlohmann::json(nullptr);
  if (!timing.is_object()) {
    h += fmt::format(
        "<p class=\"time-kind\">Cycle time {} ({}), length &divide; feed: <strong>not "
        "modelled</strong> (the time model was off).</p>\n",
        seconds(t), clockTime(t));
    return h;
  }
  const bool dynamic = timing.value("model", std::string()) == "dynamic";
  if (dynamic)
    h += fmt::format(
        "<p class=\"time-kind\">Cycle time <strong>{} ({}), modelled</strong> by the machine "
        "model (<code>[timing] model = \"dynamic\"</code>: acceleration, jerk, corners, "
        "look-ahead, block and auxiliary times). Length &divide; feed alone: {} ({}).</p>\n",
        seconds(t), clockTime(t), seconds(simple), clockTime(simple));
  else
    h += fmt::format(
        "<p class=\"time-kind\">Cycle time <strong>{} ({}), length &divide; feed</strong>: "
        "<strong>not modelled</strong> (the simple model: no acceleration, corners or "
        "auxiliary times; <code>[timing] model = \"dynamic\"</code> models them).</p>\n",
        seconds(t), clockTime(t));
  const std::string what = dynamic ? "modelled time (s)" : "time, length \u00f7 feed (s)";
  auto value = [](double v) { return fmt::format("{:.2f} s", v); };

  if (timing.contains("by_type") && timing["by_type"].is_object()) {
    static const std::pair<const char*, const char*> kinds[] = {{"cutting", "#1f5fbf"},
                                                                {"rapid", "#d9822b"},
                                                                {"dwell", "#8e5bb5"},
                                                                {"auxiliary", "#6b6b6b"}};
    std::vector<Bar> bars;
    for (const auto& [k, colour] : kinds)
      if (timing["by_type"].contains(k))
        bars.push_back({k, timing["by_type"][k].value("time", 0.0), colour});
    h += "<h3>By kind of motion</h3>\n<figure>" + barChartSvg(bars, what, value) + "</figure>\n";
  }
  if (timing.contains("by_tool") && timing["by_tool"].is_array() && !timing["by_tool"].empty()) {
    std::vector<Bar> bars;
    for (const auto& b : timing["by_tool"])
      bars.push_back({fmt::format("T{}", b.value("tool", 0)), b.value("time", 0.0), "#3b8f8f"});
    h += "<h3>By tool</h3>\n<figure>" + barChartSvg(bars, what, value) + "</figure>\n";
  }
  if (timing.contains("operations") && timing["operations"].is_array() &&
      !timing["operations"].empty()) {
    const auto& ops = timing["operations"];
    constexpr size_t kMaxBars = 40;
    std::vector<Bar> bars;
    for (size_t k = 0; k < ops.size() && k < kMaxBars; ++k) {
      const auto& op = ops[k];
      std::string label = fmt::format("{}. T{}", k + 1, op.value("tool", 0));
      if (op.contains("label") && op["label"].is_string())
        label += " " + op["label"].get<std::string>();
      bars.push_back({label, op.value("time", 0.0), "#5a7fb0"});
    }
    h += "<h3>By operation</h3>\n<figure>" + barChartSvg(bars, what, value);
    if (ops.size() > kMaxBars)
      h += fmt::format("<figcaption>The first {} of {} operations.</figcaption>", kMaxBars,
                       ops.size());
    h += "</figure>\n";
  }
  return h;
}

std::string toolpathSection(const ReportInputs& in, const std::string& units) {
  std::string h = "<h2>Tool path</h2>\n";
  if (!in.recorder || !in.setup) return h + "<p>Not recorded.</p>\n";
  const ReportRecorder& rec = *in.recorder;
  const bool lathe = in.setup->kind == MachineKind::Lathe;
  std::string svg = toolpathSvg(rec, *in.setup, units);
  if (svg.empty()) return h + "<p>No move: nothing to draw.</p>\n";
  h += "<figure class=\"toolpath\">\n" + svg;
  h += fmt::format(
      "<figcaption>{}, {}, one scale on both axes. Work coordinates of the system the program "
      "first cuts in (<code>stock.frame</code>): after the program moves work zero the path "
      "stays where the tool went on the machine. {} moves",
      lathe ? "Half-section through the spindle axis (Z right, X up as a radius)"
            : "Plan view from above (X right, Y up)",
      units, rec.moves());
  if (rec.movesNotDrawn())
    h += fmt::format(", of which the last {} are not drawn (the picture's size limit)",
                     rec.movesNotDrawn());
  h += ".</figcaption>\n</figure>\n";
  return h;
}

std::string probingSection(const ReportInputs& in, const std::string& units) {
  std::string h = "<h2>Probing and offsets written</h2>\n";
  if (!in.recorder) return h + "<p>Not recorded.</p>\n";
  const ReportRecorder& rec = *in.recorder;
  if (rec.probeCount() == 0) {
    h += "<p>No G31 move.</p>\n";
  } else {
    uint64_t hits = 0;
    for (const auto& p : rec.probes()) hits += p.hit;
    h += fmt::format(
        "<h3>G31 moves</h3>\n<p>{} G31 moves, {} touched (the skip signal came), {} did "
        "not{}.</p>\n",
        rec.probeCount(), hits, rec.probes().size() - hits,
        rec.probes().size() < rec.probeCount()
            ? fmt::format(" (of the first {} listed)", rec.probes().size())
            : std::string());
    h += fmt::format(
        "<table class=\"probes\">\n<tr><th>#</th><th class=\"l\">block</th><th "
        "class=\"l\">signal</th><th>{0} ({3})</th><th>{1} ({3})</th><th>{2} ({3})</th></tr>\n",
        axisName(in, 0), axisName(in, 1), axisName(in, 2), units);
    size_t k = 0;
    for (const auto& p : rec.probes())
      h += fmt::format(
          "<tr><td>{}</td><td class=\"l\">{}</td><td class=\"l\">{}</td><td>{:.4f}</td><td>{:.4f}"
          "</td><td>{:.4f}</td></tr>\n",
          ++k, block(in, p.at), p.hit ? "touch" : "no touch", p.position[0], p.position[1],
          p.position[2]);
    h += "</table>\n<p>Positions: where the move stopped (the touch point latched in "
         "#5061-#5063), work coordinates as the program reads them.</p>\n";
  }
  if (rec.offsetCount() == 0) {
    h += "<p>No offset written by the program.</p>\n";
    return h;
  }
  h += fmt::format("<h3>Offsets written by the program</h3>\n<p>{} writes{}.</p>\n",
                   rec.offsetCount(),
                   rec.offsets().size() < rec.offsetCount()
                       ? fmt::format(" (the first {} listed)", rec.offsets().size())
                       : std::string());
  h += fmt::format(
      "<table class=\"offsets\">\n<tr><th class=\"l\">block</th><th class=\"l\">kind</th><th "
      "class=\"l\">offset</th><th class=\"l\">axis</th><th>value ({})</th></tr>\n",
      units);
  for (const auto& o : rec.offsets())
    h += fmt::format(
        "<tr><td class=\"l\">{}</td><td class=\"l\">{}</td><td class=\"l\">{}</td><td "
        "class=\"l\">{}</td><td>{:.4f}</td></tr>\n",
        block(in, o.at), escapeXml(o.kind), escapeXml(o.name),
        o.axis >= 0 ? std::string(1, axisName(in, o.axis)) : std::string("-"), o.value);
  h += "</table>\n";
  return h;
}

}  // namespace ncvm
