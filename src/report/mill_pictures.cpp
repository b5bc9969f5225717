#include "report/mill_pictures.hpp"

#include <algorithm>
#include <cmath>

namespace ncvm {
namespace {

// Image pixel (x, y) -> cell (i, j): every `step`-th cell, top row = highest Y.
struct Sampler {
  int step, w, h, ny;
  Sampler(const HeightField& f, int maxSide) {
    int side = std::max(f.nx(), f.ny());
    step = std::max(1, (side + maxSide - 1) / std::max(1, maxSide));
    w = (f.nx() + step - 1) / step;
    h = (f.ny() + step - 1) / step;
    ny = f.ny();
  }
  int i(int x) const { return x * step; }
  int j(int y) const { return std::max(0, ny - 1 - y * step); }
};

void range(const HeightField& f, float& lo, float& hi) {
  lo = hi = f.data().empty() ? 0.0f : f.data()[0];
  for (float z : f.data()) {
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
}

uint8_t byte(double v) {
  return static_cast<uint8_t>(std::clamp(v, 0.0, 1.0) * 255 + 0.5);
}
void put(RgbImage& img, int x, int y, double r, double g, double b) {
  img.set(x, y, byte(r), byte(g), byte(b));
}

}  // namespace

std::array<double, 3> heightColour(double u) {
  // Stops of a viridis-like scale: monotonic lightness, distinct hues, no white.
  static constexpr std::array<std::array<double, 3>, 5> stops{{{0.267, 0.005, 0.329},
                                                               {0.231, 0.322, 0.545},
                                                               {0.129, 0.569, 0.549},
                                                               {0.369, 0.788, 0.384},
                                                               {0.993, 0.906, 0.144}}};
  u = std::clamp(u, 0.0, 1.0) * (stops.size() - 1);
  const size_t k = std::min(stops.size() - 2, static_cast<size_t>(u));
  const double t = u - static_cast<double>(k);
  std::array<double, 3> c{};
  for (size_t i = 0; i < 3; ++i) c[i] = stops[k][i] + t * (stops[k + 1][i] - stops[k][i]);
  return c;
}

std::array<double, 3> millDeviationColour(double dev, double tol) {
  if (std::abs(dev) <= tol) return {0.2, 0.75, 0.2};
  // 0 at the tolerance, 1 at 10 tolerances (log scale), towards red or blue.
  const double u = std::clamp(std::log10(std::abs(dev) / tol), 0.0, 1.0);
  if (dev > 0) return {0.8 + 0.2 * u, 0.8 * (1 - u), 0.1};
  return {0.1, 0.8 * (1 - u), 0.8 + 0.2 * u};
}

std::pair<float, float> heightRange(const HeightField& f) {
  float lo, hi;
  range(f, lo, hi);
  return {lo, hi};
}

RgbImage millHeightMap(const HeightField& f, int maxSide) {
  Sampler s(f, maxSide);
  RgbImage img(s.w, s.h);
  float lo, hi;
  range(f, lo, hi);
  double span = hi > lo ? hi - lo : 1.0;
  for (int y = 0; y < s.h; ++y)
    for (int x = 0; x < s.w; ++x) {
      auto c = heightColour((f.at(s.i(x), s.j(y)) - lo) / span);
      put(img, x, y, c[0], c[1], c[2]);
    }
  return img;
}

RgbImage millTopView(const HeightField& f, const MillTarget* target, int maxSide) {
  Sampler s(f, maxSide);
  RgbImage img(s.w, s.h);
  float lo, hi;
  range(f, lo, hi);
  double span = hi > lo ? hi - lo : 1.0;
  // Slope shading on the sampled grid, in units of the sample spacing.
  double spacing = f.cell() * s.step;
  for (int y = 0; y < s.h; ++y)
    for (int x = 0; x < s.w; ++x) {
      int i = s.i(x), j = s.j(y);
      int i2 = std::min(f.nx() - 1, i + s.step), j2 = std::max(0, j - s.step);
      double gx = (f.at(i2, j) - f.at(i, j)) / spacing, gy = (f.at(i, j) - f.at(i, j2)) / spacing;
      // Light from the north-west, 45 degrees up.
      double shade = std::clamp(0.75 + 0.5 * (-gx + gy) / std::sqrt(2.0), 0.25, 1.0);
      double grey = (0.55 + 0.45 * (f.at(i, j) - lo) / span) * shade;
      double r = grey, g = grey, b = grey;
      if (target) {
        double want = targetHeight(f, *target, i, j);
        if (!std::isnan(want)) {
          double dev = f.at(i, j) - want;
          if (dev > target->tolerance)
            r = 0.55 + 0.45 * grey, g = b = 0.25 * grey;
          else if (dev < -target->tolerance)
            b = 0.55 + 0.45 * grey, r = g = 0.25 * grey;
        }
      }
      put(img, x, y, r, g, b);
    }
  return img;
}

RgbImage millDeviationMap(const HeightField& f, const MillTarget& target, int maxSide) {
  Sampler s(f, maxSide);
  RgbImage img(s.w, s.h);
  const double t = target.tolerance;
  for (int y = 0; y < s.h; ++y)
    for (int x = 0; x < s.w; ++x) {
      int i = s.i(x), j = s.j(y);
      double want = targetHeight(f, target, i, j);
      if (std::isnan(want)) {
        put(img, x, y, 0.6, 0.6, 0.6);
        continue;
      }
      auto c = millDeviationColour(f.at(i, j) - want, t);
      put(img, x, y, c[0], c[1], c[2]);
    }
  return img;
}

}  // namespace ncvm
