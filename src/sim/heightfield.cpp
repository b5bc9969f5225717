#include "sim/heightfield.hpp"

#include <cmath>
#include <stdexcept>

namespace ncvm {

HeightField::HeightField(double x0, double y0, double cell, int nx, int ny, float top)
    : x0_(x0), y0_(y0), cell_(cell), nx_(nx), ny_(ny), top_(top) {
  if (!(cell > 0) || nx <= 0 || ny <= 0) throw std::invalid_argument("height field: empty grid");
  // 4 bytes per cell; refuse what cannot be a sensible stock (2^31 cells = 8 GB).
  if (static_cast<double>(nx) * static_cast<double>(ny) > 2.0e9)
    throw std::invalid_argument("height field: too many cells (make the cell larger)");
  z_.assign(static_cast<size_t>(nx) * static_cast<size_t>(ny), top);
}

HeightField HeightField::covering(double xmin, double ymin, double xmax, double ymax, double cell,
                                  float top) {
  if (!(xmax > xmin) || !(ymax > ymin)) throw std::invalid_argument("height field: empty block");
  auto count = [&](double len) {
    double n = std::ceil(len / cell - 1e-9);
    if (!(n <= 2.0e9)) throw std::invalid_argument("height field: too many cells");
    return static_cast<int>(std::max(1.0, n));
  };
  return HeightField(xmin, ymin, cell, count(xmax - xmin), count(ymax - ymin), top);
}

void HeightField::span(double a, double b, double origin, int n, int& lo, int& hi) const {
  // Centre of cell k: origin + (k + 0.5) * cell; we want a <= centre <= b.
  double l = std::ceil((a - origin) / cell_ - 0.5);
  double h = std::floor((b - origin) / cell_ - 0.5) + 1;
  lo = static_cast<int>(std::clamp(l, 0.0, static_cast<double>(n)));
  hi = static_cast<int>(std::clamp(h, 0.0, static_cast<double>(n)));
}

}  // namespace ncvm
