#pragma once
// The mill stock as a height field: one float height (mm) per square cell of an XY grid,
// sampled at the cell centre. 4 bytes per cell; a 3-axis tool can only lower it, so every
// cut is a min() and cuts commute (docs/performance.md: why not dexels).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ncvm {

class HeightField {
 public:
  HeightField() = default;
  // The block [x0, x0 + nx*cell] x [y0, y0 + ny*cell] with its top at `top`.
  HeightField(double x0, double y0, double cell, int nx, int ny, float top);
  // The block covering [xmin, xmax] x [ymin, ymax] (rounded out to whole cells).
  static HeightField covering(double xmin, double ymin, double xmax, double ymax, double cell,
                              float top);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double cell() const { return cell_; }
  double x0() const { return x0_; }
  double y0() const { return y0_; }
  double cellX(int i) const { return x0_ + (i + 0.5) * cell_; }
  double cellY(int j) const { return y0_ + (j + 0.5) * cell_; }
  float top() const { return top_; }
  float bottom() const { return bottom_; }
  void setBottom(float b) { bottom_ = b; }

  float at(int i, int j) const { return z_[index(i, j)]; }
  float& at(int i, int j) { return z_[index(i, j)]; }
  float* row(int j) { return z_.data() + static_cast<size_t>(j) * static_cast<size_t>(nx_); }
  const float* row(int j) const {
    return z_.data() + static_cast<size_t>(j) * static_cast<size_t>(nx_);
  }
  const std::vector<float>& data() const { return z_; }
  size_t bytes() const { return z_.size() * sizeof(float); }

  // Cell range [lo, hi) whose centres lie within [a, b]; empty (lo >= hi) if none.
  void columnsWithin(double a, double b, int& lo, int& hi) const { span(a, b, x0_, nx_, lo, hi); }
  void rowsWithin(double a, double b, int& lo, int& hi) const { span(a, b, y0_, ny_, lo, hi); }

 private:
  size_t index(int i, int j) const {
    return static_cast<size_t>(j) * static_cast<size_t>(nx_) + static_cast<size_t>(i);
  }
  void span(double a, double b, double origin, int n, int& lo, int& hi) const;

  double x0_ = 0, y0_ = 0, cell_ = 1;
  int nx_ = 0, ny_ = 0;
  float top_ = 0, bottom_ = -1e9f;
  std::vector<float> z_;
};

}  // namespace ncvm
