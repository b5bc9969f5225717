#include "sim/mill_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/deviation.hpp"

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
  // Bands at +-1, 2, 3, 5 tolerances, as for the lathe (sim/deviation.hpp); the middle one
  // is "within tolerance".
  const double edges[] = {-inf, -5 * t, -3 * t, -2 * t, -t, t, 2 * t, 3 * t, 5 * t, inf};
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
  // The common deviation fields (docs/stock-analysis.md) first, then the mill's own.
  nlohmann::json bandsJson = nlohmann::json::array();
  auto edge = [](double v) -> nlohmann::json {
    if (std::isinf(v)) return nullptr;
    return v;
  };
  const double n = static_cast<double>(cells);
  for (const auto& b : bands)
    bandsJson.push_back({{"from", edge(b.lo)},
                         {"to", edge(b.hi)},
                         {"share", cells ? static_cast<double>(b.cells) / n : 0.0},
                         {"area", static_cast<double>(b.cells) * cellArea}});
  double total = n * cellArea;
  nlohmann::json j = {{"tolerance", tolerance},
                      {"samples", cells},
                      {"max", std::max(maxExcess, maxGouge)},
                      {"mean", meanAbsDeviation},
                      {"max_excess", maxExcess},
                      {"max_gouge", maxGouge},
                      {"in_tolerance", cells ? static_cast<double>(bands[4].cells) / n : 1.0},
                      {"bands", bandsJson},
                      {"mean_signed", meanDeviation},
                      {"area", total},
                      {"uncut_area", uncutArea()},
                      {"uncut_share", total > 0 ? uncutArea() / total : 0.0},
                      {"gouge_area", gougeArea()},
                      {"measured", true}};
  if (cells == 0) markNotMeasured(j, "no cell of the stock lies under the target");
  return j;
}

}  // namespace ncvm

namespace ncvm {

std::vector<UncutRegion> uncutRegions(const HeightField& stock, const MillTarget& target,
                                      size_t limit) {
  const int nx = stock.nx(), ny = stock.ny();
  auto idx = [&](int i, int j) { return static_cast<size_t>(j) * static_cast<size_t>(nx) + i; };
  std::vector<uint8_t> uncut(static_cast<size_t>(nx) * static_cast<size_t>(ny), 0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double want = targetHeight(stock, target, i, j);
      if (!std::isnan(want) && stock.at(i, j) - want > target.tolerance) uncut[idx(i, j)] = 1;
    }
  // Flood fill each patch (an explicit stack: patches can have millions of cells).
  std::vector<UncutRegion> out;
  std::vector<std::pair<int, int>> stack;
  const double c = stock.cell();
  for (int j0 = 0; j0 < ny; ++j0)
    for (int i0 = 0; i0 < nx; ++i0) {
      if (uncut[idx(i0, j0)] != 1) continue;
      int imin = i0, imax = i0, jmin = j0, jmax = j0;
      uint64_t count = 0;
      uncut[idx(i0, j0)] = 2;
      stack.push_back({i0, j0});
      while (!stack.empty()) {
        auto [i, j] = stack.back();
        stack.pop_back();
        ++count;
        imin = std::min(imin, i), imax = std::max(imax, i);
        jmin = std::min(jmin, j), jmax = std::max(jmax, j);
        const int ni[] = {i - 1, i + 1, i, i}, nj[] = {j, j, j - 1, j + 1};
        for (int k = 0; k < 4; ++k) {
          if (ni[k] < 0 || nj[k] < 0 || ni[k] >= nx || nj[k] >= ny) continue;
          uint8_t& u = uncut[idx(ni[k], nj[k])];
          if (u == 1) {
            u = 2;
            stack.push_back({ni[k], nj[k]});
          }
        }
      }
      out.push_back({stock.x0() + imin * c, stock.y0() + jmin * c, stock.x0() + (imax + 1) * c,
                     stock.y0() + (jmax + 1) * c, static_cast<double>(count) * c * c, count});
    }
  std::sort(out.begin(), out.end(),
            [](const UncutRegion& a, const UncutRegion& b) { return a.cells > b.cells; });
  if (out.size() > limit) out.resize(limit);
  return out;
}

}  // namespace ncvm
