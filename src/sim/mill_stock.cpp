#include "sim/mill_stock.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "canon/arc_sweep.hpp"
#include "report/atomic_file.hpp"
#include "report/mill_pictures.hpp"
#include "report/stl_writer.hpp"
#include "sim/deviation.hpp"
#include "sim/heightfield_io.hpp"
#include "sim/heightfield_probe.hpp"

namespace ncvm {

std::unique_ptr<StockModel> makeMillStock(const Setup& setup) {
  return std::make_unique<MillStock>(setup);
}

namespace {
// Default resolution 0.05 mm, coarser when the block would need more than this many cells.
constexpr double kMaxDefaultCells = 25e6;
}  // namespace

MillStock::MillStock(const Setup& setup) : setup_(setup), frame_(setup, false) {
  const StockSpec& st = setup.stock;
  auto bad = [&](const std::string& what) { throw SetupError("stock: " + what, "stock", st.line); };
  if (st.min.size() != 3 || st.max.size() != 3)
    bad("a mill stock needs min = [x, y, z] and max = [x, y, z]");
  for (int k = 0; k < 3; ++k)
    if (!(st.max[static_cast<size_t>(k)] > st.min[static_cast<size_t>(k)]))
      bad("max must exceed min on every axis");
  unit_ = setup.initialUnit == InputUnit::Inch ? 1 / 25.4 : 1.0;
  tol_ = setup.target.tolerance > 0 ? setup.target.tolerance : 0.01 * unit_;
  const double w = st.max[0] - st.min[0], h = st.max[1] - st.min[1];
  if (st.cell > 0) {
    cell_ = st.cell;
  } else {
    cell_ = 0.05 * unit_;
    if (w * h / (cell_ * cell_) > kMaxDefaultCells) {
      cell_ = std::sqrt(w * h / kMaxDefaultCells);
      notes_.push_back(
          fmt::format("cell {:.4g} (the default 0.05 mm would need more than {:.0f} "
                      "million cells; give stock.cell)",
                      cell_, kMaxDefaultCells / 1e6));
    }
  }
  try {
    HeightField f = HeightField::covering(st.min[0], st.min[1], st.max[0], st.max[1], cell_,
                                          static_cast<float>(st.max[2]));
    f.setBottom(static_cast<float>(st.min[2]));
    sim_ = std::make_unique<MillSim>(std::move(f));
  } catch (const std::invalid_argument& e) {
    bad(std::string(e.what()));
  }
  for (const auto& [t, spec] : setup.tools) {
    if (spec.type == "probe" || spec.type == "insert") continue;  // they do not cut here
    try {
      tools_[t] = millToolFromSpec(spec, t);
    } catch (const ToolError& e) {
      throw SetupError(e.what(), fmt::format("tools.{}", t));
    }
  }
  const TargetSpec& tg = setup.target;
  if (tg.present) {
    MillTarget target;
    target.tolerance = tol_;
    if (tg.faceZ) {
      target.z = *tg.faceZ;
    } else if (!tg.heightMap.empty()) {
      try {
        targetField_ = loadHeightMap(tg.heightMap);
      } catch (const std::exception& e) {
        throw SetupError(std::string("target: ") + e.what(), "target.height_map", tg.line);
      }
      target.field = &*targetField_;
    } else {
      throw SetupError("target: a mill target needs face_z = Z or height_map = FILE", "target",
                       tg.line);
    }
    target_ = target;
  }
}

void MillStock::select(int t) {
  if (sim_->tool() && t == current_) return;  // T1 M06 with T1 already in: nothing new
  current_ = t;
  probeRadius_ = 0;
  if (auto s = setup_.tools.find(t); s != setup_.tools.end() && s->second.type == "probe")
    probeRadius_ =
        (setup_.probe.ballDiameter > 0 ? setup_.probe.ballDiameter : s->second.diameter) / 2;
  auto it = tools_.find(t);
  const MillTool* tool = it == tools_.end() ? nullptr : &it->second;
  sim_->setTool(tool);
  nlohmann::json entry = {{"t", t}};
  auto spec = setup_.tools.find(t);
  if (spec != setup_.tools.end()) {
    entry["type"] = spec->second.type;
    entry["diameter"] = spec->second.diameter;
    entry["corner_radius"] = spec->second.cornerRadius;
    entry["source"] = "tools";
  } else {
    entry["source"] = "none";
  }
  if (!tool)
    notes_.push_back(spec == setup_.tools.end()
                         ? fmt::format("T{}: no [tools.{}] entry: its moves remove nothing", t, t)
                         : fmt::format("T{}: a {} does not cut: its moves remove nothing", t,
                                       spec->second.type));
  toolsUsed_.push_back(entry);
}

void MillStock::onTool(const ToolEvent& e) {
  // The tool in the spindle is the one of the last M06; before any M06 (machines without a
  // changer, programs that leave it out) the last T word.
  if (e.change) {
    changed_ = true;
    select(e.tool);
  } else if (!changed_) {
    select(e.tool);
  }
  selected_ = e.tool;
}

uint32_t MillStock::tag(const MoveEvent& e) {
  origins_.push_back(e.at);
  return static_cast<uint32_t>(origins_.size() - 1);
}

void MillStock::onMove(const MoveEvent& work) {
  ++moves_;
  frame_.move(work);
  const MoveEvent& e = frame_.place(work, placed_);
  if (moves_ == 1 && !sim_->tool() && selected_ < 0)
    notes_.push_back("moves before the first T word remove nothing (no tool)");
  if (probeRadius_ > 0 && !e.skip) checkProbeMove(e);
  if (!sim_->tool()) return;
  const bool rapid = e.mode == MoveMode::Rapid;
  uint32_t t = tag(e);
  auto p = [](const AxisArray& a) { return Point3{a[0], a[1], a[2]}; };
  if (e.arc) return arc(e, t);
  Point3 prev = p(e.start);
  for (int k = 0; k < e.pathPoints; ++k) {
    Point3 next = p(e.path[static_cast<size_t>(k)]);
    sim_->line(prev, next, rapid, t);
    prev = next;
  }
  sim_->line(prev, p(e.end), rapid, t);
}

void MillStock::arc(const MoveEvent& e, uint32_t t) {
  const ArcSweep arc = arcSweepOf(e);
  const bool rapid = e.mode == MoveMode::Rapid;
  if (e.plane == 17 && std::abs(arc.r1 - arc.r0) <= 1e-9 * std::max(1.0, arc.r0)) {
    sim_->arcXY(arc.cu, arc.cv, arc.r0, arc.a0, arc.sweep, e.start[2], e.end[2], rapid, t);
    return;
  }
  // Other planes (and spirals): chords within the helix tolerance.
  const double r = std::max(arc.r0, arc.r1);
  double step = r > sim_->chordTol ? 2 * std::acos(1 - sim_->chordTol / r) : std::numbers::pi / 2;
  int n = std::max(1, static_cast<int>(std::ceil(std::abs(arc.sweep) / step)));
  Point3 prev{e.start[0], e.start[1], e.start[2]};
  for (int k = 1; k <= n; ++k) {
    Point3 next{};
    arc.place(static_cast<double>(k) / n, next);
    if (k == n) next = {e.end[0], e.end[1], e.end[2]};
    sim_->line(prev, next, rapid, t);
    prev = next;
  }
}

// A probe driven into the stock other than by G31 is the classic probe crash: reported as a
// collision of kind "probe" with the distance the move went on past the first contact of the
// (slightly smaller) test ball. Arcs are checked along their chord (probe moves are straight).
void MillStock::checkProbeMove(const MoveEvent& e) {
  const Vec3 a{e.start[0], e.start[1], e.start[2]}, b{e.end[0], e.end[1], e.end[2]};
  const double length = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  if (length <= 0) return;
  // Touching is not a crash: after a G31 the ball sits on the surface, and it may slide up a
  // wall it touched. Only going deeper than half a cell (the walls' accuracy) plus the
  // tolerance counts, so the test ball is that much smaller.
  const double r = std::max(probeRadius_ - (0.5 * cell_ + tol_), 0.1 * probeRadius_);
  std::optional<double> t = heightFieldFirstContact(sim_->field(), a, b, r);
  // A move that starts in the material was reported when it went in (or left by a G31).
  if (!t || *t == 0) return;
  probeHits_.push_back({tag(e), (1.0 - *t) * length});
}

std::optional<double> MillStock::probeContact(const Vec3& a, const Vec3& b, double r) {
  return heightFieldFirstContact(sim_->field(), a, b, r);
}

nlohmann::json MillStock::finish(const std::string& outDir) {
  return analysis(outDir);
}

nlohmann::json MillStock::analysis(const std::string& outDir) {
  const HeightField& f = sim_->field();
  const StockSpec& st = setup_.stock;
  nlohmann::json j;
  j["kind"] = "mill";
  j["units"] = unit_ < 1 ? "inch" : "mm";
  j["stock"] = {{"min", st.min},          {"max", st.max}, {"cell", cell_},
                {"nx", f.nx()},           {"ny", f.ny()},  {"bytes_per_cell", sizeof(float)},
                {"model", "height field"}};
  j["moves"] = moves_;
  j["cutting_moves"] = sim_->cuttingMoves();
  j["threads"] = sim_->threads();
  // One entry per move and kind: the deepest contact of its chords.
  nlohmann::json collisions = nlohmann::json::array();
  std::map<std::pair<uint32_t, int>, float> deepest;
  for (const auto& c : sim_->contacts()) {
    auto& d = deepest[{c.tag, static_cast<int>(c.kind)}];
    d = std::max(d, c.depth);
  }
  static const char* kinds[] = {"rapid", "shank", "holder"};
  for (const auto& [key, depth] : deepest) {
    const EventOrigin& o = origins_[key.first];
    collisions.push_back({{"kind", kinds[key.second]},
                          {"program", o.programName ? *o.programName : std::string()},
                          {"line", o.line},
                          {"n", o.n},
                          {"amount", depth}});
  }
  for (const ProbeHit& h : probeHits_) {
    const EventOrigin& o = origins_[h.tag];
    collisions.push_back({{"kind", "probe"},
                          {"program", o.programName ? *o.programName : std::string()},
                          {"line", o.line},
                          {"n", o.n},
                          {"amount", h.amount}});
  }
  j["collisions"] = collisions;
  j["tools"] = toolsUsed_;
  j["notes"] = notes_;
  j["target"] = nullptr;
  j["deviation"] = nullptr;
  j["uncut"] = nullptr;
  if (target_) {
    const auto& tg = setup_.target;
    j["target"] = tg.faceZ ? nlohmann::json{{"source", "face_z"}, {"z", *tg.faceZ}}
                           : nlohmann::json{{"source", "height_map"}, {"file", tg.heightMap}};
    MillAnalysis a = analyseMill(f, *target_);
    j["deviation"] = a.toJson();
    nlohmann::json regions = nlohmann::json::array();
    for (const auto& r : uncutRegions(f, *target_))
      regions.push_back({{"xmin", r.xmin},
                         {"xmax", r.xmax},
                         {"ymin", r.ymin},
                         {"ymax", r.ymax},
                         {"area", r.area}});
    j["uncut"] = {
        {"area", a.uncutArea()},
        {"share", a.cells ? a.uncutArea() / (static_cast<double>(a.cells) * a.cellArea) : 0.0},
        {"regions", regions}};
    if (a.cells == 0) markNotMeasured(j["uncut"], "no cell of the stock lies under the target");
  }
  nlohmann::json pictures = nlohmann::json::array();
  nlohmann::json files = nlohmann::json::object();
  if (!outDir.empty()) {
    std::filesystem::create_directories(outDir);
    auto out = [&](const char* name) { return (std::filesystem::path(outDir) / name).string(); };
    const MillTarget* tp = target_ ? &*target_ : nullptr;
    // What each picture covers, seen from above (the report's captions and scales).
    const nlohmann::json extent = {{"x", {f.x0(), f.x0() + f.cell() * f.nx()}},
                                   {"y", {f.y0(), f.y0() + f.cell() * f.ny()}}};
    writeFileAtomic(out("top_view.png"), encodePng(millTopView(f, tp)));
    pictures.push_back({{"file", "top_view.png"},
                        {"title", "Top view (uncut red, gouge blue)"},
                        {"extent", extent}});
    if (tp) {
      writeFileAtomic(out("deviation.png"), encodePng(millDeviationMap(f, *tp)));
      pictures.push_back({{"file", "deviation.png"},
                          {"title", "Deviation from the target (green within tolerance)"},
                          {"extent", extent},
                          {"scale", {{"quantity", "deviation"}, {"tolerance", tp->tolerance}}}});
    }
    writeFileAtomic(out("height_map.png"), encodePng(millHeightMap(f)));
    const auto [lo, hi] = heightRange(f);
    pictures.push_back({{"file", "height_map.png"},
                        {"title", "Height map (Z: violet lowest, yellow highest)"},
                        {"extent", extent},
                        {"scale", {{"quantity", "Z"}, {"from", lo}, {"to", hi}}}});
    writeStl(out("stock.stl"), f);
    writeFileAtomic(out("stock.hmap"), encodeHeightMap(f));
    files = {{"stl", "stock.stl"}, {"height_map", "stock.hmap"}};
  }
  j["pictures"] = pictures;
  j["files"] = files;
  if (!outDir.empty())
    writeFileAtomic((std::filesystem::path(outDir) / "analysis.json").string(), j.dump(2) + "\n");
  return j;
}

}  // namespace ncvm
