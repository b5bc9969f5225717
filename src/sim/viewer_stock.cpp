// The stock in the form the web viewer draws (docs/web-viewer.md, `stock`). The browser gets
// the geometry, not the files: a lathe's profile rings as they are, a mill's height field
// shrunk to a grid a browser can mesh. The final stock goes out as JSON (viewerStock), the
// timeline's snapshots as binary (viewerSnapshot, server/stock_snapshots.hpp); both come
// from the same ViewerStockData.
#include <algorithm>
#include <cmath>
#include <utility>

#include "sim/lathe_stock.hpp"
#include "sim/mill_stock.hpp"

namespace ncvm {

namespace {

// Rounded to 0.1 µm: the profile is exact to 1e-6 units, the browser needs far less and
// the answer shrinks by half.
double tidy(double v) {
  return std::round(v * 1e4) / 1e4;
}

ViewerStockData ringsOf(const ClipperLib::Paths& rings) {
  ViewerStockData d;
  for (const auto& ring : rings) {
    ViewerStockData::Ring r;
    r.hole = !ClipperLib::Orientation(ring);
    r.zx.reserve(2 * ring.size());
    // Points are (Z, radius) in Clipper units; the viewer takes [z, x] with X a diameter,
    // like profile.csv.
    for (const auto& q : ring) {
      r.zx.push_back(static_cast<double>(q.X) / LatheStock::kScale);
      r.zx.push_back(2 * static_cast<double>(q.Y) / LatheStock::kScale);
    }
    d.rings.push_back(std::move(r));
  }
  return d;
}

ViewerStockData gridOf(const HeightField& f, int maxGrid) {
  ViewerStockData d;
  d.grid = true;
  // Each grid cell is a block of step x step field cells and takes their lowest height, so
  // a slot narrower than a grid cell still shows (a mean would fill it in).
  d.step = std::max(1, (std::max(f.nx(), f.ny()) + maxGrid - 1) / std::max(1, maxGrid));
  d.nx = (f.nx() + d.step - 1) / d.step;
  d.ny = (f.ny() + d.step - 1) / d.step;
  d.x0 = f.x0();
  d.y0 = f.y0();
  d.x1 = f.x0() + f.nx() * f.cell();  // the field's far edges: the last grid cells
  d.y1 = f.y0() + f.ny() * f.cell();  // may reach past them
  d.cell = f.cell() * d.step;
  d.top = f.top();
  d.bottom = f.bottom();
  d.z.assign(static_cast<size_t>(d.nx) * static_cast<size_t>(d.ny), f.top());
  for (int j = 0; j < f.ny(); ++j) {
    float* row = d.z.data() + static_cast<size_t>(j / d.step) * static_cast<size_t>(d.nx);
    for (int i = 0; i < f.nx(); ++i) {
      float& lo = row[i / d.step];
      lo = std::min(lo, f.at(i, j));
    }
  }
  return d;
}

nlohmann::json toJson(const ViewerStockData& d) {
  if (!d.grid) {
    nlohmann::json out = {{"type", "profile"}, {"rings", nlohmann::json::array()}};
    for (const auto& r : d.rings) {
      nlohmann::json pts = nlohmann::json::array();
      for (size_t k = 0; k + 1 < r.zx.size(); k += 2)
        pts.push_back({tidy(r.zx[k]), tidy(r.zx[k + 1])});
      out["rings"].push_back({{"hole", r.hole}, {"points", std::move(pts)}});
    }
    return out;
  }
  nlohmann::json z = nlohmann::json::array();
  for (float v : d.z) z.push_back(tidy(v));
  return {{"type", "grid"}, {"nx", d.nx},   {"ny", d.ny},         {"x0", d.x0},
          {"y0", d.y0},     {"x1", d.x1},   {"y1", d.y1},         {"cell", d.cell},
          {"step", d.step}, {"top", d.top}, {"bottom", d.bottom}, {"z", std::move(z)}};
}

}  // namespace

nlohmann::json LatheStock::viewerStock(int /*maxGrid*/) {
  return toJson(ringsOf(profile()));
}

ViewerStockData LatheStock::viewerSnapshot(int /*maxGrid*/) {
  // profile() cuts the pending feed moves first. Cut apart from the moves that follow, they
  // could round differently from their joined sweep (lsim::sweepPath), so the tiles and the
  // queue are put back as they were: the run goes on exactly as without the snapshot.
  std::vector<Tile> tiles = tiles_;
  std::vector<lsim::Pt> pending = pending_;
  const size_t lo = pendLo_, hi = pendHi_;
  const double removed = removed_;
  ViewerStockData d = ringsOf(profile());
  tiles_ = std::move(tiles);
  pending_ = std::move(pending);
  pendLo_ = lo, pendHi_ = hi;
  removed_ = removed;
  return d;
}

nlohmann::json MillStock::viewerStock(int maxGrid) {
  return toJson(gridOf(sim_->field(), maxGrid));
}

// The field takes the lowest height each move leaves in a cell, so applying the queued moves
// now rather than later gives the same field.
ViewerStockData MillStock::viewerSnapshot(int maxGrid) {
  return gridOf(sim_->field(), maxGrid);
}

}  // namespace ncvm
