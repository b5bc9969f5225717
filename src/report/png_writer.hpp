#pragma once
// PNG encoding of an 8-bit RGB image (zlib deflate), for the stock pictures.
#include <cstdint>
#include <string>
#include <vector>

namespace ncvm {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major, top row first, 3 bytes per pixel
  RgbImage(int w, int h, uint8_t fill = 255)
      : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3, fill) {}
  void set(int x, int y, uint8_t r, uint8_t g, uint8_t b) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    size_t i = (static_cast<size_t>(y) * width + x) * 3;
    rgb[i] = r, rgb[i + 1] = g, rgb[i + 2] = b;
  }
};

// The PNG file's bytes.
std::string encodePng(const RgbImage& img);

}  // namespace ncvm
