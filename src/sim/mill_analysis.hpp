#pragma once
// The simulated stock measured against the intended part: a target height per cell (a plane
// "face down to Z", or a target height field), deviation = stock - target. Positive is
// material left (excess; beyond the tolerance it is "uncut"), negative is a gouge.
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "sim/heightfield.hpp"

namespace ncvm {

struct MillTarget {
  // Either a plane at z (field == nullptr) or a height field on the stock's grid.
  double z = 0;
  const HeightField* field = nullptr;
  // Region analysed, [xmin, ymin, xmax, ymax]; nullopt: the whole stock.
  std::optional<std::array<double, 4>> region;
  double tolerance = 0.01;  // mm
};

struct DeviationBand {
  double lo, hi;  // deviation range, mm (open ends are +-infinity)
  uint64_t cells = 0;
};

struct MillAnalysis {
  double cellArea = 0;
  uint64_t cells = 0;        // cells analysed
  double maxExcess = 0;      // largest stock - target > 0
  double maxGouge = 0;       // largest target - stock > 0
  double meanDeviation = 0;  // signed
  double meanAbsDeviation = 0;
  uint64_t uncutCells = 0;  // deviation > tolerance
  uint64_t gougeCells = 0;  // deviation < -tolerance
  std::vector<DeviationBand> bands;
  double tolerance = 0.01;
  double uncutArea() const { return static_cast<double>(uncutCells) * cellArea; }
  double gougeArea() const { return static_cast<double>(gougeCells) * cellArea; }
  nlohmann::json toJson() const;
};

// The target height of cell (i, j), NaN outside the region.
double targetHeight(const HeightField& stock, const MillTarget& target, int i, int j);

MillAnalysis analyseMill(const HeightField& stock, const MillTarget& target);

}  // namespace ncvm

namespace ncvm {

// A connected patch of uncut cells (deviation > tolerance, 4-neighbours).
struct UncutRegion {
  double xmin, ymin, xmax, ymax;  // extent of the cells (their edges, not centres)
  double area;
  uint64_t cells;
};

// The uncut regions, largest first, at most `limit` of them.
std::vector<UncutRegion> uncutRegions(const HeightField& stock, const MillTarget& target,
                                      size_t limit = 20);

}  // namespace ncvm
