#pragma once
// A minimal PNG encoder (8-bit grey or RGB, no interlace) on top of zlib: enough for the
// stock pictures, without pulling in libpng.
#include <cstdint>
#include <string>
#include <vector>

namespace ncvm {

struct Image {
  int width = 0, height = 0, channels = 3;  // 1 = grey, 3 = RGB
  std::vector<uint8_t> pixels;              // row-major, top row first
  Image() = default;
  Image(int w, int h, int c)
      : width(w), height(h), channels(c), pixels(size_t(w) * size_t(h) * size_t(c), 0) {}
  uint8_t* at(int x, int y) {
    return pixels.data() + (size_t(y) * size_t(width) + size_t(x)) * size_t(channels);
  }
};

// The PNG file's bytes.
std::string encodePng(const Image& img);
// Writes it atomically; throws std::runtime_error on failure.
void writePng(const std::string& path, const Image& img);

}  // namespace ncvm
