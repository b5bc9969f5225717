#include "app/compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

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

const std::vector<OperationTime>& operationsOf(const Session::Result& r) {
  static const std::vector<OperationTime> none;
  return r.timing ? r.timing->operations() : none;
}
const std::vector<HoleTime>& holesOf(const Session::Result& r) {
  static const std::vector<HoleTime> none;
  return r.timing ? r.timing->holes() : none;
}

std::string holeName(const HoleTime& h) {
  return fmt::format("    hole X{:g} Y{:g}", std::round(h.x * 1000) / 1000,
                     std::round(h.y * 1000) / 1000);
}

// An operation's holes under its row, paired by position; past kHoleRows, one row for the
// rest.
std::string holeRows(const std::vector<HoleTime>& ha, int opA, const std::vector<HoleTime>& hb,
                     int opB) {
  constexpr size_t kHoleRows = 20;
  std::vector<OperationPair> pairs = pairHoles(ha, opA, hb, opB);
  std::string out;
  double restA = 0, restB = 0;
  for (size_t k = 0; k < pairs.size(); ++k) {
    const OperationPair& p = pairs[k];
    double va = p.a >= 0 ? ha[static_cast<size_t>(p.a)].time.model : 0;
    double vb = p.b >= 0 ? hb[static_cast<size_t>(p.b)].time.model : 0;
    if (k >= kHoleRows) {
      restA += va, restB += vb;
      continue;
    }
    std::string name =
        holeName(p.a >= 0 ? ha[static_cast<size_t>(p.a)] : hb[static_cast<size_t>(p.b)]);
    out += fmt::format("{:<30} ", name + ", s") + diffCells(va, vb);
  }
  if (pairs.size() > kHoleRows)
    out += fmt::format("{:<30} ", fmt::format("    {} more holes, s", pairs.size() - kHoleRows)) +
           diffCells(restA, restB);
  return out;
}

// Per operation, side by side as pairOperations pairs them, when either program has more
// than one, names one or drills a hole; each with its holes.
std::string operationRows(const Session::Result& a, const Session::Result& b) {
  const auto& oa = operationsOf(a);
  const auto& ob = operationsOf(b);
  const auto& ha = holesOf(a);
  const auto& hb = holesOf(b);
  bool named = false;
  for (const auto* v : {&oa, &ob})
    for (const auto& o : *v) named = named || !o.label.empty();
  if (oa.size() <= 1 && ob.size() <= 1 && !named && ha.empty() && hb.empty()) return {};
  std::string out;
  std::vector<OperationPair> pairs = pairOperations(oa, ob);
  for (size_t k = 0; k < pairs.size(); ++k) {
    const OperationPair& p = pairs[k];
    const OperationTime* x = p.a >= 0 ? &oa[static_cast<size_t>(p.a)] : nullptr;
    const OperationTime* y = p.b >= 0 ? &ob[static_cast<size_t>(p.b)] : nullptr;
    const OperationTime& o = x ? *x : *y;
    std::string label = o.label.empty() && y ? y->label : o.label;
    std::string name =
        fmt::format("  op {} T{}{}{}", k + 1, o.tool, label.empty() ? "" : " ", label);
    if (name.size() > 27) name = name.substr(0, 26) + "~";
    out += fmt::format("{:<30} ", name + ", s") +
           diffCells(x ? x->time.model : 0, y ? y->time.model : 0);
    out += holeRows(ha, p.a, hb, p.b);
  }
  return out;
}

std::string endText(const Session::Result& r) {
  return r.alarm ? fmt::format("alarm {}", r.alarm->code) : std::string(endReasonName(r.end));
}
}  // namespace

std::vector<OperationPair> pairOperations(const std::vector<OperationTime>& a,
                                          const std::vector<OperationTime>& b) {
  // The k-th operation of each tool in B, by (tool, k).
  std::map<std::pair<int, int>, int> inB;
  std::map<int, int> seen;
  for (size_t j = 0; j < b.size(); ++j) inB[{b[j].tool, seen[b[j].tool]++}] = static_cast<int>(j);
  seen.clear();
  std::vector<int> partnerOfB(b.size(), -1);
  std::vector<int> partnerOfA(a.size(), -1);
  for (size_t i = 0; i < a.size(); ++i) {
    auto it = inB.find({a[i].tool, seen[a[i].tool]++});
    if (it == inB.end()) continue;
    partnerOfA[i] = it->second;
    partnerOfB[static_cast<size_t>(it->second)] = static_cast<int>(i);
  }
  std::vector<OperationPair> out;
  size_t nextB = 0;  // B's operations before this one are placed
  auto placeLonelyBefore = [&](size_t end) {
    for (; nextB < end; ++nextB)
      if (partnerOfB[nextB] < 0) out.push_back({-1, static_cast<int>(nextB)});
  };
  for (size_t i = 0; i < a.size(); ++i) {
    int j = partnerOfA[i];
    if (j >= 0) placeLonelyBefore(std::max(nextB, static_cast<size_t>(j)));
    out.push_back({static_cast<int>(i), j});
  }
  placeLonelyBefore(b.size());
  return out;
}

std::vector<OperationPair> pairHoles(const std::vector<HoleTime>& a, int opA,
                                     const std::vector<HoleTime>& b, int opB) {
  // B's holes of opB by position, 0.001 grid, in their order.
  using Grid = std::pair<int64_t, int64_t>;
  auto grid = [](const HoleTime& h) {
    return Grid{std::llround(h.x * 1000), std::llround(h.y * 1000)};
  };
  auto mine = [](const HoleTime& h, int op) {
    return op >= 0 && h.op == static_cast<uint32_t>(op);
  };
  std::map<Grid, std::vector<size_t>> inB;
  for (size_t j = b.size(); j-- > 0;)
    if (mine(b[j], opB)) inB[grid(b[j])].push_back(j);  // reversed: back() is the first
  std::vector<bool> used(b.size(), false);
  std::vector<OperationPair> out;
  for (size_t i = 0; i < a.size(); ++i) {
    if (!mine(a[i], opA)) continue;
    int partner = -1;
    auto it = inB.find(grid(a[i]));
    if (it != inB.end() && !it->second.empty()) {
      partner = static_cast<int>(it->second.back());
      used[it->second.back()] = true;
      it->second.pop_back();
    }
    out.push_back({static_cast<int>(i), partner});
  }
  for (size_t j = 0; j < b.size(); ++j)
    if (!used[j] && mine(b[j], opB)) out.push_back({-1, static_cast<int>(j)});
  return out;
}

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
  // The operations side by side (as the text's rows), each with its holes.
  const auto& oa = operationsOf(a.result);
  const auto& ob = operationsOf(b.result);
  const auto& ha = holesOf(a.result);
  const auto& hb = holesOf(b.result);
  auto index = [](int k) { return k >= 0 ? nlohmann::json(k) : nlohmann::json(nullptr); };
  auto time = [](const auto& v, int k) {
    return k >= 0 ? v[static_cast<size_t>(k)].time.model : 0.0;
  };
  nlohmann::json ops = nlohmann::json::array();
  for (const OperationPair& p : pairOperations(oa, ob)) {
    const OperationTime& o = p.a >= 0 ? oa[static_cast<size_t>(p.a)] : ob[static_cast<size_t>(p.b)];
    nlohmann::json e = {{"a", index(p.a)},         {"b", index(p.b)},
                        {"tool", o.tool},          {"time_a", time(oa, p.a)},
                        {"time_b", time(ob, p.b)}, {"difference", time(ob, p.b) - time(oa, p.a)}};
    nlohmann::json holes = nlohmann::json::array();
    for (const OperationPair& h : pairHoles(ha, p.a, hb, p.b)) {
      const HoleTime& at = h.a >= 0 ? ha[static_cast<size_t>(h.a)] : hb[static_cast<size_t>(h.b)];
      holes.push_back({{"x", at.x},
                       {"y", at.y},
                       {"a", index(h.a)},
                       {"b", index(h.b)},
                       {"time_a", time(ha, h.a)},
                       {"time_b", time(hb, h.b)},
                       {"difference", time(hb, h.b) - time(ha, h.a)}});
    }
    e["holes"] = holes;
    ops.push_back(e);
  }
  j["operations"] = ops;
  return j;
}

}  // namespace ncvm
