#include "app/sweep.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

namespace ncvm {
namespace {

double number(const std::string& key, const std::string& text) {
  double v = 0;
  auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size())
    throw SetupError(fmt::format("--vary {}: \"{}\" is not a number", key, text), key);
  return v;
}

std::vector<std::string> split(const std::string& s, char c) {
  std::vector<std::string> out;
  size_t pos = 0;
  while (true) {
    size_t next = s.find(c, pos);
    out.push_back(s.substr(pos, next == std::string::npos ? std::string::npos : next - pos));
    if (next == std::string::npos) break;
    pos = next + 1;
  }
  return out;
}

std::string folderName(const std::vector<SweepAxis>& axes, const std::vector<std::string>& v) {
  std::string name;
  for (size_t k = 0; k < axes.size(); ++k) {
    if (!name.empty()) name += "_";
    name += axes[k].key + "=" + v[k];
  }
  for (char& ch : name)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '=' || ch == '-' ||
          ch == '_'))
      ch = '-';
  return name;
}

std::string num(const nlohmann::json& j, const char* key, const char* fmtSpec) {
  if (j.is_object() && !j.value("measured", true)) return "not measured";
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return "-";
  return fmt::format(fmt::runtime(fmtSpec), j[key].get<double>());
}

}  // namespace

SweepAxis parseSweepAxis(const std::string& spec) {
  auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
    throw SetupError("--vary needs KEY=FROM:TO:STEP or KEY=V1,V2,...: " + spec);
  SweepAxis a;
  a.key = spec.substr(0, eq);
  std::string rest = spec.substr(eq + 1);
  if (rest.find(':') != std::string::npos) {
    auto parts = split(rest, ':');
    if (parts.size() != 3) throw SetupError("--vary " + a.key + ": a range is FROM:TO:STEP", a.key);
    double from = number(a.key, parts[0]), to = number(a.key, parts[1]),
           step = number(a.key, parts[2]);
    if (!(step > 0)) throw SetupError("--vary " + a.key + ": the step must be positive", a.key);
    double n = std::floor((to - from) / step + 1e-9);
    if (n < 0 || n > 10000) throw SetupError("--vary " + a.key + ": empty or huge range", a.key);
    for (int k = 0; k <= static_cast<int>(n); ++k)
      a.values.push_back(fmt::format("{:g}", from + k * step));
  } else {
    for (auto& v : split(rest, ',')) {
      if (v.empty()) throw SetupError("--vary " + a.key + ": empty value", a.key);
      a.values.push_back(v);
    }
  }
  return a;
}

std::vector<SweepRow> runSweep(
    const Setup& base, const std::vector<SweepAxis>& axes, const std::string& outRoot,
    const std::function<SweepRow(const Setup&, const std::string&)>& run) {
  std::vector<SweepRow> rows;
  std::vector<size_t> idx(axes.size(), 0);
  size_t total = 1;
  for (const auto& a : axes) total *= a.values.size();
  for (size_t n = 0; n < total; ++n) {
    std::vector<std::string> values;
    Setup s = base;
    for (size_t k = 0; k < axes.size(); ++k) {
      values.push_back(axes[k].values[idx[k]]);
      applySetting(s, axes[k].key + "=" + values.back());
    }
    std::string dir = outRoot.empty() ? "" : outRoot + "/" + folderName(axes, values);
    SweepRow row;
    try {
      row = run(s, dir);
    } catch (const SetupError& e) {
      row.end = "setup error";
      row.alarm = e.what();
    }
    row.values = values;
    row.dir = dir;
    rows.push_back(std::move(row));
    // Odometer: the last axis varies fastest.
    for (size_t k = axes.size(); k-- > 0;) {
      if (++idx[k] < axes[k].values.size()) break;
      idx[k] = 0;
    }
  }
  return rows;
}

bool sweepRowClean(const SweepRow& r) {
  const auto& st = r.stock;
  return r.alarm.empty() && st.is_object() && st.contains("uncut") && st["uncut"].is_object() &&
         st["uncut"]["area"].is_number() && st["uncut"]["area"].get<double>() == 0 &&
         st["collisions"].empty();
}

std::string sweepMarkdown(const std::vector<SweepAxis>& axes, const std::vector<SweepRow>& rows) {
  std::string out = "|";
  for (const auto& a : axes) out += " " + a.key + " |";
  out += " end | uncut area | uncut % | max excess | max gouge | collisions | nothing uncut |\n|";
  for (size_t k = 0; k < axes.size(); ++k) out += "--:|";
  out += "---|--:|--:|--:|--:|--:|---|\n";
  std::vector<std::string> clean;
  for (const auto& r : rows) {
    out += "|";
    for (const auto& v : r.values) out += " " + v + " |";
    std::string end = r.alarm.empty() ? r.end : r.end + ": " + r.alarm;
    const nlohmann::json& st = r.stock;
    nlohmann::json uncut = st.is_object() && st.contains("uncut") ? st["uncut"] : nlohmann::json();
    nlohmann::json dev =
        st.is_object() && st.contains("deviation") ? st["deviation"] : nlohmann::json();
    std::string pct = uncut.is_object() && uncut["share"].is_number()
                          ? fmt::format("{:.1f}", 100 * uncut["share"].get<double>())
                          : num(uncut, "share", "{:.1f}");
    std::string coll =
        st.is_object() && st.contains("collisions") ? std::to_string(st["collisions"].size()) : "-";
    bool ok = sweepRowClean(r);
    out += fmt::format(" {} | {} | {} | {} | {} | {} | {} |\n", end, num(uncut, "area", "{:.1f}"),
                       pct, num(dev, "max_excess", "{:.3f}"), num(dev, "max_gouge", "{:.3f}"), coll,
                       ok ? "**yes**" : "no");
    if (ok) {
      std::string c;
      for (size_t k = 0; k < axes.size(); ++k)
        c += (k ? ", " : "") + axes[k].key + " = " + r.values[k];
      clean.push_back(c);
    }
  }
  out += "\nNothing uncut: ";
  if (clean.empty()) out += "no combination.\n";
  for (size_t k = 0; k < clean.size(); ++k) out += (k ? "; " : "") + clean[k];
  if (!clean.empty()) out += ".\n";
  return out;
}

std::string sweepCsv(const std::vector<SweepAxis>& axes, const std::vector<SweepRow>& rows) {
  std::string out;
  for (const auto& a : axes) out += a.key + ",";
  out += "end,alarm,uncut_area,uncut_share,max_excess,max_gouge,collisions,nothing_uncut\n";
  for (const auto& r : rows) {
    for (const auto& v : r.values) out += v + ",";
    const nlohmann::json& st = r.stock;
    nlohmann::json uncut = st.is_object() && st.contains("uncut") ? st["uncut"] : nlohmann::json();
    nlohmann::json dev =
        st.is_object() && st.contains("deviation") ? st["deviation"] : nlohmann::json();
    std::string alarm = r.alarm;
    for (char& ch : alarm)
      if (ch == ',' || ch == '"') ch = ' ';
    out += fmt::format("{},{},{},{},{},{},{},{}\n", r.end, alarm, num(uncut, "area", "{:.3f}"),
                       num(uncut, "share", "{:.5f}"), num(dev, "max_excess", "{:.4f}"),
                       num(dev, "max_gouge", "{:.4f}"),
                       st.is_object() && st.contains("collisions") ? st["collisions"].size() : 0,
                       sweepRowClean(r) ? "yes" : "no");
  }
  return out;
}

}  // namespace ncvm
