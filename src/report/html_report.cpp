#include "report/html_report.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "report/clock_time.hpp"
#include "report/mill_pictures.hpp"
#include "report/report_sections.hpp"
#include "report/svg_chart.hpp"
#include "sim/deviation.hpp"

namespace ncvm {

namespace {

std::string escape(const std::string& s) {
  return escapeXml(s);
}

std::string base64(const std::string& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    auto v = (static_cast<uint32_t>(static_cast<uint8_t>(in[i])) << 16) |
             (static_cast<uint32_t>(static_cast<uint8_t>(in[i + 1])) << 8) |
             static_cast<uint8_t>(in[i + 2]);
    for (int s = 18; s >= 0; s -= 6) out += t[(v >> s) & 63];
  }
  if (i < in.size()) {
    uint32_t v = static_cast<uint32_t>(static_cast<uint8_t>(in[i])) << 16;
    if (i + 1 < in.size()) v |= static_cast<uint32_t>(static_cast<uint8_t>(in[i + 1])) << 8;
    out += t[(v >> 18) & 63];
    out += t[(v >> 12) & 63];
    out += i + 1 < in.size() ? t[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string readAll(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string num(const nlohmann::json& v, int digits = 4) {
  if (v.is_number()) return fmt::format("{:.{}f}", v.get<double>(), digits);
  if (v.is_null()) return "";
  return escape(v.is_string() ? v.get<std::string>() : v.dump());
}

std::string where(const nlohmann::json& a) {
  std::string s = fmt::format("{}:{}", a.value("file", std::string()), a.value("line", 0));
  if (a.contains("n") && a["n"].is_number() && a["n"].get<int>() >= 0)
    s += fmt::format(" N{}", a["n"].get<int>());
  return escape(s);
}

// What a stock picture covers, from its analysis entry: "X -10 ... 35 mm, Y -30 ... 15 mm".
std::string extentText(const nlohmann::json& p, const std::string& units) {
  if (!p.contains("extent") || !p["extent"].is_object()) return "";
  std::string s;
  // Across first, then up, as the picture is seen.
  for (const char* axis : {"x", "z", "y", "radius"}) {
    if (!p["extent"].contains(axis)) continue;
    const auto& range = p["extent"][axis];
    if (!range.is_array() || range.size() != 2) continue;
    const std::string a = axis;
    std::string name = a == "x"   ? "X (left to right)"
                       : a == "y" ? "Y (bottom to top)"
                       : a == "z" ? "Z (left to right)"
                                  : "X as a radius (bottom to top)";
    if (!s.empty()) s += ", ";
    s += fmt::format("{} {:.3f} &hellip; {:.3f} {}", name, range[0].get<double>(),
                     range[1].get<double>(), escape(units));
  }
  return s.empty() ? s : ". Covers " + s + ".";
}

}  // namespace

std::string htmlReport(const nlohmann::json& state, const std::string& title,
                       const std::string& pictureDir, const ReportInputs& in) {
  const std::string units =
      state.contains("modal") && state["modal"].is_object() && state["modal"].contains("units")
          ? state["modal"]["units"].get<std::string>()
          : std::string("mm");
  std::string h;
  h +=
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + escape(title) + "</title>\n";
  h +=
      "<style>body{font-family:sans-serif;margin:2em;max-width:70em}table{border-collapse:collapse}"
      "td,th{border:1px solid #bbb;padding:.2em .6em;text-align:right}th{background:#eee}"
      "td.l,th.l{text-align:left}.alarm{color:#b00}figure{margin:1em "
      "0}img,svg{max-width:100%;height:auto}</style>\n";
  h += "</head><body>\n<h1>" + escape(title) + "</h1>\n";

  h += "<h2>Summary</h2>\n<table>\n";
  auto row = [&](const std::string& k, const std::string& v) {
    h += "<tr><th class=\"l\">" + k + "</th><td class=\"l\">" + v + "</td></tr>\n";
  };
  row("program", escape(state.value("program", std::string())));
  if (in.setup)
    row("machine", fmt::format("{} ({})", in.setup->kind == MachineKind::Lathe ? "lathe" : "mill",
                               escape(in.setup->control)));
  row("units", escape(units) + " (lengths below are in these units unless marked)");
  row("ended", escape(state.value("end", std::string())));
  row("blocks", num(state.value("blocks", nlohmann::json(0)), 0));
  row("moves", num(state.value("moves", nlohmann::json(0)), 0));
  double t = state.value("cycle_time", 0.0);
  const bool modelled = state.contains("timing") && state["timing"].is_object() &&
                        state["timing"].value("model", std::string()) == "dynamic";
  row("cycle time", fmt::format("{:.2f} s ({}), {}", t, clockTime(t),
                                modelled ? "modelled" : "length &divide; feed, not modelled"));
  if (state.contains("path_length"))
    row("path length",
        fmt::format("rapid {} {u} / feed {} {u}", num(state["path_length"]["rapid"], 3),
                    num(state["path_length"]["feed"], 3), fmt::arg("u", escape(units))));
  h += "</table>\n";

  h += "<h2>Alarms and warnings</h2>\n";
  const auto& alarm = state.contains("alarm") ? state["alarm"] : nlohmann::json(nullptr);
  if (alarm.is_object())
    h += "<p class=\"alarm\">" + where(alarm) + ": " + escape(alarm.value("code", std::string())) +
         " " + escape(alarm.value("text", std::string())) + "</p>\n";
  else
    h += "<p>No alarm.</p>\n";
  if (state.contains("warnings") && !state["warnings"].empty()) {
    h += "<ul>\n";
    for (const auto& w : state["warnings"])
      h += "<li>" + where(w) + ": " + escape(w.value("code", std::string())) + " " +
           escape(w.value("text", std::string())) + "</li>\n";
    h += "</ul>\n";
  }

  h += timeSection(state);
  h += toolpathSection(in, units);
  h += probingSection(in, units);

  h += "<h2>Stock</h2>\n";
  if (!state.contains("stock") || !state["stock"].is_object()) {
    h += "<p class=\"no-stock\">" + escape(in.noStock) + "</p>\n";
  } else {
    const auto& st = state["stock"];
    const std::string stockUnits = st.value("units", units);
    if (st.contains("pictures")) {
      for (const auto& p : st["pictures"]) {
        std::string file = p.value("file", std::string());
        std::filesystem::path path = std::filesystem::path(pictureDir) / file;
        if (file.empty() || !std::filesystem::exists(path)) continue;
        h += "<figure>\n";
        std::string data = readAll(path);
        if (path.extension() == ".svg") {
          auto start = data.find("<svg");
          h += start == std::string::npos ? "" : data.substr(start);
        } else if (path.extension() == ".png") {
          h += "<img alt=\"" + escape(file) + "\" src=\"data:image/png;base64," + base64(data) +
               "\">";
        }
        if (p.contains("scale") && p["scale"].is_object() && p["scale"].contains("tolerance")) {
          const double tol = p["scale"].value("tolerance", 0.01);
          h += deviationScaleSvg(
              tol,
              fmt::format("deviation, stock - target ({}), log scale past the tolerance",
                          stockUnits),
              [tol](double d) { return millDeviationColour(d, tol); });
        } else if (p.contains("scale") && p["scale"].is_object()) {
          const auto& sc = p["scale"];
          h += colourScaleSvg(
              sc.value("from", 0.0), sc.value("to", 0.0),
              fmt::format("{} ({})", sc.value("quantity", std::string("Z")), stockUnits),
              heightColour);
        }
        h += "\n<figcaption>" + escape(p.value("title", file)) + extentText(p, stockUnits) +
             "</figcaption>\n</figure>\n";
      }
    }
    if (st.contains("deviation") && !notMeasuredText(st["deviation"]).empty()) {
      h += "<h3>Deviation from the target</h3>\n<p class=\"not-measured\">Deviation " +
           escape(notMeasuredText(st["deviation"])) + ".</p>\n";
    } else if (st.contains("deviation") && st["deviation"].is_object()) {
      const auto& d = st["deviation"];
      h += "<h3>Deviation from the target</h3>\n<table>\n";
      h += fmt::format(
          "<tr><th>tolerance ({0})</th><th>max ({0})</th><th>mean ({0})</th><th>max excess "
          "({0})</th><th>max gouge ({0})</th><th>within tolerance</th></tr>\n",
          escape(stockUnits));
      h += "<tr><td>" + num(d["tolerance"]) + "</td><td>" + num(d["max"]) + "</td><td>" +
           num(d["mean"]) + "</td><td>" + num(d["max_excess"]) + "</td><td>" + num(d["max_gouge"]) +
           "</td><td>" + fmt::format("{:.1f} %", 100 * d.value("in_tolerance", 0.0)) +
           "</td></tr>\n</table>\n";
      h += fmt::format("<table>\n<tr><th>from ({0})</th><th>to ({0})</th><th>share</th></tr>\n",
                       escape(stockUnits));
      for (const auto& b : d["bands"])
        h += "<tr><td>" + (b["from"].is_null() ? std::string("-&infin;") : num(b["from"])) +
             "</td><td>" + (b["to"].is_null() ? std::string("+&infin;") : num(b["to"])) +
             "</td><td>" + fmt::format("{:.2f} %", 100 * b.value("share", 0.0)) + "</td></tr>\n";
      h += "</table>\n";
    }
    if (st.contains("collisions") && !st["collisions"].empty()) {
      h += "<h3>Collisions</h3>\n<table>\n<tr><th class=\"l\">block</th><th "
           "class=\"l\">what</th><th>amount</th></tr>\n";
      const bool lathe = st.value("kind", std::string()) == "lathe";
      for (const auto& c : st["collisions"]) {
        const std::string kind = c.value("kind", std::string());
        // docs/stock-analysis.md: a lathe's rapid and holder collisions are areas, the
        // rest depths or distances.
        const std::string unit = lathe && kind != "probe" ? stockUnits + "&sup2;" : stockUnits;
        h += "<tr><td class=\"l\">" + where(c) + "</td><td class=\"l\">" + escape(kind) +
             "</td><td>" + num(c.value("amount", nlohmann::json(0.0)), 6) + " " + unit +
             "</td></tr>\n";
      }
      h += "</table>\n";
    }
  }
  h += "</body></html>\n";
  return h;
}

}  // namespace ncvm
