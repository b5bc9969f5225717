#include "sim/mill_analysis.hpp"

#include <cmath>
#include <limits>

namespace ncvm {

double targetHeight(const HeightField& stock, const MillTarget& target, int i, int j) {
  if (target.region) {
    const auto& r = *target.region;
    double x = stock.cellX(i), y = stock.cellY(j);
    if (x < r[0] || x > r[2] || y < r[1] || y > r[3]) return std::nan("");
  }
  if (target.field) {
    const HeightField& t = *target.field;
    // Same grid expected; otherwise the nearest target cell.
    int ti = static_cast<int>(std::floor((stock.cellX(i) - t.x0()) / t.cell()));
    int tj = static_cast<int>(std::floor((stock.cellY(j) - t.y0()) / t.cell()));
    if (ti < 0 || tj < 0 || ti >= t.nx() || tj >= t.ny()) return std::nan("");
    return t.at(ti, tj);
  }
  return target.z;
}

MillAnalysis analyseMill(const HeightField& stock, const MillTarget& target) {
  MillAnalysis a;
  a.tolerance = target.tolerance;
  a.cellArea = stock.cell() * stock.cell();
  const double t = target.tolerance, inf = std::numeric_limits<double>::infinity();
  // Bands in multiples of the tolerance; the middle one is "within tolerance".
  const double edges[] = {-inf, -10 * t, -4 * t, -2 * t, -t, t, 2 * t, 4 * t, 10 * t, inf};
  for (size_t k = 0; k + 1 < std::size(edges); ++k) a.bands.push_back({edges[k], edges[k + 1], 0});
  double sum = 0, sumAbs = 0;
  for (int j = 0; j < stock.ny(); ++j) {
    for (int i = 0; i < stock.nx(); ++i) {
      double want = targetHeight(stock, target, i, j);
      if (std::isnan(want)) continue;
      double dev = static_cast<double>(stock.at(i, j)) - want;
      // Heights are floats: a deviation under 0.05 um is representation, not machining.
      if (std::abs(dev) < 5e-5) dev = 0;
      ++a.cells;
      sum += dev;
      sumAbs += std::abs(dev);
      a.maxExcess = std::max(a.maxExcess, dev);
      a.maxGouge = std::max(a.maxGouge, -dev);
      if (dev > t) ++a.uncutCells;
      if (dev < -t) ++a.gougeCells;
      // [-t, t] is closed; gouge bands are [lo, hi), excess bands (lo, hi].
      size_t band = 4;
      if (dev < -t) {
        band = 0;
        while (!(dev < a.bands[band].hi)) ++band;
      } else if (dev > t) {
        band = 5;
        while (!(dev <= a.bands[band].hi)) ++band;
      }
      ++a.bands[band].cells;
    }
  }
  if (a.cells) {
    a.meanDeviation = sum / static_cast<double>(a.cells);
    a.meanAbsDeviation = sumAbs / static_cast<double>(a.cells);
  }
  return a;
}

nlohmann::json MillAnalysis::toJson() const {
  nlohmann::json bandsJson = nlohmann::json::array();
  auto edge = [](double v) -> nlohmann::json {
    if (std::isinf(v)) return nullptr;
    return v;
  };
  for (const auto& b : bands) {
    double pct = cells ? 100.0 * static_cast<double>(b.cells) / static_cast<double>(cells) : 0;
    bandsJson.push_back({{"from", edge(b.lo)},
                         {"to", edge(b.hi)},
                         {"cells", b.cells},
                         {"area", static_cast<double>(b.cells) * cellArea},
                         {"percent", pct}});
  }
  double total = static_cast<double>(cells) * cellArea;
  return {{"tolerance", tolerance},
          {"cells", cells},
          {"area", total},
          {"max_excess", maxExcess},
          {"max_gouge", maxGouge},
          {"mean_deviation", meanDeviation},
          {"mean_abs_deviation", meanAbsDeviation},
          {"uncut_area", uncutArea()},
          {"uncut_percent", total > 0 ? 100.0 * uncutArea() / total : 0.0},
          {"gouge_area", gougeArea()},
          {"bands", bandsJson}};
}

}  // namespace ncvm
