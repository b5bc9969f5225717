#include "report/png_writer.hpp"

#include <zlib.h>

#include <stdexcept>

#include "report/atomic_file.hpp"

namespace ncvm {
namespace {

void put32(std::string& s, uint32_t v) {
  for (int k = 3; k >= 0; --k) s.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}

void chunk(std::string& out, const char* type, const std::string& data) {
  put32(out, static_cast<uint32_t>(data.size()));
  std::string body(type, 4);
  body += data;
  out += body;
  uLong crc =
      crc32(0L, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()));
  put32(out, static_cast<uint32_t>(crc));
}

}  // namespace

std::string encodePng(const Image& img) {
  if (img.width <= 0 || img.height <= 0 || (img.channels != 1 && img.channels != 3))
    throw std::runtime_error("png: bad image size");
  const size_t stride = size_t(img.width) * size_t(img.channels);
  // Each row gets filter type 1 (Sub): height maps are smooth, so it compresses well.
  std::string raw;
  raw.reserve((stride + 1) * size_t(img.height));
  for (int y = 0; y < img.height; ++y) {
    const uint8_t* row = img.pixels.data() + size_t(y) * stride;
    raw.push_back(1);
    for (size_t k = 0; k < stride; ++k) {
      uint8_t left = k >= size_t(img.channels) ? row[k - size_t(img.channels)] : 0;
      raw.push_back(static_cast<char>(static_cast<uint8_t>(row[k] - left)));
    }
  }
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(packed.data()), &size,
                reinterpret_cast<const Bytef*>(raw.data()), static_cast<uLong>(raw.size()),
                6) != Z_OK)
    throw std::runtime_error("png: zlib failed");
  packed.resize(size);

  std::string out("\x89PNG\r\n\x1a\n", 8);
  std::string ihdr;
  put32(ihdr, static_cast<uint32_t>(img.width));
  put32(ihdr, static_cast<uint32_t>(img.height));
  ihdr.push_back(8);                          // bit depth
  ihdr.push_back(img.channels == 3 ? 2 : 0);  // colour type: RGB or grey
  ihdr.append(3, '\0');                       // deflate, adaptive filters, no interlace
  chunk(out, "IHDR", ihdr);
  chunk(out, "IDAT", packed);
  chunk(out, "IEND", "");
  return out;
}

void writePng(const std::string& path, const Image& img) {
  writeFileAtomic(path, encodePng(img));
}

}  // namespace ncvm
