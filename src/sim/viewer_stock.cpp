// The final stock in the form the web viewer draws (docs/web-viewer.md, `stock`). The
// browser gets the geometry, not the files: a lathe's profile rings as they are, a mill's
// height field shrunk to a grid a browser can mesh.
#include <algorithm>
#include <cmath>

#include "sim/lathe_stock.hpp"
#include "sim/mill_stock.hpp"

namespace ncvm {

namespace {

// Rounded to 0.1 µm: the profile is exact to 1e-6 units, the browser needs far less and
// the answer shrinks by half.
double tidy(double v) {
  return std::round(v * 1e4) / 1e4;
}

}  // namespace

nlohmann::json LatheStock::viewerStock(int /*maxGrid*/) {
  ClipperLib::Paths rings = profile();
  nlohmann::json out = {{"type", "profile"}, {"rings", nlohmann::json::array()}};
  for (const auto& ring : rings) {
    nlohmann::json pts = nlohmann::json::array();
    // Points are (Z, radius) in Clipper units; the viewer takes [z, x] with X a diameter,
    // like profile.csv.
    for (const auto& q : ring)
      pts.push_back(
          {tidy(static_cast<double>(q.X) / kScale), tidy(2 * static_cast<double>(q.Y) / kScale)});
    out["rings"].push_back({{"hole", !ClipperLib::Orientation(ring)}, {"points", std::move(pts)}});
  }
  return out;
}

nlohmann::json MillStock::viewerStock(int maxGrid) {
  const HeightField& f = sim_->field();
  // Each grid cell is a block of step x step field cells and takes their lowest height, so
  // a slot narrower than a grid cell still shows (a mean would fill it in).
  int step = std::max(1, (std::max(f.nx(), f.ny()) + maxGrid - 1) / std::max(1, maxGrid));
  int nx = (f.nx() + step - 1) / step, ny = (f.ny() + step - 1) / step;
  nlohmann::json z = nlohmann::json::array();
  for (int gj = 0; gj < ny; ++gj)
    for (int gi = 0; gi < nx; ++gi) {
      float lo = f.top();
      for (int j = gj * step; j < std::min(f.ny(), (gj + 1) * step); ++j)
        for (int i = gi * step; i < std::min(f.nx(), (gi + 1) * step); ++i)
          lo = std::min(lo, f.at(i, j));
      z.push_back(tidy(lo));
    }
  return {{"type", "grid"},
          {"nx", nx},
          {"ny", ny},
          {"x0", f.x0()},
          {"y0", f.y0()},
          {"x1", f.x0() + f.nx() * f.cell()},  // the field's far edges: the last grid cells
          {"y1", f.y0() + f.ny() * f.cell()},  // may reach past them
          {"cell", f.cell() * step},
          {"step", step},
          {"top", f.top()},
          {"bottom", f.bottom()},
          {"z", std::move(z)}};
}

}  // namespace ncvm
