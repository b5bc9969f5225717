#include "report/html_report.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/deviation.hpp"
#include "report/clock_time.hpp"

namespace ncvm {

namespace {

std::string escape(const std::string& s) {
  std::string out;
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

}  // namespace

std::string htmlReport(const nlohmann::json& state, const std::string& title,
                       const std::string& pictureDir) {
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
  row("ended", escape(state.value("end", std::string())));
  row("blocks", num(state.value("blocks", nlohmann::json(0)), 0));
  row("moves", num(state.value("moves", nlohmann::json(0)), 0));
  double t = state.value("cycle_time", 0.0);
  row("cycle time", fmt::format("{:.2f} s ({})", t, clockTime(t)));
  if (state.contains("path_length"))
    row("path length", fmt::format("rapid {} / feed {}", num(state["path_length"]["rapid"], 3),
                                   num(state["path_length"]["feed"], 3)));
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

  if (state.contains("stock") && state["stock"].is_object()) {
    const auto& st = state["stock"];
    h += "<h2>Stock</h2>\n";
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
        h += "\n<figcaption>" + escape(p.value("title", file)) + "</figcaption>\n</figure>\n";
      }
    }
    if (st.contains("deviation") && !notMeasuredText(st["deviation"]).empty()) {
      h += "<h3>Deviation from the target</h3>\n<p class=\"not-measured\">Deviation " +
           escape(notMeasuredText(st["deviation"])) + ".</p>\n";
    } else if (st.contains("deviation") && st["deviation"].is_object()) {
      const auto& d = st["deviation"];
      h += "<h3>Deviation from the target</h3>\n<table>\n";
      h += "<tr><th>tolerance</th><th>max</th><th>mean</th><th>max excess</th><th>max "
           "gouge</th><th>within tolerance</th></tr>\n";
      h += "<tr><td>" + num(d["tolerance"]) + "</td><td>" + num(d["max"]) + "</td><td>" +
           num(d["mean"]) + "</td><td>" + num(d["max_excess"]) + "</td><td>" + num(d["max_gouge"]) +
           "</td><td>" + fmt::format("{:.1f} %", 100 * d.value("in_tolerance", 0.0)) +
           "</td></tr>\n</table>\n";
      h += "<table>\n<tr><th>from</th><th>to</th><th>share</th></tr>\n";
      for (const auto& b : d["bands"])
        h += "<tr><td>" + (b["from"].is_null() ? std::string("-&infin;") : num(b["from"])) +
             "</td><td>" + (b["to"].is_null() ? std::string("+&infin;") : num(b["to"])) +
             "</td><td>" + fmt::format("{:.2f} %", 100 * b.value("share", 0.0)) + "</td></tr>\n";
      h += "</table>\n";
    }
    if (st.contains("collisions") && !st["collisions"].empty()) {
      h += "<h3>Collisions</h3>\n<table>\n<tr><th class=\"l\">block</th><th "
           "class=\"l\">what</th><th>material</th></tr>\n";
      for (const auto& c : st["collisions"])
        h += "<tr><td class=\"l\">" + where(c) + "</td><td class=\"l\">" +
             escape(c.value("kind", std::string())) + "</td><td>" +
             num(c.value("amount", nlohmann::json(0.0)), 6) + "</td></tr>\n";
      h += "</table>\n";
    }
  }
  h += "</body></html>\n";
  return h;
}

}  // namespace ncvm
