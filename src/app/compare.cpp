#include "app/compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace ncvm {

namespace {
struct Row {
  std::string key, label;
  std::function<double(const Session::Result&)> get;
  bool decimals;  // times and lengths with 3 decimals, counts as integers
};

double kindTime(const Session::Result& r, TimeKind k) {
  return r.timing ? r.timing->byKind(k).model : 0.0;
}

std::vector<Row> rows(bool dynamic) {
  using R = const Session::Result&;
  std::vector<Row> out;
  out.push_back({"cycle_time", dynamic ? "cycle time (modelled), s" : "cycle time (length/feed), s",
                 [](R r) { return r.timing ? r.timing->total().model : r.stats.time; }, true});
  if (dynamic)
    out.push_back({"cycle_time_simple", "cycle time (length/feed), s",
                   [](R r) { return r.stats.time; }, true});
  for (int k = 0; k < kTimeKinds; ++k) {
    auto kind = static_cast<TimeKind>(k);
    out.push_back({timeKindName(kind), fmt::format("  {}, s", timeKindName(kind)),
                   [kind](R r) { return kindTime(r, kind); }, true});
  }
  out.push_back({"path_length", "path length",
                 [](R r) { return r.stats.rapidLength + r.stats.feedLength; }, true});
  out.push_back({"rapid_path", "  rapid path", [](R r) { return r.stats.rapidLength; }, true});
  out.push_back({"feed_path", "  feed path", [](R r) { return r.stats.feedLength; }, true});
  out.push_back(
      {"blocks", "blocks", [](R r) { return static_cast<double>(r.stats.blocks); }, false});
  out.push_back({"moves", "moves", [](R r) { return static_cast<double>(r.stats.moves); }, false});
  auto drill = [](auto field) {
    return
        [field](R r) { return r.timing ? static_cast<double>(r.timing->drilling().*field) : 0.0; };
  };
  out.push_back({"holes", "holes drilled", drill(&DrillStats::holes), false});
  out.push_back({"pecks", "pecks", drill(&DrillStats::pecks), false});
  out.push_back({"full_retracts", "full retracts", drill(&DrillStats::fullRetracts), false});
  return out;
}

std::string number(double v, bool decimals) {
  if (!decimals) return fmt::format("{}", static_cast<int64_t>(std::llround(v)));
  return fmt::format("{:.3f}", v);
}

std::string diffCells(double va, double vb) {
  return fmt::format("{:>14.3f} {:>14.3f} {:>14} {:>9}\n", va, vb,
                     (vb - va > 0 ? "+" : "") + fmt::format("{:.3f}", vb - va),
                     va != 0 ? fmt::format("{:.1f}%", vb / va * 100.0) : "-");
}

// Per operation (from tool change to tool change, or from comment to comment), side by side
// in program order, when either program has more than one or names one.
std::string operationRows(const Session::Result& a, const Session::Result& b) {
  static const std::vector<OperationTime> none;
  const auto& oa = a.timing ? a.timing->operations() : none;
  const auto& ob = b.timing ? b.timing->operations() : none;
  bool named = false;
  for (const auto* v : {&oa, &ob})
    for (const auto& o : *v) named = named || !o.label.empty();
  if (oa.size() <= 1 && ob.size() <= 1 && !named) return {};
  std::string out;
  for (size_t k = 0; k < std::max(oa.size(), ob.size()); ++k) {
    const OperationTime& o = k < oa.size() ? oa[k] : ob[k];
    std::string label = o.label.empty() && k < ob.size() ? ob[k].label : o.label;
    std::string name =
        fmt::format("  op {} T{}{}{}", k + 1, o.tool, label.empty() ? "" : " ", label);
    if (name.size() > 27) name = name.substr(0, 26) + "~";
    double va = k < oa.size() ? oa[k].time.model : 0, vb = k < ob.size() ? ob[k].time.model : 0;
    out += fmt::format("{:<30} ", name + ", s") + diffCells(va, vb);
  }
  return out;
}

std::string endText(const Session::Result& r) {
  return r.alarm ? fmt::format("alarm {}", r.alarm->code) : std::string(endReasonName(r.end));
}
}  // namespace

std::string compareText(const ComparedRun& a, const ComparedRun& b, bool dynamic) {
  std::string out = fmt::format("ncvm compare: A = {} ({}), B = {} ({})\n", a.name,
                                endText(a.result), b.name, endText(b.result));
  out += fmt::format("{:<30} {:>14} {:>14} {:>14} {:>9}\n", "", "A", "B", "B - A", "B / A");
  for (const Row& row : rows(dynamic)) {
    double va = row.get(a.result), vb = row.get(b.result);
    std::string ratio = va != 0 ? fmt::format("{:.1f}%", vb / va * 100.0) : "-";
    std::string diff = number(vb - va, row.decimals);
    if (vb - va > 0) diff = "+" + diff;
    out += fmt::format("{:<30} {:>14} {:>14} {:>14} {:>9}\n", row.label, number(va, row.decimals),
                       number(vb, row.decimals), diff, ratio);
  }
  // Per tool, when either program has more than one.
  auto tools = [](const Session::Result& r) {
    return r.timing ? r.timing->byTool() : std::vector<ToolTime>{};
  };
  std::vector<ToolTime> ta = tools(a.result), tb = tools(b.result);
  if (ta.size() > 1 || tb.size() > 1) {
    std::vector<int> ids;
    for (const auto& t : ta) ids.push_back(t.tool);
    for (const auto& t : tb)
      if (std::find(ids.begin(), ids.end(), t.tool) == ids.end()) ids.push_back(t.tool);
    for (int id : ids) {
      auto find = [id](const std::vector<ToolTime>& v) {
        for (const auto& t : v)
          if (t.tool == id) return t.time.model;
        return 0.0;
      };
      double va = find(ta), vb = find(tb);
      out +=
          fmt::format("{:<30} {:>14.3f} {:>14.3f} {:>14} {:>9}\n", fmt::format("  tool T{}, s", id),
                      va, vb, (vb - va > 0 ? "+" : "") + fmt::format("{:.3f}", vb - va),
                      va != 0 ? fmt::format("{:.1f}%", vb / va * 100.0) : "-");
    }
  }
  out += operationRows(a.result, b.result);
  double ta0 = rows(dynamic)[0].get(a.result), tb0 = rows(dynamic)[0].get(b.result);
  if (ta0 > 0 && tb0 > 0) {
    out += tb0 < ta0 ? fmt::format("B is {:.3f} s ({:.1f}%) faster than A\n", ta0 - tb0,
                                   (ta0 - tb0) / ta0 * 100.0)
                     : fmt::format("B is {:.3f} s ({:.1f}%) slower than A\n", tb0 - ta0,
                                   (tb0 - ta0) / ta0 * 100.0);
  }
  return out;
}

nlohmann::json compareJson(const ComparedRun& a, const ComparedRun& b, bool dynamic) {
  nlohmann::json j;
  auto one = [](const ComparedRun& r) {
    nlohmann::json o;
    o["file"] = r.name;
    o["end"] = r.result.state.value("end", "");
    o["alarm"] = r.result.state.value("alarm", nlohmann::json(nullptr));
    o["cycle_time"] = r.result.state.value("cycle_time", 0.0);
    o["cycle_time_simple"] = r.result.stats.time;
    o["path_length"] = r.result.state.value("path_length", nlohmann::json(nullptr));
    o["blocks"] = r.result.stats.blocks;
    o["moves"] = r.result.stats.moves;
    o["timing"] = r.result.state.value("timing", nlohmann::json(nullptr));
    return o;
  };
  j["a"] = one(a);
  j["b"] = one(b);
  nlohmann::json d = nlohmann::json::object();
  for (const Row& row : rows(dynamic)) d[row.key] = row.get(b.result) - row.get(a.result);
  j["difference"] = d;
  return j;
}

}  // namespace ncvm
